// The PACS client against a real Orthanc (issue 22; tests/support/OrthancServer.h starts one on a loopback port
// with a temporary configuration and stops it at the end, also when a test fails). A phantom CT series is uploaded
// with DCMTK's storescu (another implementation than ours), then: C-ECHO; C-FIND at the study level by patient ID,
// by a name with a wildcard, by modality and by a date range, each against what was uploaded, at the patient and
// the series level, and cancelled; C-GET of a study and of one series (DICOM TLS and a partial transfer:
// tst_pacs_transport.cpp); the failures (a wrong called AE title, a port where nothing listens, a node that never
// answers, an unknown calling AE on a strict server for echo, find, get, move and store, while VASCUSIM gets,
// moves and stores there) give messages that say what to fix; `vascusim-cli pacs echo|find` the same way, with
// its exit codes. The round trip through the CLI: find -> get -> import -> segment -> report -> store the report's
// PDF and the labels' SEG into the patient's study -> find them -> get them back -> dcmdump them; an anonymized
// report refused, then stored as a new study on request; the UID root applied. Skips, saying so, where Orthanc is
// not installed (scripts/install-deps.sh installs it).

#include "DicomFixtures.h"
#include "PacsTestSupport.h"
#include "vsim/core/Error.h"
#include "vsim/dicom/DicomScan.h"
#include "vsim/dicom/PacsClient.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QtTest>

using namespace vsim;
using test::CliResult;
using test::dumpedValue;
using test::dumpedValues;
using test::errorOf;
using test::fileOfModality;
using test::jsonOf;
using test::runCli;
using test::startOrthanc;

