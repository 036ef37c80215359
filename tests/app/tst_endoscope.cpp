// The virtual endoscope (issue 20, item 8; thesis 5.5.2) on the small patient-like AAA phantom after Segment
// and Skeleton & Centerlines: Vessels > Virtual Endoscope puts the camera inside the lumen (the wall all
// round it, nearer at the picture's edges than down the vessel at its centre, pink where lit), flying along
// the longest segment (play: 20 mm/s for a second moves it 20 mm; backwards moves it back; the slice views'
// cursor follows); focused on the wall at the centre the picture is sharp and clean, out of focus it blurs
// and grows noisy (the thesis's unfocused vision); a flow run's particles show as dark red blood cells in
// front of the camera. Pictures kept in test-output/gui-endoscope.
#include "DicomFixtures.h"
#include "EndoscopePanel.h"
#include "GuiTestMain.h"
#include "MainWindow.h"
#include "TestOutput.h"
#include "ViewLayout.h"
#include "vsim/viz/EndoscopeView.h"
#include "vsim/viz/SliceView.h"

#include <QComboBox>

#include <algorithm>
#include <cmath>

namespace fs = std::filesystem;
using namespace vsim;

namespace {

/// The standard deviation of a picture's green channel minus its 3 x 3 mean, over the central half: the fine
/// grain.
double grain(const QImage& picture)
{
    double squares = 0.0;
    int n = 0;
    for (int y = picture.height() / 4; y < 3 * picture.height() / 4; ++y)
        for (int x = picture.width() / 4; x < 3 * picture.width() / 4; ++x)
        {
            double mean = 0.0;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    mean += picture.pixelColor(x + dx, y + dy).green();
            const double d = picture.pixelColor(x, y).green() - mean / 9.0;
            squares += d * d;
            ++n;
        }
    return std::sqrt(squares / n);
}

int bloodCellPixels(const QImage& picture)
{
    int count = 0;
    for (int y = 0; y < picture.height(); ++y)
        for (int x = 0; x < picture.width(); ++x)
        {
            const QColor c = picture.pixelColor(x, y);
            count += c.red() > 60 && c.green() < 0.25 * c.red() && c.blue() < 0.3 * c.red();
        }
    return count;
}

} // namespace

