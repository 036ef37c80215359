// File > Query/Retrieve (PACS) and File > Send to PACS against a real Orthanc (issue 22): a node saved in the
// settings and read back (DICOM TLS settings too), Echo, a study search by patient ID filling the tree (a
// screenshot of the dialog for the guide), a patient search opening onto the patient's study and its series,
// Cancel giving the dialog back at once, Retrieve and Import of the series into the open study, the same study
// fetched again recognised (nothing imported twice); then segment, report, and Send to PACS of the report (DICOM
// PDF) and the label (SEG) into the patient's study, and an anonymized report refused. Skips, saying so, where
// Orthanc or storescu is not installed.

#include "DicomFixtures.h"
#include "GuiTestMain.h"
#include "Languages.h"
#include "MainWindow.h"
#include "OrthancServer.h"
#include "PacsDialog.h"
#include "PacsNodes.h"
#include "PacsSendDialog.h"
#include "ReportExportDialog.h"

#include <QMessageBox>
#include <QTreeWidget>

namespace fs = std::filesystem;
using namespace vsim;

namespace {

bool toldInABox(gui::MainWindow& window, const QString& words)
{
    for (QMessageBox* box : window.findChildren<QMessageBox*>())
        if (box->text().contains(words) || box->informativeText().contains(words))
            return true;
    return false;
}

} // namespace

