// File > Query/Retrieve (PACS) against a real Orthanc (issue 22): a node saved in the settings and read back, Echo,
// a search by patient ID filling the table (a screenshot of the dialog for the guide), Retrieve and Import into the
// open study in the task runner, and the same study fetched again recognised (nothing imported twice). Skips,
// saying so, where Orthanc or storescu is not installed.

#include "DicomFixtures.h"
#include "GuiTestMain.h"
#include "MainWindow.h"
#include "OrthancServer.h"
#include "PacsDialog.h"
#include "PacsNodes.h"

#include <QMessageBox>
#include <QTableWidget>

namespace fs = std::filesystem;
using namespace vsim;

class TestPacsDialog : public QObject
{
    Q_OBJECT

private slots:
    void findRetrieveAndImport()
    {
        if (const QString reason = test::OrthancServer::unavailableReason(); !reason.isEmpty())
            QSKIP(qPrintable(reason));
        const test::OrthancServer orthanc(fs::path(test::outputFolder("gui-pacs").toStdString()) / "orthanc", false);
        dicom::CtSeriesDescription description;
        description.patientName = "GUI^PACS";
        description.patientId = "PACS-GUI-1";
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
        dialog->setNode("Test PACS", orthanc.node());
        QVERIFY(dialog->saveNode());
        const QList<gui::PacsNodeEntry> saved = gui::loadPacsNodes();
        QCOMPARE(saved.size(), 1);
        QCOMPARE(saved[0].name, QString("Test PACS"));
        QCOMPARE(saved[0].node.port, orthanc.node().port);

        QSignalSpy echoed(dialog, &gui::PacsDialog::echoFinished);
        dialog->echo();
        QVERIFY(echoed.wait(30000));
        QVERIFY2(dialog->statusText().contains("answers"), qPrintable(dialog->statusText()));

        QSignalSpy searched(dialog, &gui::PacsDialog::searchFinished);
        dialog->setFilters("", "PACS-GUI-1", "20261101", "20261130", "CT");
        dialog->search();
        QVERIFY(searched.wait(30000));
        QCOMPARE(dialog->results()->rowCount(), 1);
        QCOMPARE(dialog->results()->item(0, 0)->text(), QString("GUI^PACS"));
        QCOMPARE(dialog->results()->item(0, 2)->text(), QString("2026-11-20"));
        QCOMPARE(dialog->selectedStudyUid().toStdString(), series.written.studyInstanceUid);
        dialog->grab().save(QString::fromStdString((fs::path(test::outputFolder("gui").toStdString()) / "pacs-dialog.png").string()));

        // Retrieve and Import, as the dialog's button does.
        QVERIFY(window.retrieveFromPacs(dialog->node(), dialog->selectedStudyUid(), dialog->selectedStudyLabel()));
        QVERIFY(test::waitForTask(window)); // the fetch, then the import it starts
        QVERIFY(!window.tasks().isBusy() || test::waitForTask(window));
        const study::Study& study = window.document().study();
        QCOMPARE(study.artifacts().size(), std::size_t(1));
        QCOMPARE(study.artifacts().front().attributes.at("series_instance_uid"), series.written.seriesInstanceUid);

        // The same study again: fetched, recognised, not imported twice (the message says so).
        QVERIFY(window.retrieveFromPacs(dialog->node(), dialog->selectedStudyUid()));
        QVERIFY(test::waitForTask(window));
        QVERIFY(!window.tasks().isBusy() || test::waitForTask(window));
        QCOMPARE(study.artifacts().size(), std::size_t(1));
        bool told = false;
        for (QMessageBox* box : window.findChildren<QMessageBox*>())
            told = told || box->text().contains("already in the study");
        QVERIFY2(told, "the second fetch says the series is already in the study");
        delete dialog;
    }
};

VSIM_GUI_TEST_MAIN(TestPacsDialog)
#include "tst_pacs_dialog.moc"
