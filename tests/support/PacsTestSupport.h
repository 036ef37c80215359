#pragma once

// What the PACS tests share (tests/dicom): an Orthanc started in the suite's folder, the CLI run as a user runs it
// (VSIM_CLI, the target's compile definition), dcmdump's values of a file, the error a call throws.

#include "OrthancServer.h"
#include "TestOutput.h"
#include "vsim/core/Error.h"

#include <QDir>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QString>
#include <QStringList>

#include <filesystem>
#include <functional>
#include <memory>

namespace vsim::test {

/// Starts an Orthanc in the suite's folder `name`; null (and `failure` set) when it does not start.
inline std::unique_ptr<OrthancServer> startOrthanc(const char* name, bool strict, QString& failure, int vascusimPort = 11112)
{
    try
    {
        return std::make_unique<OrthancServer>(std::filesystem::path(outputFolder("pacs").toStdString()) / name,
                                                     strict, vascusimPort);
    }
    catch (const Error& error)
    {
        failure = QString::fromStdString(error.what());
        return nullptr;
    }
}

struct CliResult
{
    int code = -1;
    QString output; ///< stdout and stderr
};

inline CliResult runCli(const QStringList& arguments)
{
    QProcess cli;
    cli.setProcessChannelMode(QProcess::MergedChannels);
    cli.start(VSIM_CLI, arguments);
    cli.waitForFinished(120000);
    return {cli.exitStatus() == QProcess::NormalExit ? cli.exitCode() : -1, QString::fromUtf8(cli.readAll())};
}

/// Every value of `tag` ("0008,0060") that dcmdump lists in `file`, nested sequences included, top level first.
inline QStringList dumpedValues(const QString& file, const QString& tag)
{
    QProcess dcmdump;
    dcmdump.start("dcmdump", {"-Un", "+P", tag, file}); // -Un: UIDs as numbers, not names
    dcmdump.waitForFinished(30000);
    QStringList values;
    for (const QString& line : QString::fromUtf8(dcmdump.readAllStandardOutput()).split('\n', Qt::SkipEmptyParts))
    {
        const qsizetype open = line.indexOf('['), close = line.indexOf(']');
        if (open >= 0 && close > open)
            values << line.mid(open + 1, close - open - 1);
    }
    return values;
}

inline QString dumpedValue(const QString& file, const QString& tag)
{
    const QStringList values = dumpedValues(file, tag);
    return values.isEmpty() ? QString() : values[0];
}

/// The one file of `folder` whose Modality is `modality`.
inline QString fileOfModality(const QString& folder, const QString& modality)
{
    QStringList matches;
    for (const QString& name : QDir(folder).entryList(QDir::Files))
        if (dumpedValue(folder + "/" + name, "0008,0060") == modality)
            matches << folder + "/" + name;
    return matches.size() == 1 ? matches[0] : QString();
}

inline QJsonObject jsonOf(const QString& output)
{
    return QJsonDocument::fromJson(output.mid(output.indexOf('{')).toUtf8()).object();
}

inline QString errorOf(const std::function<void()>& call)
{
    try
    {
        call();
    }
    catch (const Error& error)
    {
        return QString::fromStdString(error.what());
    }
    return {};
}


} // namespace vsim::test