class TestPacsDialog : public QObject
{
    Q_OBJECT

private slots:
    void findRetrieveImportAndSend()
    {
        if (const QString reason = test::OrthancServer::unavailableReason(); !reason.isEmpty())
            QSKIP(qPrintable(reason));
        const test::OrthancServer orthanc(fs::path(test::outputFolder("gui-pacs").toStdString()) / "orthanc", false);
        dicom::CtSeriesDescription description;
        description.patientName = "GUI^PACS";
        description.patientId = "PACS-GUI-1";
        description.patientBirthDate = "19500101";
        description.studyDate = "20261120";
        description.studyDescription = "CTA abdomen";
        const test::PhantomSeries series = test::writePhantomSeries(dicom::PhantomKind::Aaa, test::smallPhantomOptions(),
                                                                    test::freshFolder("gui-pacs", "series"), description);
        QCOMPARE(orthanc.uploadWithStorescu(series.written.files), 0);

        gui::MainWindow window;
        window.show();
        QVERIFY(window.newStudy(QString::fromStdString((test::freshFolder("gui-pacs", "study") / "pacs.vsim").string())));

        auto* dialog = new gui::PacsDialog(&window);
        dialog->show();
        dicom::PacsNode withTls = orthanc.node();
        withTls.tls = {true, "/etc/pacs/ca.pem", "/etc/pacs/ours.pem", "/etc/pacs/ours.key"};
        dialog->setNode("TLS PACS", withTls);
        QVERIFY(dialog->saveNode());
        dialog->setNode("Test PACS", orthanc.node());
        QVERIFY(dialog->saveNode());
        const QList<gui::PacsNodeEntry> saved = gui::loadPacsNodes();
        QCOMPARE(saved.size(), 2);
        QCOMPARE(saved[0].name, QString("TLS PACS"));
        QVERIFY(saved[0].node.tls.enabled);
        QCOMPARE(QString::fromStdString(saved[0].node.tls.privateKey), QString("/etc/pacs/ours.key"));
        QCOMPARE(saved[1].name, QString("Test PACS"));
        QCOMPARE(saved[1].node.port, orthanc.node().port);
        QVERIFY(!saved[1].node.tls.enabled);

        QSignalSpy echoed(dialog, &gui::PacsDialog::echoFinished);
        dialog->echo();
        QVERIFY(echoed.wait(30000));
        QVERIFY2(dialog->statusText().contains("answers"), qPrintable(dialog->statusText()));

        // Studies by patient ID and dates; a study opens onto its series.
        QSignalSpy searched(dialog, &gui::PacsDialog::searchFinished);
        QSignalSpy loaded(dialog, &gui::PacsDialog::childrenLoaded);
        dialog->setFilters("", "PACS-GUI-1", "20261101", "20261130", "CT");
        dialog->search();
        QVERIFY(searched.wait(30000));
        QTreeWidget* tree = dialog->results();
        QCOMPARE(tree->topLevelItemCount(), 1);
        QTreeWidgetItem* study = tree->topLevelItem(0);
        QCOMPARE(study->text(0), QString("GUI^PACS"));
        QCOMPARE(study->text(2), QString("2026-11-20"));
        tree->setCurrentItem(study);
        QCOMPARE(dialog->selectedTarget().studyInstanceUid, series.written.studyInstanceUid);
        QVERIFY(dialog->selectedTarget().seriesInstanceUid.empty());
        study->setExpanded(true); // a series-level query
        QVERIFY(loaded.wait(30000));
        QCOMPARE(study->childCount(), 1);
        tree->setCurrentItem(study->child(0));
        QCOMPARE(dialog->selectedTarget().seriesInstanceUid, series.written.seriesInstanceUid);
        QVERIFY2(study->child(0)->text(6).startsWith(QString::number(series.written.files.size())),
                 qPrintable(study->child(0)->text(6)));
        dialog->resize(1100, 720);
        dialog->grab().save(QString::fromStdString((fs::path(test::outputFolder("gui").toStdString()) / "pacs-dialog.png").string()));

        // Patients: the one patient, its study below it, the study's series below that.
        dialog->setLevel(gui::PacsDialog::Level::Patients);
        dialog->setFilters("GUI*", "");
        dialog->search();
        QVERIFY(searched.wait(30000));
        QCOMPARE(tree->topLevelItemCount(), 1);
        QTreeWidgetItem* patient = tree->topLevelItem(0);
        QCOMPARE(patient->text(1), QString("PACS-GUI-1"));
        QVERIFY2(patient->text(2).contains("1950-01-01"), qPrintable(patient->text(2)));
        tree->setCurrentItem(patient);
        QVERIFY(dialog->selectedTarget().studyInstanceUid.empty()); // a patient is not retrieved as a whole
        patient->setExpanded(true);
        QVERIFY(loaded.wait(30000));
        QCOMPARE(patient->childCount(), 1);
        patient->child(0)->setExpanded(true);
        QVERIFY(loaded.wait(30000));
        QCOMPARE(patient->child(0)->childCount(), 1);
        QTreeWidgetItem* seriesRow = patient->child(0)->child(0);

        // Cancel: the dialog is free at once, says so, and searches again.
        dialog->search();
        QVERIFY(dialog->isBusy());
        dialog->cancel();
        QVERIFY(!dialog->isBusy());
        QCOMPARE(dialog->statusText(), QString("Cancelled."));
        dialog->setLevel(gui::PacsDialog::Level::Studies);
        dialog->setFilters("", "PACS-GUI-1");
        dialog->search();
        QVERIFY(searched.wait(30000));
        QCOMPARE(tree->topLevelItemCount(), 1);
        Q_UNUSED(seriesRow);

        // The PACS folder's clean-up: a fetch older than a day goes at the next retrieve; a recent one and what
        // VascuSim did not make stay.
        const QDir pacsFolder(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + "/pacs");
        const QString old = "1.2.3-20200101T000000000", recent = "1.2.3-" +
            QDateTime::currentDateTimeUtc().addSecs(-3600).toString("yyyyMMddTHHmmsszzz"), foreign = "notes-20200101T000000000";
        for (const QString& name : {old, recent, foreign})
        {
            QVERIFY(pacsFolder.mkpath(name));
            QFile file(pacsFolder.filePath(name + "/IM1"));
            QVERIFY(file.open(QIODevice::WriteOnly));
        }
        QVERIFY(pacsFolder.mkpath(foreign + "/subfolder")); // not what a retrieve writes

        // Retrieve and Import of the series, as the dialog's button does.
        const dicom::RetrieveTarget oneSeries(series.written.studyInstanceUid, series.written.seriesInstanceUid);
        QVERIFY(window.retrieveFromPacs(dialog->node(), oneSeries, "CT #1"));
        QVERIFY(test::waitForTask(window)); // the fetch, then the import it starts
        QVERIFY(!window.tasks().isBusy() || test::waitForTask(window));
        const study::Study& opened = window.document().study();
        QCOMPARE(opened.artifacts().size(), std::size_t(1));
        QCOMPARE(opened.artifacts().front().attributes.at("series_instance_uid"), series.written.seriesInstanceUid);
        QVERIFY(!pacsFolder.exists(old));
        QVERIFY(pacsFolder.exists(recent + "/IM1") && pacsFolder.exists(foreign + "/IM1"));
        QVERIFY(QDir(pacsFolder.filePath(recent)).removeRecursively() && QDir(pacsFolder.filePath(foreign)).removeRecursively());

        // The same study again: fetched, recognised, not imported twice (the message says so).
        QVERIFY(window.retrieveFromPacs(dialog->node(), series.written.studyInstanceUid));
        QVERIFY(test::waitForTask(window));
        QVERIFY(!window.tasks().isBusy() || test::waitForTask(window));
        QCOMPARE(opened.artifacts().size(), std::size_t(1));
        QVERIFY2(toldInABox(window, "already in the study"), "the second fetch says the series is already in the study");
        delete dialog;

        // Send to PACS: segment, report, then the report's PDF and the label's SEG into the patient's study.
        QVERIFY(window.segmentVessels() && test::waitForTask(window));
        const QString work = QString::fromStdString(test::freshFolder("gui-pacs", "report").string());
        QVERIFY(window.exportReport({work + "/report.pdf", report::PageSize::A4, false, false, false}));
        QVERIFY(test::waitForTask(window, 300000));
        gui::PacsSendDialog send(opened);
        send.chooseNode("Test PACS");
        const gui::PacsSendRequest request = send.request();
        QVERIFY(!request.reportId.empty() && !request.labelId.empty());
        QCOMPARE(request.node.port, orthanc.node().port);
        send.grab().save(QString::fromStdString((fs::path(test::outputFolder("gui").toStdString()) / "pacs-send.png").string()));
        QVERIFY(window.sendToPacs(request));
        QVERIFY(test::waitForTask(window));
        std::vector<std::string> modalities;
        for (const dicom::SeriesMatch& found : dicom::findSeries(orthanc.node(), series.written.studyInstanceUid))
            modalities.push_back(found.modality);
        std::sort(modalities.begin(), modalities.end());
        QCOMPARE(modalities, (std::vector<std::string>{"CT", "DOC", "SEG"}));

        // An anonymized report: refused by default, with the reason; nothing more on the PACS.
        QVERIFY(window.exportReport({work + "/anonymous.pdf", report::PageSize::A4, true, false, false}));
        QVERIFY(test::waitForTask(window, 300000));
        gui::PacsSendDialog sendAnonymous(opened);
        sendAnonymous.chooseNode("Test PACS");
        gui::PacsSendRequest anonymous = sendAnonymous.request();
        QCOMPARE(anonymous.anonymized, dicom::AnonymizedObjects::Refuse);
        anonymous.labelId.clear();
        QVERIFY(window.sendToPacs(anonymous));
        QVERIFY(test::waitForTask(window));
        QVERIFY2(toldInABox(window, "de-identified"), "the refusal says why");
        QCOMPARE(dicom::findStudies(orthanc.node(), {}).size(), std::size_t(1));
        const QDir outbox(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + "/pacs-outbox");
        QVERIFY2(outbox.entryList(QDir::NoDotAndDotDot | QDir::AllEntries).isEmpty(), "the outbox is left empty");

        // The German and Chinese guides' pictures of both dialogs, made in those languages (the dialogs take the
        // language in force when they are made).
        for (const QString language : {"de", "zh_CN"})
        {
            QVERIFY(gui::installLanguage(language));
            {
                gui::PacsDialog translated(&window);
                translated.show();
                translated.setNode("Test PACS", orthanc.node());
                QSignalSpy found(&translated, &gui::PacsDialog::searchFinished);
                QSignalSpy children(&translated, &gui::PacsDialog::childrenLoaded);
                translated.setFilters("", "PACS-GUI-1", "20261101", "20261130", "CT");
                translated.search();
                QVERIFY(found.wait(30000));
                QTreeWidgetItem* item = translated.results()->topLevelItem(0);
                QVERIFY(item);
                translated.results()->setCurrentItem(item);
                item->setExpanded(true);
                QVERIFY(children.wait(30000));
                translated.results()->setCurrentItem(item->child(0));
                translated.resize(1100, 720);
                QVERIFY(translated.grab().save(QString::fromStdString(
                    (fs::path(test::outputFolder("gui").toStdString()) / ("pacs-dialog-" + language.toStdString() + ".png")).string())));
                gui::PacsSendDialog translatedSend(opened);
                translatedSend.chooseNode("Test PACS");
                QVERIFY(translatedSend.grab().save(QString::fromStdString(
                    (fs::path(test::outputFolder("gui").toStdString()) / ("pacs-send-" + language.toStdString() + ".png")).string())));
            }
            gui::installLanguage("en");
        }
    }
};

VSIM_GUI_TEST_MAIN(TestPacsDialog)
#include "tst_pacs_dialog.moc"
