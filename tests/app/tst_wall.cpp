// The wall steps from the workstation: on the imported small aaa phantom, Segment, Skeleton & Centerlines, then
// Build Wall Mesh and Wall Stress at Blood Pressure in the background: the wall and the stress frame are added
// (undoable, with provenance and metrics), the 3D view shows the stress with its legend; without a wall the step
// says what to do first.

#include "DicomFixtures.h"
#include "GuiTestMain.h"
#include "MainWindow.h"
#include "ViewLayout.h"
#include "vsim/viz/VolumeView3D.h"

#include <QSignalSpy>

namespace fs = std::filesystem;
using namespace vsim;

class TestWall : public QObject
{
    Q_OBJECT

private slots:
    void wallMeshAndStress()
    {
        const fs::path folder = test::freshFolder("gui-wall", "aaa");
        test::writePhantomSeries(dicom::PhantomKind::Aaa, test::smallPhantomOptions(), folder);
        gui::MainWindow window;
        window.resize(1200, 900);
        window.show();
        const fs::path bundle = test::freshFolder("gui-wall", "study") / "wall.vsim";
        QVERIFY(window.newStudy(QString::fromStdString(bundle.string())));
        QSignalSpy failed(&window.tasks(), &gui::TaskRunner::failed);
        QVERIFY(!window.simulateWall("physiological")); // no wall yet: says so, adds nothing
        QVERIFY(window.importDicom(QString::fromStdString(folder.string())));
        QVERIFY(vsim::test::waitForTask(window));
        QVERIFY(window.segmentVessels());
        QVERIFY(vsim::test::waitForTask(window));
        QVERIFY(window.extractSkeletonAndCenterlines());
        QVERIFY(vsim::test::waitForTask(window));

        window.wallMeshParameters().set("target_vertices", 1500);
        QVERIFY(window.buildWallMesh());
        QVERIFY(vsim::test::waitForTask(window));
        QCOMPARE(failed.count(), 0);
        const study::Artifact wall = window.document().study().artifacts().back();
        QCOMPARE(wall.kind, study::ArtifactKind::TetMesh);
        QCOMPARE(wall.provenance.command, std::string("mesh wall"));
        QCOMPARE(wall.attributes.at("inverted_elements"), std::string("0"));

        window.femParameters().set("settle_time_s", 0.2); // 20 pseudo-time steps keep the test short
        QVERIFY(window.simulateWall("physiological"));
        QVERIFY(vsim::test::waitForTask(window));
        QCOMPARE(failed.count(), 0);
        const study::Artifact stress = window.document().study().artifacts().back();
        QCOMPARE(stress.provenance.command, std::string("simulate fem"));
        QCOMPARE(stress.provenance.parameters.at("protocol"), std::string("physiological"));
        const double peak = std::stod(stress.attributes.at("peak_von_mises_kpa"));
        qInfo("GUI wall: %s elements under 5 deg, peak von Mises %.1f kPa, peak rupture index %s",
              wall.attributes.at("elements_under_5_deg").c_str(), peak, stress.attributes.at("peak_rupture_index").c_str());
        QVERIFY(peak > 0.0);
        QCOMPARE(window.views()->volumeView()->legendTitle(), QString("von Mises (kPa)"));
        const std::size_t before = window.document().study().artifacts().size();
        window.document().undoStack()->undo();
        QCOMPARE(window.document().study().artifacts().size(), before - 1);
    }
};

VSIM_GUI_TEST_MAIN(TestWall)
#include "tst_wall.moc"
