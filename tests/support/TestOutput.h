#pragma once

// Where tests keep what a person may want to look at afterwards (screenshots, bundles): $VSIM_TEST_OUTPUT,
// set by CTest to <build>/test-output, or the system temporary folder when a suite runs alone.

#include <QDir>
#include <QString>

#include <cstdlib>

namespace vsim::test {

inline QString outputFolder(const QString& suite)
{
    const char* root = std::getenv("VSIM_TEST_OUTPUT");
    const QString folder = QDir(root ? QString::fromLocal8Bit(root) : QDir::tempPath()).filePath(suite);
    QDir().mkpath(folder);
    return folder;
}

} // namespace vsim::test
