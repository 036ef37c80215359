// Along the vessel (issue 20, item 3): on the small patient-like AAA phantom after Segment and Skeleton &
// Centerlines, the "3D + CPR" layout shows the longest segment's straightened CPR (one row per 0.5 mm of centerline),
// the cross-section perpendicular to it with the lumen caliper (cyan circle: the measured section's equivalent
// diameter, within 15 % of the picture's half-level disc) on a bright lumen, and the diameter plot;
// a click on the CPR or the plot and the wheel over the cross-section move along the centerline, and the MPR cursor
// follows; the rotation slider turns the CPR; a path across the junction joins its segments. Screenshot kept in test-output/gui-vessel-view.
#include "DicomFixtures.h"
#include "GuiTestMain.h"
#include "MainWindow.h"
#include "PixelChecks.h"
#include "TestOutput.h"
#include "VesselViewPanel.h"
#include "ViewCapture.h"
#include "ViewLayout.h"
#include "vsim/viz/PlaneImageView.h"
#include "vsim/viz/SliceView.h"

#include <QComboBox>
#include <QSlider>

namespace fs = std::filesystem;
using namespace vsim;

class TestVesselView : public QObject
{
    Q_OBJECT

private slots:
    void alongTheVessel()
    {
        const fs::path folder = test::freshFolder("gui-vessel-view", "aaa");
        test::writePhantomSeries(dicom::PhantomKind::Aaa, test::smallPhantomOptions(), folder);
        gui::MainWindow window;
        window.resize(1400, 900);
        window.show();
        QVERIFY(window.newStudy(QString::fromStdString((test::freshFolder("gui-vessel-view", "study") / "v.vsim").string())));
        QVERIFY(!window.showVesselView()); // no centerlines yet: refused with a message
        QVERIFY(test::runVesselSteps(window, folder.string()));
        QVERIFY(window.showVesselView());
        gui::ViewLayout* views = window.views();
        QCOMPARE(views->layoutMode(), gui::LayoutMode::VolumePlusCpr);
        gui::VesselViewPanel* panel = views->vesselPanel();
        QVERIFY(panel->isVisible() && !views->sliceView(viz::SliceOrientation::Axial)->isVisible());
        QApplication::processEvents();
        const imaging::CenterlineFrames& frames = panel->frames();
        qInfo("segment %d: %.1f mm of centerline, %zu CPR rows", panel->segment(), frames.lengthMm(), frames.points.size());
        QCOMPARE(panel->reformationView()->pictureHeight(), int(frames.points.size()));
        QVERIFY(frames.lengthMm() > 50.0);

        // The cross-section is centred on the lumen: bright in the middle, darker 20 mm away.
        viz::PlaneImageView* section = panel->crossSectionView();
        const auto value = [&](const imaging::PlaneImage& image, double xMm, double yMm) {
            return image.at(int(std::lround(xMm / image.pixelMm)), int(std::lround(yMm / image.pixelMm)));
        };
        viz::SliceView* axial = views->sliceView(viz::SliceOrientation::Axial);
        const imaging::PlaneImage picture = imaging::crossSection(axial->image(), frames, panel->arc(), 25.0, 0.25, panel->angle());
        qInfo("cross-section at %.1f mm: centre %.0f HU, 20 mm off %.0f HU", panel->arc(), value(picture, 25.0, 25.0), value(picture, 45.0, 25.0));
        QVERIFY(value(picture, 25.0, 25.0) > 150.0f && value(picture, 45.0, 25.0) < value(picture, 25.0, 25.0) - 100.0f);
        QVERIFY(test::cyanPixels(section->grabFramebuffer()) > 20); // the lumen caliper
        // The caliper is the measured section's equivalent diameter: the disc of the picture at half level (between
        // the lumen's centre and the tissue 20 mm off) has about that area.
        bool measured = false;
        const double caliper = panel->lumenDiameterAt(panel->arc(), &measured);
        const float half = 0.5f * (value(picture, 25.0, 25.0) + value(picture, 45.0, 25.0));
        double area = 0.0;
        for (float v : picture.values)
            area += v > half ? picture.pixelMm * picture.pixelMm : 0.0;
        const double discDiameter = 2.0 * std::sqrt(area / M_PI);
        qInfo("caliper %.1f mm (%s), half-level disc of the picture %.1f mm", caliper, measured ? "measured section" : "centerline radius", discDiameter);
        QVERIFY(measured);
        QVERIFY(std::abs(caliper / discDiameter - 1.0) < 0.15);
        QVERIFY((axial->cursor() - panel->position()).norm() < 1e-9); // the MPRs are there

        // A click on the CPR a quarter down moves there; the plot and the wheel too.
        viz::PlaneImageView* cpr = panel->reformationView();
        const double target = 0.25 * frames.lengthMm();
        QTest::mouseClick(cpr, Qt::LeftButton, {}, cpr->widgetAt(QPointF(25.0, target)).toPoint());
        QVERIFY2(std::abs(panel->arc() - target) < 1.0, qPrintable(QString::number(panel->arc())));
        QVERIFY((axial->cursor() - panel->position()).norm() < 1e-9);
        gui::LinePlot* plot = panel->diameterPlot();
        QTest::mouseClick(plot, Qt::LeftButton, {}, QPoint(int(std::lround(plot->widgetXOf(0.6 * frames.lengthMm()))), plot->height() / 2));
        QVERIFY(std::abs(panel->arc() - 0.6 * frames.lengthMm()) < 1.5);
        const double before = panel->arc();
        QWheelEvent wheel(QPointF(10, 10), section->mapToGlobal(QPointF(10, 10)), {}, QPoint(0, 240), Qt::NoButton, Qt::NoModifier,
                          Qt::NoScrollPhase, false);
        QApplication::sendEvent(section, &wheel);
        QVERIFY(std::abs(panel->arc() - before - 1.0) < 1e-9); // two notches of 0.5 mm

        // The rotation turns the reformation: another picture of the same rows.
        const imaging::PlaneImage straight = imaging::straightenedReformation(axial->image(), frames, 25.0, 0.0);
        panel->findChild<QSlider*>("vesselRotation")->setValue(90);
        QCOMPARE(panel->angle(), 90.0);
        const imaging::PlaneImage turned = imaging::straightenedReformation(axial->image(), frames, 25.0, 90.0);
        double difference = 0.0;
        for (std::size_t i = 0; i < straight.values.size(); ++i)
            difference += std::abs(straight.values[i] - turned.values[i]);
        QVERIFY(difference / double(straight.values.size()) > 5.0);
        captureWindow(panel).save(test::outputFolder("gui-vessel-view") + "/vessel-view.png");

        QVERIFY(!panel->outerCaliperAt(panel->arc())); // no sac measured: no outer-wall caliper

        // A path across the junction (the aorta into an iliac artery): one CPR along the segments joined, its length
        // theirs, its rows one per 0.5 mm, the plot its sections in order.
        auto* choices = panel->findChild<QComboBox*>("vesselSegment");
        int pathChoice = -1;
        for (int index = 0; index < choices->count() && pathChoice < 0; ++index)
            if (choices->itemData(index).toList().size() >= 2)
                pathChoice = index;
        QVERIFY2(pathChoice >= 0, "no path across a junction offered");
        choices->setCurrentIndex(pathChoice);
        const gui::VesselPath path = choices->itemData(pathChoice).toList();
        QCOMPARE(panel->path(), path);
        QCOMPARE(panel->segment(), -1);
        double joined = 0.0;
        for (const QVariant& step : path)
            joined += window.document().study().loadSkeleton(window.document().study().newestArtifact(
                study::ArtifactKind::Skeleton, "centerline")).edges[std::size_t(std::abs(step.toInt()) - 1)].length();
        qInfo("path %s: %.1f mm of frames for %.1f mm of segments", qPrintable(choices->itemText(pathChoice)),
              panel->frames().lengthMm(), joined);
        QVERIFY(std::abs(panel->frames().lengthMm() - joined) < 2.0);
        QCOMPARE(panel->reformationView()->pictureHeight(), int(panel->frames().points.size()));
        for (std::size_t i = 1; i < panel->frames().points.size(); ++i) // no jump at the junction
            QVERIFY((panel->frames().points[i] - panel->frames().points[i - 1]).norm() < 0.6);
    }
};

VSIM_GUI_TEST_MAIN(TestVesselView)
#include "tst_vessel_view.moc"
