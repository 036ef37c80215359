// The vessel steps from the GUI: segment the imported phantom in the background (label undoable, lumen surface in
// the 3D view), then skeleton and centerlines as one undo step; without an image the step says what to do first.
#include "DicomFixtures.h"
#include "GuiTestMain.h"
#include "MainWindow.h"
#include "ViewLayout.h"
#include "vsim/viz/SliceView.h"
#include "vsim/imaging/VesselSegmentation.h"

#include <QSignalSpy>
#include <QTableWidget>

namespace fs = std::filesystem;
using namespace vsim;

class TestVessels : public QObject
{
    Q_OBJECT

private slots:
    void segmentSkeletonCenterlines()
    {
        const fs::path folder = test::freshFolder("gui-vessels", "aaa");
        const auto phantom = test::writePhantomSeries(dicom::PhantomKind::Aaa, test::smallPhantomOptions(), folder);
        gui::MainWindow window;
        window.resize(1200, 900);
        window.show();
        const fs::path bundle = test::freshFolder("gui-vessels", "study") / "vessels.vsim";
        QVERIFY(window.newStudy(QString::fromStdString(bundle.string())));
        QVERIFY(window.importDicom(QString::fromStdString(folder.string())));
        QVERIFY(vsim::test::waitForTask(window));

        QVERIFY(window.segmentVessels());
        QVERIFY(vsim::test::waitForTask(window));
        const study::Study& study = window.document().study();
        QCOMPARE(study.artifacts().size(), std::size_t(2));
        const study::Artifact& label = study.artifacts().back();
        QCOMPARE(label.kind, study::ArtifactKind::Label);
        QCOMPARE(label.provenance.command, std::string("segment"));
        const LabelVolume truth = dicom::renderPhantomLabels(phantom.model, phantom.geometry);
        const double dice = imaging::diceCoefficient(study.loadLabel(label.id), 1, truth, dicom::label::kVesselLumen);
        qInfo("GUI segmentation of the 3.5 mm aaa: Dice %.3f", dice);
        QVERIFY(dice > 0.85); // 3.5 mm voxels: the small renal branches are a few voxels wide

        QVERIFY(window.extractSkeletonAndCenterlines());
        QVERIFY(vsim::test::waitForTask(window));
        QCOMPARE(window.document().study().artifacts().size(), std::size_t(4));
        QCOMPARE(window.document().study().artifacts().back().name, std::string("Centerlines"));
        // The measurement table: the maximum-diameter row first (the aaa's 55 mm, coarse 3.5 mm voxels here), and
        // a click takes the MPR cursor into the aneurysm.
        QTableWidget* table = window.measurementTable();
        QVERIFY(table->rowCount() >= 2);
        const double maximum = table->item(0, 7)->text().toDouble();
        qInfo("measurement table: %d rows, maximum diameter %.2f mm", table->rowCount(), maximum);
        QVERIFY(std::abs(maximum - 55.0) < 4.0);
        emit table->cellClicked(0, 0);
        const Eigen::Vector3d cursor = window.views()->sliceView(viz::SliceOrientation::Axial)->cursor();
        QVERIFY(std::abs(cursor.z() - phantom.model.measures.at("aneurysm_centre_z_mm")) < 25.0);
        window.grab().save(QString::fromStdString((fs::path(test::outputFolder("gui").toStdString()) / "vessels.png").string()));
        window.document().undoStack()->undo(); // skeleton and centerlines go together
        QCOMPARE(window.document().study().artifacts().size(), std::size_t(2));
        window.document().undoStack()->undo();
        QCOMPARE(window.document().study().artifacts().size(), std::size_t(1));
    }

    void seedFromTheCursor()
    {
        const fs::path folder = test::freshFolder("gui-vessels", "seeded");
        test::writePhantomSeries(dicom::PhantomKind::Aaa, test::smallPhantomOptions(), folder);
        gui::MainWindow window;
        const fs::path bundle = test::freshFolder("gui-vessels", "seeded-study") / "seeded.vsim";
        QVERIFY(window.newStudy(QString::fromStdString(bundle.string())));
        QVERIFY(window.importDicom(QString::fromStdString(folder.string())));
        QVERIFY(vsim::test::waitForTask(window));
        // The cursor on the aorta above the aneurysm, as a click in an MPR view puts it.
        const Eigen::Vector3d aorta = dicom::kPhantomCentre + Eigen::Vector3d(0, -5, 100);
        window.views()->sliceView(viz::SliceOrientation::Axial)->setCursor(aorta);
        QVERIFY(window.segmentVessels(window.views()->sliceView(viz::SliceOrientation::Axial)->cursor()));
        QVERIFY(vsim::test::waitForTask(window));
        const study::Artifact& label = window.document().study().artifacts().back();
        QCOMPARE(label.provenance.parameters.at("seed_found_automatically"), std::string("no"));
        // A seed in the spine is refused with a message and adds nothing.
        QSignalSpy failed(&window.tasks(), &gui::TaskRunner::failed);
        QVERIFY(window.segmentVessels(dicom::kPhantomCentre + Eigen::Vector3d(0, 45, 0)));
        QVERIFY(vsim::test::waitForTask(window));
        QCOMPARE(failed.count(), 1);
        QVERIFY(failed.front().at(1).toString().contains("not in a contrast-filled vessel"));
        QCOMPARE(window.document().study().artifacts().size(), std::size_t(2));
    }

    void withoutImageSaysWhatToDo()
    {
        gui::MainWindow window;
        const fs::path bundle = test::freshFolder("gui-vessels", "empty") / "empty.vsim";
        QVERIFY(window.newStudy(QString::fromStdString(bundle.string())));
        QVERIFY(!window.segmentVessels());
        QVERIFY(!window.extractSkeletonAndCenterlines());
        QCOMPARE(window.document().study().artifacts().size(), std::size_t(0));
    }
};

VSIM_GUI_TEST_MAIN(TestVessels)
#include "tst_vessels.moc"
