// Import DICOM from the GUI: the dialog scans in the background and lists patient > study > series with a
// preview, slice count and spacing, preselecting the CT with most slices; the import runs in the task runner,
// is undoable, and a cancelled import adds nothing.
#include "DicomFixtures.h"
#include "DicomImportDialog.h"
#include "GuiTestMain.h"
#include "MainWindow.h"

#include <QSignalSpy>
#include <fstream>
#include <QTreeWidget>

namespace fs = std::filesystem;
using namespace vsim;

class TestDicomDialog : public QObject
{
    Q_OBJECT


    static std::vector<QTreeWidgetItem*> seriesRows(QTreeWidget* tree)
    {
        std::vector<QTreeWidgetItem*> rows;
        for (QTreeWidgetItemIterator it(tree); *it; ++it)
            if ((*it)->childCount() == 0)
                rows.push_back(*it);
        return rows;
    }

private slots:
    void listsPreviewsAndImports()
    {
        const fs::path folder = test::freshFolder("gui-dicom", "two-series");
        dicom::CtSeriesDescription second;
        second.fileNamePrefix = "ST";
        second.seriesNumber = 2;
        second.seriesDescription = "Runoff";
        dicom::PhantomOptions larger = test::smallPhantomOptions();
        larger.size[2] = 56;
        const auto aaa = test::writePhantomSeries(dicom::PhantomKind::Aaa, test::smallPhantomOptions(), folder);
        const auto runoff = test::writePhantomSeries(dicom::PhantomKind::Stenosis, larger, folder, second);

        gui::MainWindow window;
        window.show();
        const fs::path bundle = test::freshFolder("gui-dicom", "study") / "dicom.vsim";
        QVERIFY(window.newStudy(QString::fromStdString(bundle.string())));

        gui::DicomImportDialog dialog(&window);
        dialog.show();
        QSignalSpy previews(&dialog, &gui::DicomImportDialog::thumbnailsFinished);
        dialog.scan(QString::fromStdString(folder.string()));
        QVERIFY(previews.wait(60000));
        const auto rows = seriesRows(dialog.seriesTree());
        QCOMPARE(rows.size(), std::size_t(2));
        QCOMPARE(dialog.selectedSeriesKey().toStdString(), runoff.written.seriesInstanceUid); // most slices
        for (QTreeWidgetItem* row : rows)
        {
            QVERIFY2(!row->icon(0).isNull(), "every series has a preview");
            QVERIFY(row->text(2) == "48" || row->text(2) == "56");
            QVERIFY(row->text(3).startsWith("3.50 x 3.50 x 8.00"));
        }
        dialog.grab().save(QString::fromStdString((fs::path(test::outputFolder("gui").toStdString()) / "dicom-import-dialog.png").string()));

        // Import the other series, as a user picking it would.
        QVERIFY(window.importDicom(dialog.scannedPath(), QString::fromStdString(aaa.written.seriesInstanceUid),
                                   dialog.scanResult()));
        QVERIFY(vsim::test::waitForTask(window));
        const study::Study& study = window.document().study();
        QCOMPARE(study.artifacts().size(), std::size_t(1));
        const study::Artifact& image = study.artifacts().front();
        QCOMPARE(image.provenance.command, std::string("import dicom"));
        QCOMPARE(image.attributes.at("series_instance_uid"), aaa.written.seriesInstanceUid);
        QCOMPARE(study.metadata().at("patient_id"), std::string("VSIM-PHANTOM"));
        QCOMPARE(test::differingVoxels(study.loadImage(image.id), aaa.truth), std::size_t(0));
        window.document().undoStack()->undo();
        QCOMPARE(window.document().study().artifacts().size(), std::size_t(0));
        window.document().undoStack()->redo();
        QCOMPARE(window.document().study().artifacts().size(), std::size_t(1));
    }

    void cancelledImportAddsNothing()
    {
        const fs::path folder = test::freshFolder("gui-dicom", "large");
        dicom::PhantomOptions options = test::smallPhantomOptions();
        options.size = {128, 128, 300};
        options.spacing = {2.6, 2.6, 1.3};
        test::writePhantomSeries(dicom::PhantomKind::Aaa, options, folder);
        gui::MainWindow window;
        const fs::path bundle = test::freshFolder("gui-dicom", "cancel") / "cancel.vsim";
        QVERIFY(window.newStudy(QString::fromStdString(bundle.string())));
        QSignalSpy cancelled(&window.tasks(), &gui::TaskRunner::cancelled);
        QVERIFY(window.importDicom(QString::fromStdString(folder.string())));
        window.tasks().cancel();
        QVERIFY(vsim::test::waitForTask(window));
        QCOMPARE(cancelled.count(), 1);
        QCOMPARE(window.document().study().artifacts().size(), std::size_t(0));
        QVERIFY(!window.document().undoStack()->canUndo());
    }

    void junkFolderReportsWhy()
    {
        const fs::path folder = test::freshFolder("gui-dicom", "junk");
        std::ofstream(folder / "notes.txt") << "not DICOM";
        gui::MainWindow window;
        const fs::path bundle = test::freshFolder("gui-dicom", "junk-study") / "junk.vsim";
        QVERIFY(window.newStudy(QString::fromStdString(bundle.string())));
        QSignalSpy failed(&window.tasks(), &gui::TaskRunner::failed);
        QVERIFY(window.importDicom(QString::fromStdString(folder.string())));
        QVERIFY(vsim::test::waitForTask(window));
        QCOMPARE(failed.count(), 1);
        QVERIFY(failed.front().at(1).toString().contains("no importable DICOM image series"));
        QCOMPARE(window.document().study().artifacts().size(), std::size_t(0));
    }
};

VSIM_GUI_TEST_MAIN(TestDicomDialog)
#include "tst_dicom_dialog.moc"
