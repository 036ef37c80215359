#pragma once

// main() for GUI suites: VTK needs the OpenGL 3.2 core surface format set before QApplication exists; and the
// wait for a main window's background task.
#include "MainWindow.h"

#include <QApplication>
#include <QString>
#include <QSettings>
#include <QSignalSpy>
#include <QSurfaceFormat>
#include <QtTest>

namespace vsim::test {

/// Waits until the window's task runner is idle again; false after `milliseconds`.
inline bool waitForTask(gui::MainWindow& window, int milliseconds = 120000)
{
    QSignalSpy idle(&window.tasks(), &gui::TaskRunner::idle);
    return idle.wait(milliseconds);
}

/// The vessel steps as a user runs them in the window's study: Import DICOM from `folder`, Segment, Skeleton &
/// Centerlines, each in the background; false as soon as one is refused or does not finish.
inline bool runVesselSteps(gui::MainWindow& window, const std::string& folder)
{
    return window.importDicom(QString::fromStdString(folder)) && waitForTask(window) && window.segmentVessels() &&
           waitForTask(window) && window.extractSkeletonAndCenterlines() && waitForTask(window);
}

} // namespace vsim::test

#define VSIM_GUI_TEST_MAIN(TestClass)                                                                                  \
    int main(int argc, char** argv)                                                                                    \
    {                                                                                                                  \
        QSurfaceFormat format;                                                                                         \
        format.setVersion(3, 2);                                                                                       \
        format.setProfile(QSurfaceFormat::CoreProfile);                                                                \
        format.setDepthBufferSize(24);                                                                                 \
        QSurfaceFormat::setDefaultFormat(format);                                                                      \
        QApplication application(argc, argv);                                                                          \
        QApplication::setOrganizationName("VascuSimTests");                                                            \
        QApplication::setApplicationName(#TestClass); /* settings of its own, from a clean start */                    \
        QSettings().clear();                                                                                           \
        TestClass test;                                                                                                \
        return QTest::qExec(&test, argc, argv);                                                                        \
    }
