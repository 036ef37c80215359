// The PACS client against a real Orthanc (issue 22; tests/support/OrthancServer.h starts one on a loopback port
// with a temporary configuration and stops it at the end, also when a test fails). A phantom CT series is uploaded
// with DCMTK's storescu (another implementation than ours), then: C-ECHO; C-FIND at the study level by patient ID,
// by a name with a wildcard, by modality and by a date range, each against what was uploaded; the failures (a
// wrong called AE title, a port where nothing listens, an unknown calling AE on a strict server) give messages
// that say what to fix; `vascusim-cli pacs echo|find` the same way, with its exit codes. Skips, saying so, where
// Orthanc is not installed (scripts/install-deps.sh installs it).

#include "DicomFixtures.h"
#include "OrthancServer.h"
#include "vsim/core/Error.h"
#include "vsim/dicom/DicomScan.h"
#include "vsim/dicom/PacsClient.h"

#include <QProcess>
#include <QtTest>

using namespace vsim;

namespace {

/// Sends the files with storescu (DCMTK's C-STORE SCU) from AE title VASCUSIM; returns its exit code.
int storeWithStorescu(const dicom::PacsNode& node, const std::vector<std::filesystem::path>& files)
{
    QStringList arguments{"-aet", QString::fromStdString(node.callingAeTitle), "-aec", QString::fromStdString(node.calledAeTitle),
                          QString::fromStdString(node.host), QString::number(node.port)};
    for (const std::filesystem::path& file : files)
        arguments << QString::fromStdString(file.string());
    QProcess storescu;
    storescu.start("storescu", arguments);
    storescu.waitForFinished(60000);
    return storescu.exitStatus() == QProcess::NormalExit ? storescu.exitCode() : -1;
}

/// Starts an Orthanc in the suite's folder `name`; null (and `failure` set) when it does not start.
std::unique_ptr<test::OrthancServer> startOrthanc(const char* name, bool strict, QString& failure)
{
    try
    {
        return std::make_unique<test::OrthancServer>(std::filesystem::path(test::outputFolder("pacs").toStdString()) / name,
                                                     strict);
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

CliResult runCli(const QStringList& arguments)
{
    QProcess cli;
    cli.setProcessChannelMode(QProcess::MergedChannels);
    cli.start(VSIM_CLI, arguments);
    cli.waitForFinished(120000);
    return {cli.exitStatus() == QProcess::NormalExit ? cli.exitCode() : -1, QString::fromUtf8(cli.readAll())};
}

QString errorOf(const std::function<void()>& call)
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

} // namespace

class TestPacs : public QObject
{
    Q_OBJECT
private slots:
    void init()
    {
        if (test::OrthancServer::executable().isEmpty())
            QSKIP("Orthanc is not installed (Debian package orthanc; scripts/install-deps.sh installs it)");
        if (QStandardPaths::findExecutable("storescu").isEmpty())
            QSKIP("storescu is not installed (Debian package dcmtk)");
    }

    void echoAndFindStudies()
    {
        QString failure;
        const std::unique_ptr<test::OrthancServer> orthanc = startOrthanc("orthanc", false, failure);
        QVERIFY2(orthanc, qPrintable(failure));
        const test::OrthancServer& server = *orthanc;
        const dicom::PacsNode node = server.node();
        dicom::pacsEcho(node);
        QVERIFY(dicom::findStudies(node, {}).empty());

        dicom::CtSeriesDescription description;
        description.patientName = "MÜLLER^JÜRGEN";
        description.patientId = "PACS-TEST-1";
        description.studyDate = "20261115";
        const test::PhantomSeries series = test::writePhantomSeries(dicom::PhantomKind::Aaa, test::smallPhantomOptions(),
                                                                    test::freshFolder("pacs", "series"), description);
        QCOMPARE(storeWithStorescu(node, series.written.files), 0);

        dicom::StudyQuery byId;
        byId.patientId = "PACS-TEST-1";
        const std::vector<dicom::StudyMatch> found = dicom::findStudies(node, byId);
        QCOMPARE(found.size(), std::size_t(1));
        QCOMPARE(QString::fromStdString(found[0].studyInstanceUid), QString::fromStdString(series.written.studyInstanceUid));
        QCOMPARE(QString::fromStdString(found[0].patientName), QString("MÜLLER^JÜRGEN")); // UTF-8 both ways
        QCOMPARE(QString::fromStdString(found[0].studyDate), QString("20261115"));
        QCOMPARE(found[0].seriesCount, 1);
        QVERIFY2(QString::fromStdString(found[0].modalities).contains("CT"), found[0].modalities.c_str());

        // Orthanc 1.10 matches no query text beyond ASCII (not even the exact UTF-8 name, with ISO_IR 192: seen
        // with DCMTK's findscu too); the name's wildcards are tried on its ASCII part.
        dicom::StudyQuery byName;
        byName.patientName = "*LLER^J*";
        QCOMPARE(dicom::findStudies(node, byName).size(), std::size_t(1));
        dicom::StudyQuery otherModality;
        otherModality.modality = "MR";
        QVERIFY(dicom::findStudies(node, otherModality).empty());
        dicom::StudyQuery inRange, outOfRange;
        inRange.dateFrom = "20261101", inRange.dateTo = "20261130";
        outOfRange.dateFrom = "20261201";
        QCOMPARE(dicom::findStudies(node, inRange).size(), std::size_t(1));
        QVERIFY(dicom::findStudies(node, outOfRange).empty());

        // C-GET: every slice back, in the series sent; an unknown study fails and leaves nothing.
        const std::filesystem::path retrieved = test::freshFolder("pacs", "retrieved");
        const std::vector<std::filesystem::path> files = dicom::retrieveStudy(node, series.written.studyInstanceUid, retrieved);
        QCOMPARE(files.size(), series.written.files.size());
        const std::vector<dicom::DicomSeries> scanned = dicom::scanDicom(retrieved).series;
        QCOMPARE(scanned.size(), std::size_t(1));
        QCOMPARE(QString::fromStdString(scanned[0].seriesInstanceUid), QString::fromStdString(series.written.seriesInstanceUid));
        QCOMPARE(scanned[0].headers.size(), series.written.files.size());
        const std::filesystem::path empty = test::freshFolder("pacs", "retrieved-nothing");
        const QString unknown = errorOf([&] { dicom::retrieveStudy(node, "1.2.3.4.5.6.7.8.9", empty); });
        QVERIFY2(!unknown.isEmpty(), "an unknown study must fail");
        QVERIFY(std::filesystem::is_empty(empty));
        QVERIFY(errorOf([&] { dicom::retrieveStudy(node, series.written.studyInstanceUid, retrieved); }).contains("not empty"));
    }

    void cliEchoAndFind()
    {
        QString failure;
        const std::unique_ptr<test::OrthancServer> orthanc = startOrthanc("orthanc-cli", false, failure);
        QVERIFY2(orthanc, qPrintable(failure));
        const dicom::PacsNode node = orthanc->node();
        const QStringList where{"--aet", "ORTHANC", "--host", "127.0.0.1", "--port", QString::number(node.port)};
        CliResult echo = runCli(QStringList{"pacs", "echo"} + where);
        QVERIFY2(echo.code == 0 && echo.output.contains("\"echo\": \"ok\""), qPrintable(echo.output));

        dicom::CtSeriesDescription description;
        description.patientId = "PACS-CLI-1";
        const test::PhantomSeries series = test::writePhantomSeries(dicom::PhantomKind::Stenosis, test::smallPhantomOptions(),
                                                                    test::freshFolder("pacs", "cli-series"), description);
        QCOMPARE(storeWithStorescu(node, series.written.files), 0);
        CliResult find = runCli(QStringList{"pacs", "find", "--patient-id", "PACS-CLI-1"} + where);
        QVERIFY2(find.code == 0 && find.output.contains(QString::fromStdString(series.written.studyInstanceUid)),
                 qPrintable(find.output));

        const QString out = QString::fromStdString(test::freshFolder("pacs", "cli-get").string()) + "/study";
        CliResult get = runCli(QStringList{"pacs", "get", "--study-uid", QString::fromStdString(series.written.studyInstanceUid),
                                           "--out", out} + where);
        QVERIFY2(get.code == 0 && QDir(out + "/dicom").entryList(QDir::Files).size() == int(series.written.files.size()),
                 qPrintable(get.output));
        // The retrieved series imports (find -> get -> import).
        const QString study = QString::fromStdString(test::freshFolder("pacs", "cli-study").string()) + "/retrieved.vsim";
        CliResult imported = runCli({"import", out + "/dicom", "--study", study});
        QVERIFY2(imported.code == 0, qPrintable(imported.output));
        CliResult again = runCli(QStringList{"pacs", "get", "--study-uid", QString::fromStdString(series.written.studyInstanceUid),
                                             "--out", out} + where);
        QVERIFY2(again.code == 1 && again.output.contains("not empty"), qPrintable(again.output));

        CliResult wrongTitle = runCli({"pacs", "echo", "--aet", "NOTORTHANC", "--host", "127.0.0.1", "--port", QString::number(node.port)});
        QVERIFY2(wrongTitle.code == 1 && wrongTitle.output.contains("rejected the association"), qPrintable(wrongTitle.output));
        CliResult badPort = runCli({"pacs", "echo", "--aet", "ORTHANC", "--host", "127.0.0.1", "--port", "70000"});
        QVERIFY2(badPort.code == 2 && badPort.output.contains("--port"), qPrintable(badPort.output));
        CliResult badDate = runCli(QStringList{"pacs", "find", "--date", "2026-11-01"} + where);
        QVERIFY2(badDate.code == 2 && badDate.output.contains("--date"), qPrintable(badDate.output));
    }

    void failuresSayWhatToFix()
    {
        QString failure;
        const std::unique_ptr<test::OrthancServer> orthanc = startOrthanc("orthanc-failures", false, failure);
        QVERIFY2(orthanc, qPrintable(failure));
        const test::OrthancServer& server = *orthanc;
        dicom::PacsNode wrongTitle = server.node();
        wrongTitle.calledAeTitle = "NOTORTHANC";
        const QString rejected = errorOf([&] { dicom::pacsEcho(wrongTitle); });
        QVERIFY2(rejected.contains("rejected the association") && rejected.contains("NOTORTHANC"), qPrintable(rejected));

        dicom::PacsNode nobody = server.node();
        nobody.port = test::freeLoopbackPort(); // nothing listens there
        const QString refused = errorOf([&] { dicom::pacsEcho(nobody); });
        QVERIFY2(refused.contains("could not connect") && refused.contains(QString::number(nobody.port)), qPrintable(refused));

        dicom::PacsNode badTitle = server.node();
        badTitle.callingAeTitle = "A_TITLE_LONGER_THAN_16";
        QVERIFY(errorOf([&] { dicom::pacsEcho(badTitle); }).contains("1 to 16 characters"));
    }

    /// Only registered modalities: VASCUSIM echoes and finds, an unknown AE title is refused.
    void strictServerRefusesStrangers()
    {
        QString failure;
        const std::unique_ptr<test::OrthancServer> orthanc = startOrthanc("orthanc-strict", true, failure);
        QVERIFY2(orthanc, qPrintable(failure));
        const test::OrthancServer& server = *orthanc;
        dicom::pacsEcho(server.node());
        QVERIFY(dicom::findStudies(server.node(), {}).empty());
        dicom::PacsNode stranger = server.node();
        stranger.callingAeTitle = "STRANGER";
        const QString refused = errorOf([&] { dicom::pacsEcho(stranger); });
        QVERIFY2(!refused.isEmpty(), "an unknown AE title must be refused");
        qInfo("an unknown AE on the strict server: %s", qPrintable(refused));
    }
};

QTEST_GUILESS_MAIN(TestPacs)
#include "tst_pacs.moc"
