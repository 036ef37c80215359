// The document workflow of the main window: import a volume in the background, undo and redo the import and a
// rename, save, and reopen with the same artifacts; a broken file gives an error and leaves the study untouched.
#include "ArtifactCommands.h"
#include "GuiTestMain.h"
#include "MainWindow.h"
#include "StudyFixtures.h"
#include "TestOutput.h"
#include "vsim/dicom/DicomSegmentation.h"
#include "vsim/interop/ItkImage.h"

#include <QSignalSpy>
#include <itkImageFileWriter.h>
#include <itkNrrdImageIO.h>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

class TestDocument : public QObject
{
    Q_OBJECT

private slots:
    void importUndoRedoSaveReopen()
    {
        const fs::path folder(vsim::test::outputFolder("gui-document").toStdString());
        const fs::path bundle = folder / "document.vsim";
        fs::remove_all(bundle);
        const fs::path volume = folder / "volume.nrrd";
        auto writer = itk::ImageFileWriter<vsim::interop::ItkImage3<std::int16_t>>::New();
        writer->SetImageIO(itk::NrrdImageIO::New());
        const vsim::CtVolume truth = vsim::test::patternedVolume(12, 5);
        writer->SetInput(vsim::interop::toItk(truth));
        writer->SetFileName(volume.string());
        writer->Update();

        auto* window = new vsim::gui::MainWindow();
        window->show();
        QVERIFY(window->newStudy(QString::fromStdString(bundle.string())));
        QVERIFY(window->importVolume(QString::fromStdString(volume.string())));
        QVERIFY(vsim::test::waitForTask(*window));
        auto& document = window->document();
        QCOMPARE(document.study().artifacts().size(), std::size_t(1));
        const std::string id = document.study().artifacts()[0].id;

        document.undoStack()->push(new vsim::gui::RenameArtifactCommand(document, id, "Arterial"));
        QCOMPARE(document.study().artifact(id).name, std::string("Arterial"));
        document.undoStack()->undo();
        QCOMPARE(document.study().artifact(id).name, std::string("volume"));
        document.undoStack()->undo(); // the import
        QVERIFY(document.study().artifacts().empty());
        document.undoStack()->redo();
        document.undoStack()->redo();
        QCOMPARE(document.study().artifact(id).name, std::string("Arterial"));
        QVERIFY(window->isWindowModified());

        QVERIFY(window->saveStudy());
        QVERIFY(vsim::test::waitForTask(*window));
        QVERIFY(!window->isWindowModified());
        const vsim::study::Study reopened = vsim::study::Study::open(bundle, vsim::study::Access::ReadOnly);
        QCOMPARE(reopened.artifact(id).name, std::string("Arterial"));
        QVERIFY(vsim::test::samePattern(reopened.loadImage(id), 5));

        // A mask on the CT's grid imports as a label (File > Import Label), shown in the MPRs; one on another grid
        // is refused with a message and adds nothing.
        vsim::CtVolume mask(truth.geometry());
        mask.data()[17] = 1;
        mask.data()[18] = 1;
        writer->SetInput(vsim::interop::toItk(mask));
        writer->SetFileName((folder / "mask.nrrd").string());
        writer->Update();
        QVERIFY(window->importLabel(QString::fromStdString((folder / "mask.nrrd").string())));
        QVERIFY(vsim::test::waitForTask(*window));
        const vsim::study::Artifact label = document.study().artifacts().back();
        QCOMPARE(label.kind, vsim::study::ArtifactKind::Label);
        QCOMPARE(int(document.study().loadLabel(label.id).data()[18]), 1);
        // The same as a DICOM SEG (written by DCMTK's dcmseg): the same voxels.
        vsim::LabelVolume asLabel(truth.geometry());
        std::fill(asLabel.data(), asLabel.data() + asLabel.size(), std::uint8_t(0));
        asLabel.data()[17] = asLabel.data()[18] = 1;
        vsim::dicom::writeDicomSegmentation(asLabel, {"lumen"}, {}, folder / "mask-seg.dcm");
        QSignalSpy segFailed(&window->tasks(), &vsim::gui::TaskRunner::failed);
        QVERIFY(window->importLabel(QString::fromStdString((folder / "mask-seg.dcm").string())));
        QVERIFY(vsim::test::waitForTask(*window));
        QVERIFY2(segFailed.isEmpty(), segFailed.isEmpty() ? "" : qPrintable(segFailed.front().at(1).toString()));
        const vsim::study::Artifact fromSeg = document.study().artifacts().back();
        QCOMPARE(fromSeg.provenance.parameters.at("source"), std::string("DICOM SEG"));
        const vsim::LabelVolume segLabel = document.study().loadLabel(fromSeg.id);
        QVERIFY(std::equal(segLabel.data(), segLabel.data() + segLabel.size(), asLabel.data()));
        document.undoStack()->undo();
        vsim::VolumeGeometry shifted = truth.geometry();
        shifted.origin.x() += 0.35; // half a voxel
        vsim::CtVolume misplaced(shifted);
        misplaced.data()[17] = 1;
        writer->SetInput(vsim::interop::toItk(misplaced));
        writer->SetFileName((folder / "misplaced.nrrd").string());
        writer->Update();
        QSignalSpy refused(&window->tasks(), &vsim::gui::TaskRunner::failed);
        QVERIFY(window->importLabel(QString::fromStdString((folder / "misplaced.nrrd").string())));
        QVERIFY(vsim::test::waitForTask(*window));
        QCOMPARE(refused.count(), 1);
        QCOMPARE(document.study().artifacts().size(), std::size_t(2));
        document.undoStack()->undo(); // the label
        QCOMPARE(document.study().artifacts().size(), std::size_t(1));

        // A broken file: the task fails with a message, the study keeps its one artifact.
        const fs::path junk = folder / "junk.nii";
        std::ofstream(junk) << "not a volume";
        QSignalSpy failed(&window->tasks(), &vsim::gui::TaskRunner::failed);
        QVERIFY(window->importVolume(QString::fromStdString(junk.string())));
        QVERIFY(vsim::test::waitForTask(*window));
        QCOMPARE(failed.count(), 1);
        QCOMPARE(document.study().artifacts().size(), std::size_t(1));
        window->setAttribute(Qt::WA_DeleteOnClose, false);
        delete window;
    }
};

VSIM_GUI_TEST_MAIN(TestDocument)
#include "tst_document.moc"
