// The wall steps from the workstation: on the imported small aaa phantom, Segment, Skeleton & Centerlines, then
// Build Wall Mesh and Wall Stress at Blood Pressure in the background: the wall and the stress frame are added
// (undoable, with provenance and metrics), the 3D view shows the stress with its legend; without a wall the step
// says what to do first. The interactive protocol drags a point of the wall towards the cursor; its frame rate on
// a 20k-tet wall is measured.

#include "DicomFixtures.h"
#include "GuiTestMain.h"
#include "InteractiveWall.h"
#include "LinePlot.h"
#include "MainWindow.h"
#include "RunPlayer.h"
#include "TubeWall.h"
#include "ViewCapture.h"
#include "ViewLayout.h"
#include "vsim/core/Units.h"
#include "vsim/viz/SliceView.h"
#include "vsim/viz/VolumeView3D.h"

#include <QDir>
#include <QDockWidget>
#include <QSettings>
#include <QSlider>

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTest>

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
        QVERIFY(vsim::test::runVesselSteps(window, folder.string()));

        window.wallMeshParameters().set("target_vertices", 1500);
        // The thrombus layer needs the AAA sac, which this analytic phantom (no fat around the aorta) cannot give:
        // refused with the reason, nothing added.
        const std::size_t artifactsBefore = window.document().study().artifacts().size();
        window.wallMeshParameters().set("thrombus_layer", 1);
        QVERIFY(!window.buildWallMesh());
        QCOMPARE(window.document().study().artifacts().size(), artifactsBefore);
        window.wallMeshParameters().set("thrombus_layer", 0);
        QVERIFY(window.buildWallMesh());
        QVERIFY(vsim::test::waitForTask(window));
        QCOMPARE(failed.count(), 0);
        const study::Artifact wall = window.document().study().artifacts().back();
        QCOMPARE(wall.kind, study::ArtifactKind::TetMesh);
        QCOMPARE(wall.provenance.command, std::string("mesh wall"));
        // Built from the lumen the centerlines were traced from (the segmentation's label).
        const std::string centerlinesId = window.document().study().newestArtifact(study::ArtifactKind::Skeleton, "centerline");
        QCOMPARE(wall.provenance.inputs.front(), window.document().study().artifact(centerlinesId).provenance.inputs.back());
        QCOMPARE(wall.attributes.at("inverted_elements"), std::string("0"));

        QVERIFY(window.simulateWall("physiological"));
        // The converged quadratic wall takes about 90 s on 2 cores alone; the default 120 s wait ran out in a
        // suite beside other work (2026-12-05): 300 s, the solve's own figures are checked below.
        QVERIFY(vsim::test::waitForTask(window, 300000));
        QCOMPARE(failed.count(), 0);
        const study::Artifact stress = window.document().study().artifacts().back();
        QCOMPARE(stress.provenance.command, std::string("simulate fem"));
        QCOMPARE(stress.provenance.parameters.at("protocol"), std::string("physiological"));
        const double peak = std::stod(stress.attributes.at("peak_von_mises_kpa"));
        qInfo("GUI wall: %s elements under 5 deg, peak von Mises %.1f kPa, force residual %s; no rupture index without "
              "the patient's sex and family history: %s", wall.attributes.at("elements_under_5_deg").c_str(), peak,
              stress.attributes.at("run_force_residual").c_str(), stress.attributes.at("rupture_index_computed").c_str());
        QVERIFY(peak > 0.0);
        QVERIFY(!stress.attributes.count("peak_rupture_index"));
        // Issue 14: the legend says when the run's solves did not converge; issue 16: the Newton equilibrium does.
        const bool converged = stress.attributes.at("run_converged") == "1";
        QVERIFY(converged);
        QCOMPARE(window.views()->volumeView()->legendTitle(),
                 converged ? QString("von Mises (kPa)") : QString("von Mises (kPa), NOT CONVERGED"));
        // Issue 17: the whole run is kept beside the stress (a Run artifact: every frame, the same status).
        const study::Artifact& runArtifact = window.document().study().artifact(stress.attributes.at("run_artifact"));
        QCOMPARE(runArtifact.kind, study::ArtifactKind::Run);
        const SolverRun run = window.document().study().loadRun(runArtifact.id);
        QVERIFY(run.frames.size() >= 2);
        QCOMPARE(run.status.converged(), converged);
        QCOMPARE(run.axis.unit, std::string("kPa")); // the default quadratic wall's load increments (wall_model 1)
        QCOMPARE(stress.provenance.parameters.at("wall_model"), std::string("1"));
        for (std::size_t f = 1; f < run.frames.size(); ++f)
            QVERIFY(run.frames[f].position > run.frames[f - 1].position);
        // The one time player on that run: every kept frame, the legend naming the field and the frame, play with
        // loop moves on, the run's range fixed; closing it brings the stress picture back.
        QVERIFY(window.openRunPlayer(runArtifact.id));
        QVERIFY(vsim::test::waitForTask(window));
        gui::RunPlayer* player = window.runPlayer();
        QVERIFY(player);
        QCOMPARE(player->frameCount(), int(run.frames.size()));
        QCOMPARE(player->field(), QString("von_mises_kpa"));
        QVERIFY2(window.views()->volumeView()->legendTitle().startsWith("von Mises stress (kPa), frame 1 / "),
                 qPrintable(window.views()->volumeView()->legendTitle()));
        const int middle = player->frameCount() / 2;
        player->setFrame(middle);
        // Every view follows the frame: the slices through a point inside the wall show its cut, coloured by the
        // field; the plot's cursor sits on the frame's pressure or time, and a click in the plot goes to a frame.
        const TetMesh middleWall = std::get<TetMesh>(window.document().study().loadRunFrame(runArtifact.id, std::size_t(middle)).data);
        Eigen::Vector3d insideWall = Eigen::Vector3d::Zero();
        for (int corner : middleWall.tets.front())
            insideWall += 0.25 * middleWall.points[std::size_t(corner)];
        window.views()->sliceView(viz::SliceOrientation::Axial)->setCursor(insideWall);
        for (auto orientation : {viz::SliceOrientation::Axial, viz::SliceOrientation::Coronal, viz::SliceOrientation::Sagittal})
            QVERIFY2(window.views()->sliceView(orientation)->fieldCellsShown() > 0, "a slice through the wall shows no cut");
        gui::LinePlot* plot = window.runPlot();
        QVERIFY(plot);
        QCOMPARE(plot->curves().size(), std::size_t(2)); // peak and median per frame
        QCOMPARE(plot->curves().front().x.size(), run.frames.size());
        for (std::size_t f = 0; f < run.frames.size(); ++f)
            QVERIFY(plot->curves()[0].y[f] >= plot->curves()[1].y[f]);
        QCOMPARE(*plot->cursor(), run.frames[std::size_t(middle)].position);
        QTest::mouseClick(plot, Qt::LeftButton, {}, QPoint(int(std::lround(plot->widgetXOf(run.frames[1].position))), plot->height() / 2));
        QCOMPARE(player->frame(), 1);
        player->setFrame(middle);
        window.grab().save(QString::fromStdString(
            (std::filesystem::path(vsim::test::outputFolder("gui").toStdString()) / "run-player-wall-mid.png").string()));
        player->setLoop(true);
        player->setSpeed(4.0);
        const int from = player->frame();
        player->play();
        QTRY_VERIFY_WITH_TIMEOUT(player->frame() != from, 3000);
        player->pause();
        QVERIFY(!player->isPlaying());
        // A movie of the played run (View > Capture): one PNG per frame of the 3D view, the frame played before
        // restored; the first and last frames differ (the stress grows with the pressure).
        QSettings().setValue("capture/folder", vsim::test::outputFolder("gui-wall-movie"));
        const int played = player->frame();
        const gui::MovieResult movie = window.saveMovie(gui::MainWindow::MovieSource::PlayedRun);
        QCOMPARE(movie.frames, player->frameCount());
        QCOMPARE(player->frame(), played);
        const QDir frames(movie.folder);
        const QImage first(frames.filePath("frame-0001.png"));
        const QImage last(frames.filePath(QString("frame-%1.png").arg(player->frameCount(), 4, 10, QChar('0'))));
        QVERIFY(!first.isNull() && first.size() == last.size() && first != last);
        player->setFrame(player->frameCount() - 1);
        QVERIFY(window.views()->volumeView()->legendTitle().contains(
            QString("frame %1 / %1").arg(player->frameCount())));
        window.findChild<QDockWidget*>("runPlayerDock")->close();
        QTRY_COMPARE(window.views()->volumeView()->legendTitle(), QString("von Mises (kPa)"));
        QCOMPARE(window.views()->sliceView(viz::SliceOrientation::Axial)->fieldCellsShown(), 0LL);

        const std::size_t before = window.document().study().artifacts().size();
        window.document().undoStack()->undo(); // the stress and its run go together
        QCOMPARE(window.document().study().artifacts().size(), before - 2);
        QVERIFY(!window.document().study().hasArtifact(runArtifact.id));

        // The interactive protocol: pressure from the slider, a point of the wall dragged 3 mm outward.
        QVERIFY(window.startInteractiveWall());
        gui::InteractiveWall* wall3d = window.interactiveWall();
        QVERIFY(wall3d);
        auto* slider = window.findChild<QSlider*>("interactivePressure");
        QVERIFY(slider);
        slider->setValue(120);
        QCOMPARE(wall3d->simulation().pressure(), units::mmHgToPa(120.0));
        const TriangleMesh& surface = wall3d->lastSurface();
        const Eigen::Vector3d grabbed = surface.points[surface.triangles.front()[0]];
        wall3d->grab(grabbed);
        const Eigen::Vector3d target = grabbed + Eigen::Vector3d(3.0, 0.0, 0.0);
        wall3d->dragTo(target);
        const double startGap = (grabbed - target).norm();
        for (int frame = 0; frame < 30; ++frame)
            wall3d->advance();
        double gap = 1e300;
        for (const Eigen::Vector3d& point : wall3d->lastSurface().points)
            gap = std::min(gap, (point - target).norm());
        qInfo("interactive: the wall point closest to the drag target is %.2f mm from it (%.2f mm at the grab)", gap,
              startGap);
        QVERIFY(gap < startGap - 0.1);
        window.stopInteractiveWall();
        QVERIFY(!window.interactiveWall());
    }

    // The interactive protocol's frame rate on a 20k-tet wall (a closed tube, 19,968 tets), dragging: steps and
    // drawing together, this machine's CPU and Xvfb's software OpenGL. Printed for RESULTS.md.
    void interactiveFrameRateAt20kTets()
    {
        const TetMesh wall = test::tubeWall({1, 128, 26});
        gui::MainWindow window;
        window.resize(1200, 900);
        window.show();
        gui::InteractiveWall interactive(wall, sim::fem::ElasticMaterial{}, sim::fem::BackwardEulerSettings{},
                                         window.views()->volumeView());
        interactive.setPressureMmHg(120.0);
        interactive.grab(Eigen::Vector3d(11.5, 0.0, 50.0));
        interactive.dragTo(Eigen::Vector3d(16.5, 0.0, 50.0));
        QElapsedTimer clock;
        clock.start();
        int frames = 0;
        while (clock.elapsed() < 3000)
        {
            interactive.advance();
            window.views()->volumeView()->repaint();
            ++frames;
        }
        const double fps = 1000.0 * frames / double(clock.elapsed());
        qInfo("interactive wall, %zu tets, dragging: %.1f frames/s over %d frames (step + colours + render)",
              wall.tets.size(), fps, frames);
        QVERIFY(frames > 3);
    }
};

VSIM_GUI_TEST_MAIN(TestWall)
#include "tst_wall.moc"