class TestEndoscope : public QObject
{
    Q_OBJECT

private slots:
    void flyThroughTheLumen()
    {
        const fs::path folder = test::freshFolder("gui-endoscope", "aaa");
        test::writePhantomSeries(dicom::PhantomKind::Aaa, test::smallPhantomOptions(), folder);
        const QString output = test::outputFolder("gui-endoscope");
        gui::MainWindow window;
        window.resize(1400, 1000);
        window.show();
        QVERIFY(window.newStudy(
            QString::fromStdString((test::freshFolder("gui-endoscope", "study") / "e.vsim").string())));
        QVERIFY(!window.showEndoscope()); // no centerlines yet: refused with a message
        QVERIFY(test::runVesselSteps(window, folder.string()));
        if (window.showEndoscope() && window.tasks().isBusy())
            QVERIFY(test::waitForTask(window));
        gui::EndoscopePanel* panel = window.endoscope();
        QVERIFY(panel && panel->hasData() && panel->isVisible());
        viz::EndoscopeView* view = panel->view();
        QVERIFY(view->hasLumen());
        qInfo("segment %d: %.1f mm; endoscope %d x %d", panel->segment(), panel->frames().lengthMm(),
              view->width(), view->height());

        // Inside the lumen, looking along it: the wall is hit all round; nearer at the edges than down the
        // middle.
        const int segmentEdge = panel->segment();
        const double at30 = 0.3 * panel->frames().lengthMm();
        panel->setArc(at30);
        const QImage sharp = view->sharpPicture();
        const std::vector<float>& depth = view->depthMm();
        const int w = sharp.width(), h = sharp.height();
        auto depthAt = [&](int x, int y) { return depth[std::size_t(y) * std::size_t(w) + std::size_t(x)]; };
        int hit = 0;
        for (float d : depth)
            hit += std::isfinite(d);
        const double edgeDepth =
            0.25 * (depthAt(2, h / 2) + depthAt(w - 3, h / 2) + depthAt(w / 2, 2) + depthAt(w / 2, h - 3));
        qInfo("wall hit on %.1f %% of the pixels; depth at the edges %.1f mm, at the centre %.1f mm",
              100.0 * hit / depth.size(), edgeDepth, depthAt(w / 2, h / 2));
        QVERIFY(hit > 0.9 * double(depth.size()));
        QVERIFY(edgeDepth < 40.0 && depthAt(w / 2, h / 2) > 2.0 * edgeDepth);
        double red = 0.0, green = 0.0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                red += sharp.pixelColor(x, y).red(), green += sharp.pixelColor(x, y).green();
        QVERIFY2(red > 1.4 * green && red / (w * h) > 40.0, "the lit wall is pink");

        // Flying: 20 mm/s for one second, forwards then backwards; the slice views follow the camera.
        viz::SliceView* axial = window.views()->sliceView(viz::SliceOrientation::Axial);
        const double start = panel->arc();
        panel->setSpeed(20.0);
        panel->play();
        QVERIFY(panel->playing());
        panel->advance(1.0);
        QVERIFY2(std::abs(panel->arc() - start - 20.0) < 1e-6, qPrintable(QString::number(panel->arc())));
        const Eigen::Vector3d cursor = axial->cursor();
        const imaging::CenterlineFrames& frames = panel->frames();
        const double along = panel->arc() / frames.stepMm;
        const std::size_t i = std::size_t(along);
        const Eigen::Vector3d expected =
            frames.points[i] + (along - double(i)) * (frames.points[i + 1] - frames.points[i]);
        QVERIFY((cursor - expected).norm() < 1e-6);
        panel->setDirection(-1);
        panel->advance(0.5);
        QVERIFY(std::abs(panel->arc() - start - 10.0) < 1e-6);
        panel->pause();
        QVERIFY(!panel->playing());
        panel->setDirection(1);

        // Across the junction: a path from the inlet into a branch, flown through in one go.
        auto* choices = panel->findChild<QComboBox*>("endoscopeSegment");
        int pathChoice = -1;
        for (int index = 0; index < choices->count() && pathChoice < 0; ++index)
            if (choices->itemData(index).toList().size() >= 2)
                pathChoice = index;
        QVERIFY(pathChoice >= 0);
        choices->setCurrentIndex(pathChoice);
        QCOMPARE(panel->segment(), -1);
        const double pathLength = panel->frames().lengthMm();
        panel->setArc(0.0);
        panel->play();
        panel->setSpeed(50.0);
        for (int second = 0; second * 50.0 < pathLength + 50.0 && panel->playing(); ++second)
            panel->advance(1.0);
        qInfo("path %s: %.1f mm flown to its end", qPrintable(choices->itemText(pathChoice)), panel->arc());
        QVERIFY(!panel->playing() && std::abs(panel->arc() - pathLength) < 1e-9); // stops at the outlet
        view->picture();
        const auto wallHits = std::count_if(view->depthMm().begin(), view->depthMm().end(), [](float d) { return std::isfinite(d); });
        QVERIFY(wallHits > 0.5 * double(view->depthMm().size())); // near the outlet, still inside the lumen
        choices->setCurrentIndex(choices->findData(gui::VesselPath{segmentEdge + 1}));
        panel->setArc(at30);

        // Focus: on the wall at the centre, sharp and clean; out of focus, blurred and noisy.
        panel->setFocalLength(2.0);
        panel->focusOnCentre();
        const QImage focused = view->picture();
        const double focusedBlur = view->medianBlurPx(), focusedGrain = grain(focused);
        panel->setFocusDistance(2.0);
        const QImage unfocused = view->picture();
        const double unfocusedBlur = view->medianBlurPx(), unfocusedGrain = grain(unfocused);
        qInfo("focused: median blur %.2f px, grain %.1f; unfocused (2 mm): median blur %.2f px, grain %.1f",
              focusedBlur, focusedGrain, unfocusedBlur, unfocusedGrain);
        QVERIFY(unfocusedBlur > 3.0 * std::max(focusedBlur, 0.5));
        QVERIFY(unfocusedGrain > 2.0 * focusedGrain);
        QVERIFY(focused.save(output + "/endoscope-focused.png") &&
                unfocused.save(output + "/endoscope-unfocused.png"));

        // A flow run's particles: blood cells in the lumen ahead of the camera.
        const double at = panel->arc();
        std::vector<Eigen::Vector3d> cells;
        for (double s = at + 4.0; s < std::min(at + 30.0, frames.lengthMm()); s += 0.7)
            cells.push_back(frames.points[frames.indexAt(s)] +
                            0.3 * std::sin(s) * frames.normals[frames.indexAt(s)]);
        panel->setFocusDistance(15.0);
        const int before = bloodCellPixels(view->sharpPicture());
        panel->setParticles(cells);
        QCOMPARE(view->particleCount(), cells.size());
        const QImage withCells = view->sharpPicture();
        const int after = bloodCellPixels(withCells);
        qInfo("%zu blood cells: %d dark red pixels (%d without)", cells.size(), after, before);
        QVERIFY(after > before + 300);
        QVERIFY(view->picture().save(output + "/endoscope-blood-cells.png"));
        panel->setParticles({});
        QCOMPARE(bloodCellPixels(view->sharpPicture()), before);
    }
};

VSIM_GUI_TEST_MAIN(TestEndoscope)
#include "tst_endoscope.moc"