class TestPacs : public QObject
{
    Q_OBJECT
private slots:
    void init()
    {
        if (const QString reason = test::OrthancServer::unavailableReason(); !reason.isEmpty())
            QSKIP(qPrintable(reason));
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
        QCOMPARE(orthanc->uploadWithStorescu(series.written.files), 0);

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
        const QString unknown = errorOf([&] { dicom::retrieveStudy(node, std::string("1.2.3.4.5.6.7.8.9"), empty); });
        QVERIFY2(!unknown.isEmpty(), "an unknown study must fail");
        QVERIFY(std::filesystem::is_empty(empty));
        QVERIFY(errorOf([&] { dicom::retrieveStudy(node, series.written.studyInstanceUid, retrieved); }).contains("not empty"));

        // The patient level (Patient Root) and the series level (Study Root), each against what was uploaded.
        const std::vector<dicom::PatientMatch> patients = dicom::findPatients(node, {"", "PACS-TEST-1"});
        QCOMPARE(patients.size(), std::size_t(1));
        QCOMPARE(QString::fromStdString(patients[0].patientName), QString("MÜLLER^JÜRGEN"));
        QCOMPARE(patients[0].studyCount, 1);
        QVERIFY(dicom::findPatients(node, {"", "NOBODY"}).empty());
        const std::vector<dicom::SeriesMatch> seriesFound = dicom::findSeries(node, series.written.studyInstanceUid);
        QCOMPARE(seriesFound.size(), std::size_t(1));
        QCOMPARE(QString::fromStdString(seriesFound[0].seriesInstanceUid), QString::fromStdString(series.written.seriesInstanceUid));
        QCOMPARE(QString::fromStdString(seriesFound[0].modality), QString("CT"));
        QCOMPARE(seriesFound[0].instanceCount, int(series.written.files.size()));
        QVERIFY(dicom::findSeries(node, series.written.studyInstanceUid, "SEG").empty());
        QVERIFY(errorOf([&] { dicom::findSeries(node, ""); }).contains("study's instance UID"));
        // C-GET of the one series; an unknown series of the study fails and leaves nothing.
        const std::filesystem::path oneSeries = test::freshFolder("pacs", "retrieved-series");
        const dicom::RetrieveTarget target(series.written.studyInstanceUid, series.written.seriesInstanceUid);
        QCOMPARE(dicom::retrieveStudy(node, target, oneSeries).size(), series.written.files.size());
        const std::filesystem::path noSeries = test::freshFolder("pacs", "retrieved-no-series");
        const QString unknownSeries =
            errorOf([&] { dicom::retrieveStudy(node, {series.written.studyInstanceUid, "1.2.3.4.5"}, noSeries); });
        QVERIFY2(unknownSeries.contains("series 1.2.3.4.5") && std::filesystem::is_empty(noSeries), qPrintable(unknownSeries));

        // Cancel during a query: a C-CANCEL at the first answer, vsim::Cancelled here.
        CancellationToken token;
        token.cancel();
        const Progress cancelled([](double, const std::string&) {}, token);
        for (int level = 0; level < 3; ++level)
        {
            bool threw = false;
            try
            {
                if (level == 0)
                    dicom::findPatients(node, {}, cancelled);
                else if (level == 1)
                    dicom::findStudies(node, {}, cancelled);
                else
                    dicom::findSeries(node, series.written.studyInstanceUid, {}, cancelled);
            }
            catch (const Cancelled&)
            {
                threw = true;
            }
            QVERIFY2(threw, "a cancelled query throws Cancelled");
        }
        dicom::pacsEcho(node); // and the PACS still answers
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
        QCOMPARE(orthanc->uploadWithStorescu(series.written.files), 0);
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
        // Fetched twice: recognised by its Series Instance UID, not imported again.
        CliResult twice = runCli({"import", out + "/dicom", "--study", study});
        QVERIFY2(twice.code == 1 && twice.output.contains("already in the study"), qPrintable(twice.output));
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

    void roundTripThroughTheCli()
    {
        QString failure;
        const std::unique_ptr<test::OrthancServer> orthanc = startOrthanc("orthanc-round-trip", false, failure);
        QVERIFY2(orthanc, qPrintable(failure));
        const QStringList where{"--aet", "ORTHANC", "--host", "127.0.0.1", "--port", QString::number(orthanc->node().port)};
        dicom::CtSeriesDescription description;
        description.patientName = "ROUND^TRIP";
        description.patientId = "PACS-ROUND-1";
        const test::PhantomSeries series = test::writePhantomSeries(dicom::PhantomKind::Stenosis, test::smallPhantomOptions(),
                                                                    test::freshFolder("pacs", "round-series"), description);
        QCOMPARE(orthanc->uploadWithStorescu(series.written.files), 0);
        const QString studyUid = QString::fromStdString(series.written.studyInstanceUid);
        const QString work = QString::fromStdString(test::freshFolder("pacs", "round-trip").string());

        // find -> get -> import -> segment -> report (DICOM PDF) and the label as SEG, under our UID root.
        CliResult find = runCli(QStringList{"pacs", "find", "--patient-id", "PACS-ROUND-1"} + where);
        QVERIFY2(find.code == 0 && find.output.contains(studyUid), qPrintable(find.output));
        CliResult get = runCli(QStringList{"pacs", "get", "--study-uid", studyUid, "--out", work + "/get"} + where);
        QVERIFY2(get.code == 0, qPrintable(get.output));
        const QString study = work + "/patient.vsim";
        for (const QStringList& step : {QStringList{"import", work + "/get/dicom", "--study", study},
                                        QStringList{"segment", "--study", study},
                                        QStringList{"report", "--study", study, "--out", work + "/report.pdf", "--dicom-pdf",
                                                    work + "/report.dcm", "--uid-root", "1.2.826.0.1.3680043.10.999"},
                                        QStringList{"report", "--study", study, "--out", work + "/anonymous.pdf",
                                                    "--dicom-pdf", work + "/anonymous.dcm", "--anonymize"},
                                        QStringList{"export-label", "--study", study, "--out", work + "/labels.dcm"}})
        {
            const CliResult result = runCli(step);
            QVERIFY2(result.code == 0, qPrintable(step.join(' ') + ": " + result.output));
        }

        // store: both into the patient's study; then the PACS lists them there.
        CliResult store = runCli(QStringList{"pacs", "store", work + "/report.dcm", work + "/labels.dcm"} + where);
        QVERIFY2(store.code == 0, qPrintable(store.output));
        const QJsonArray stored = jsonOf(store.output)["stored"].toArray();
        QCOMPARE(stored.size(), 2);
        for (const QJsonValue& object : stored)
            QCOMPARE(object["study_instance_uid"].toString(), studyUid);
        find = runCli(QStringList{"pacs", "find", "--patient-id", "PACS-ROUND-1"} + where);
        const QJsonArray studies = jsonOf(find.output)["studies"].toArray();
        QVERIFY2(find.code == 0 && studies.size() == 1, qPrintable(find.output));
        QCOMPARE(studies[0]["series"].toInt(), 3);
        const QString modalities = studies[0]["modalities"].toString();
        QVERIFY2(modalities.contains("CT") && modalities.contains("DOC") && modalities.contains("SEG"), qPrintable(modalities));
        // The series level lists the three; the patient level the one patient with the one study.
        CliResult seriesFind = runCli(QStringList{"pacs", "find", "--level", "series", "--study-uid", studyUid} + where);
        const QJsonArray seriesList = jsonOf(seriesFind.output)["series"].toArray();
        QVERIFY2(seriesFind.code == 0 && seriesList.size() == 3, qPrintable(seriesFind.output));
        QString segSeries;
        for (const QJsonValue& one : seriesList)
            if (one["modality"].toString() == "SEG")
                segSeries = one["series_instance_uid"].toString();
        QVERIFY2(!segSeries.isEmpty(), qPrintable(seriesFind.output));
        CliResult patientFind = runCli(QStringList{"pacs", "find", "--level", "patient", "--patient-id", "PACS-ROUND-1"} + where);
        const QJsonArray patientList = jsonOf(patientFind.output)["patients"].toArray();
        QVERIFY2(patientFind.code == 0 && patientList.size() == 1 && patientList[0]["studies"].toInt() == 1,
                 qPrintable(patientFind.output));
        CliResult noStudy = runCli(QStringList{"pacs", "find", "--level", "series"} + where);
        QVERIFY2(noStudy.code == 2 && noStudy.output.contains("--study-uid"), qPrintable(noStudy.output));
        CliResult badLevel = runCli(QStringList{"pacs", "find", "--level", "image"} + where);
        QVERIFY2(badLevel.code == 2 && badLevel.output.contains("--level"), qPrintable(badLevel.output));
        // C-GET of the SEG series alone: the one object.
        CliResult segGet = runCli(QStringList{"pacs", "get", "--study-uid", studyUid, "--series-uid", segSeries, "--out",
                                              work + "/seg-only"} + where);
        QVERIFY2(segGet.code == 0 && QDir(work + "/seg-only/dicom").entryList(QDir::Files).size() == 1, qPrintable(segGet.output));

        // get them back and read them with dcmdump: the PDF and the SEG in the CT's study, the SEG referencing the
        // CT series, the UIDs under the root given.
        get = runCli(QStringList{"pacs", "get", "--study-uid", studyUid, "--out", work + "/back"} + where);
        QVERIFY2(get.code == 0, qPrintable(get.output));
        const QString pdf = fileOfModality(work + "/back/dicom", "DOC"), seg = fileOfModality(work + "/back/dicom", "SEG");
        QVERIFY2(!pdf.isEmpty() && !seg.isEmpty(), "the PDF and the SEG come back, one each");
        QCOMPARE(dumpedValue(pdf, "0008,0016"), QString("1.2.840.10008.5.1.4.1.1.104.1")); // Encapsulated PDF Storage
        QCOMPARE(dumpedValue(pdf, "0042,0012"), QString("application/pdf"));
        QCOMPARE(dumpedValue(pdf, "0020,000d"), studyUid);
        QVERIFY(dumpedValue(pdf, "0008,0018").startsWith("1.2.826.0.1.3680043.10.999."));
        QCOMPARE(dumpedValue(pdf, "0010,0020"), QString("PACS-ROUND-1"));
        QCOMPARE(dumpedValue(seg, "0008,0016"), QString("1.2.840.10008.5.1.4.1.1.66.4")); // Segmentation Storage
        QCOMPARE(dumpedValue(seg, "0020,000d"), studyUid);
        QVERIFY(dumpedValues(seg, "0020,000e").contains(QString::fromStdString(series.written.seriesInstanceUid)));

        // The anonymized report: refused (nothing sent), then on request a new study of its own.
        CliResult refused = runCli(QStringList{"pacs", "store", work + "/anonymous.dcm", work + "/labels.dcm"} + where);
        QVERIFY2(refused.code == 1 && refused.output.contains("de-identified") && refused.output.contains("Nothing was sent"),
                 qPrintable(refused.output));
        find = runCli(QStringList{"pacs", "find"} + where);
        QCOMPARE(jsonOf(find.output)["studies"].toArray().size(), 1);
        CliResult asNew = runCli(QStringList{"pacs", "store", work + "/anonymous.dcm", "--anonymized", "new-study"} + where);
        QVERIFY2(asNew.code == 0, qPrintable(asNew.output));
        const QJsonObject anonymous = jsonOf(asNew.output)["stored"].toArray()[0].toObject();
        QVERIFY(anonymous["as_new_study"].toBool() && anonymous["study_instance_uid"].toString() != studyUid);
        find = runCli(QStringList{"pacs", "find", "--patient-id", "ANONYMIZED"} + where);
        const QJsonArray anonymousStudies = jsonOf(find.output)["studies"].toArray();
        QVERIFY2(anonymousStudies.size() == 1 &&
                     anonymousStudies[0]["study_instance_uid"].toString() == anonymous["study_instance_uid"].toString(),
                 qPrintable(find.output));
        CliResult badOption = runCli(QStringList{"pacs", "store", work + "/anonymous.dcm", "--anonymized", "keep"} + where);
        QVERIFY2(badOption.code == 2 && badOption.output.contains("--anonymized"), qPrintable(badOption.output));
        CliResult notDicom = runCli(QStringList{"pacs", "store", work + "/report.pdf"} + where);
        QVERIFY2(notDicom.code == 1 && notDicom.output.contains("not a DICOM file"), qPrintable(notDicom.output));
        CliResult badRoot = runCli({"report", "--study", study, "--out", work + "/r2.pdf", "--uid-root", "1.02.3"});
        QVERIFY2(badRoot.code == 2 && badRoot.output.contains("--uid-root") && !QFile::exists(work + "/r2.pdf"),
                 qPrintable(badRoot.output));
    }

    /// C-MOVE to our own listener; a destination the PACS does not know, or where nothing listens, fails and leaves
    /// nothing; Cancel during a C-GET or a C-MOVE leaves nothing.
    void moveToOurListenerAndCancel()
    {
        QString failure;
        const int listenPort = test::freeLoopbackPort();
        const std::unique_ptr<test::OrthancServer> orthanc = startOrthanc("orthanc-move", false, failure, listenPort);
        QVERIFY2(orthanc, qPrintable(failure));
        const dicom::PacsNode node = orthanc->node();
        dicom::CtSeriesDescription description;
        description.patientId = "PACS-MOVE-1";
        const test::PhantomSeries series = test::writePhantomSeries(dicom::PhantomKind::Aaa, test::smallPhantomOptions(),
                                                                    test::freshFolder("pacs", "move-series"), description);
        QCOMPARE(orthanc->uploadWithStorescu(series.written.files), 0);
        const std::string uid = series.written.studyInstanceUid;

        const std::filesystem::path moved = test::freshFolder("pacs", "moved");
        const std::vector<std::filesystem::path> files = dicom::moveStudy(node, uid, moved, listenPort);
        QCOMPARE(files.size(), series.written.files.size());
        const std::vector<dicom::DicomSeries> scanned = dicom::scanDicom(moved).series;
        QCOMPARE(scanned.size(), std::size_t(1));
        QCOMPARE(scanned[0].headers.size(), series.written.files.size());

        const std::filesystem::path nowhere = test::freshFolder("pacs", "moved-nowhere");
        const QString notListening = errorOf([&] { dicom::moveStudy(node, uid, nowhere, test::freeLoopbackPort()); });
        QVERIFY2(!notListening.isEmpty() && std::filesystem::is_empty(nowhere), qPrintable(notListening));
        dicom::PacsNode unknown = node;
        unknown.callingAeTitle = "UNKNOWNAE";
        const QString unknownDestination = errorOf([&] { dicom::moveStudy(unknown, uid, nowhere, listenPort); });
        QVERIFY2(unknownDestination.contains("is our AE title UNKNOWNAE registered at the PACS") &&
                     std::filesystem::is_empty(nowhere),
                 qPrintable(unknownDestination));

        CancellationToken token;
        token.cancel();
        const Progress cancelled([](double, const std::string&) {}, token);
        for (bool move : {false, true})
        {
            const std::filesystem::path folder = test::freshFolder("pacs", move ? "move-cancelled" : "get-cancelled");
            bool threw = false;
            try
            {
                move ? dicom::moveStudy(node, uid, folder, listenPort, cancelled)
                     : dicom::retrieveStudy(node, uid, folder, cancelled);
            }
            catch (const Cancelled&)
            {
                threw = true;
            }
            QVERIFY2(threw && std::filesystem::is_empty(folder), move ? "C-MOVE cancel" : "C-GET cancel");
        }

        const QString out = QString::fromStdString(test::freshFolder("pacs", "cli-move").string()) + "/study";
        CliResult get = runCli({"pacs", "get", "--aet", "ORTHANC", "--host", "127.0.0.1", "--port", QString::number(node.port),
                                "--study-uid", QString::fromStdString(uid), "--out", out, "--move", QString::number(listenPort)});
        QVERIFY2(get.code == 0 && get.output.contains("C-MOVE") &&
                     QDir(out + "/dicom").entryList(QDir::Files).size() == int(series.written.files.size()),
                 qPrintable(get.output));
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

    /// Only registered modalities: VASCUSIM echoes, finds, gets, moves and stores; an unknown AE title is refused
    /// each time and leaves nothing.
    void strictServerRefusesStrangers()
    {
        QString failure;
        const int listenPort = test::freeLoopbackPort();
        const std::unique_ptr<test::OrthancServer> orthanc = startOrthanc("orthanc-strict", true, failure, listenPort);
        QVERIFY2(orthanc, qPrintable(failure));
        const test::OrthancServer& server = *orthanc;
        dicom::pacsEcho(server.node());
        QVERIFY(dicom::findStudies(server.node(), {}).empty());
        dicom::CtSeriesDescription description;
        description.patientId = "PACS-STRICT-1";
        const test::PhantomSeries series = test::writePhantomSeries(dicom::PhantomKind::Stenosis, test::smallPhantomOptions(),
                                                                    test::freshFolder("pacs", "strict-series"), description);
        QCOMPARE(server.uploadWithStorescu(series.written.files), 0);
        const std::string uid = series.written.studyInstanceUid;
        QCOMPARE(dicom::findStudies(server.node(), {}).size(), std::size_t(1));
        const std::filesystem::path got = test::freshFolder("pacs", "strict-get");
        QCOMPARE(dicom::retrieveStudy(server.node(), uid, got).size(), series.written.files.size());
        const std::filesystem::path moved = test::freshFolder("pacs", "strict-move");
        QCOMPARE(dicom::moveStudy(server.node(), uid, moved, listenPort).size(), series.written.files.size());
        const std::vector<dicom::StoredObject> stored = dicom::storeFiles(server.node(), {series.written.files.front()});
        QCOMPARE(stored.size(), std::size_t(1));

        dicom::PacsNode stranger = server.node();
        stranger.callingAeTitle = "STRANGER";
        const QString refused = errorOf([&] { dicom::pacsEcho(stranger); });
        QVERIFY2(!refused.isEmpty(), "an unknown AE title must be refused");
        qInfo("an unknown AE on the strict server: %s", qPrintable(refused));
        QVERIFY(!errorOf([&] { dicom::findStudies(stranger, {}); }).isEmpty());
        const std::filesystem::path strangerGet = test::freshFolder("pacs", "strict-stranger-get");
        QVERIFY(!errorOf([&] { dicom::retrieveStudy(stranger, uid, strangerGet); }).isEmpty());
        QVERIFY(std::filesystem::is_empty(strangerGet));
        const std::filesystem::path strangerMove = test::freshFolder("pacs", "strict-stranger-move");
        QVERIFY(!errorOf([&] { dicom::moveStudy(stranger, uid, strangerMove, listenPort); }).isEmpty());
        QVERIFY(std::filesystem::is_empty(strangerMove));
        QVERIFY(!errorOf([&] { dicom::storeFiles(stranger, {series.written.files.front()}); }).isEmpty());
    }

    /// A PACS that accepts the connection and never answers: the node's timeout ends the wait with a message.
    void silentServerTimesOut()
    {
        const int listening = ::socket(AF_INET, SOCK_STREAM, 0);
        sockaddr_in address{};
        address.sin_family = AF_INET;
        address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        socklen_t length = sizeof address;
        QVERIFY(::bind(listening, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0);
        QVERIFY(::listen(listening, 4) == 0);
        QVERIFY(::getsockname(listening, reinterpret_cast<sockaddr*>(&address), &length) == 0);
        dicom::PacsNode silent{"SILENT", "127.0.0.1", ntohs(address.sin_port)};
        silent.timeoutS = 2;
        QElapsedTimer clock;
        clock.start();
        const QString timedOut = errorOf([&] { dicom::pacsEcho(silent); });
        const double seconds = clock.elapsed() / 1000.0;
        ::close(listening);
        qInfo("a silent PACS: %.1f s, '%s'", seconds, qPrintable(timedOut));
        QVERIFY2(timedOut.contains("did not answer within 2 s") && timedOut.contains(QString::number(silent.port)),
                 qPrintable(timedOut));
        QVERIFY2(seconds < 10.0, "the 2 s timeout bounds the wait");
    }
};

QTEST_GUILESS_MAIN(TestPacs)
#include "tst_pacs.moc"
