// The slice views behave as radiologists' hands expect (issue 20, item 1), checked on pixels and view state: a
// click moves the crosshair and leaves the image where it is; one wheel notch or arrow key is one slice; Ctrl +
// wheel zooms about the mouse and the middle button pans; the corner overlays say the patient, the window/level,
// the slice and the HU under the mouse; the scale bar is as long on screen as it says; a thick-slab MIP shows a
// block the thin slice misses; linked views share the cursor and window/level, unlinked ones do not; a "go to"
// brings a point into view. The CT is the marker phantom (MarkerPhantom.h): air with a 3000 HU block at a known
// LPS position, anisotropic voxels and a flipped direction matrix. Screenshots are kept in test-output/gui. The
// suite runs twice: as is, and at a device pixel ratio of 2 (QT_SCALE_FACTOR=2, tst_gui_slice_views_hidpi).
#include "GuiTestMain.h"
#include "MarkerPhantom.h"
#include "TestOutput.h"
#include "ViewLayout.h"
#include "vsim/viz/SliceView.h"

#include <QWheelEvent>

using vsim::viz::SliceOrientation;
using vsim::viz::SliceView;

namespace {

constexpr int kWhite = 200; // the block at bone window: white; overlays are coloured, never white

QPointF blockCentre(SliceView* view, int* count)
{
    return vsim::test::brightCentroid(view->grabFramebuffer(), kWhite, count);
}

void wheel(SliceView* view, QPointF at, int delta, Qt::KeyboardModifiers modifiers = Qt::NoModifier)
{
    QWheelEvent event(at, view->mapToGlobal(at), QPoint(), QPoint(0, delta), Qt::NoButton, modifiers, Qt::NoScrollPhase, false);
    QApplication::sendEvent(view, &event);
}

void mouse(SliceView* view, QEvent::Type type, QPointF at, Qt::MouseButton button, Qt::MouseButtons buttons)
{
    QMouseEvent event(type, at, view->mapToGlobal(at), button, buttons, Qt::NoModifier);
    QApplication::sendEvent(view, &event);
}

/// A widget position (logical pixels) in the view's framebuffer (device pixels; 2 x under QT_SCALE_FACTOR=2).
QPointF device(SliceView* view, const QPointF& logical) { return logical * view->devicePixelRatioF(); }

bool near(const QPointF& a, const QPointF& b, double tolerance) { return std::hypot(a.x() - b.x(), a.y() - b.y()) <= tolerance; }

QString where(const QPointF& p) { return QString("(%1, %2)").arg(p.x(), 0, 'f', 2).arg(p.y(), 0, 'f', 2); }

/// Whether a pixel within `reach` pixels of `at` has the hue of a colour (RGB 0-1): its channels in the colour's
/// proportions within 0.15 and bright (lines are drawn antialiased, so their pixels are dimmed by coverage).
bool hasColour(const QImage& image, QPoint at, const Eigen::Vector3d& rgb, int reach = 2)
{
    for (int dy = -reach; dy <= reach; ++dy)
        for (int dx = -reach; dx <= reach; ++dx)
        {
            const QPoint p = at + QPoint(dx, dy);
            if (!image.rect().contains(p))
                continue;
            const QRgb pixel = image.pixel(p);
            const Eigen::Vector3d seen(qRed(pixel), qGreen(pixel), qBlue(pixel));
            if (seen.maxCoeff() > 100 && (seen / seen.maxCoeff() - rgb / rgb.maxCoeff()).cwiseAbs().maxCoeff() < 0.15)
                return true;
        }
    return false;
}

} // namespace

class TestSliceViews : public QObject
{
    Q_OBJECT

    vsim::gui::ViewLayout* m_layout = nullptr;
    vsim::test::Phantom m_phantom;

    SliceView* view(SliceOrientation orientation) const { return m_layout->sliceView(orientation); }

private slots:
    void initTestCase()
    {
        m_phantom = vsim::test::markerPhantom();
        m_layout = new vsim::gui::ViewLayout();
        m_layout->resize(1200, 900);
        m_layout->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_layout));
        m_layout->showImage(m_phantom.image);
        m_layout->applyWindowLevel(vsim::viz::kBonePreset);
    }

    void cleanupTestCase() { delete m_layout; }

    void init()
    {
        m_layout->setLinked(true);
        m_layout->setSlabThickness(0.0);
        m_layout->resetViews();
        m_layout->jumpTo(m_phantom.marker);
    }

    void clickMovesTheCrosshairNotTheImage()
    {
        SliceView* axial = view(SliceOrientation::Axial);
        int before = 0, after = 0;
        const QPointF blockBefore = blockCentre(axial, &before);
        QVERIFY2(before > 10, "the block must be visible in its slice");
        const Eigen::Vector3d centreBefore = axial->viewCentre();
        const QPointF click(0.3 * axial->width(), 0.7 * axial->height());
        mouse(axial, QEvent::MouseButtonPress, click, Qt::LeftButton, Qt::LeftButton);
        mouse(axial, QEvent::MouseButtonRelease, click, Qt::LeftButton, Qt::NoButton);
        QVERIFY((axial->cursor() - axial->patientAt(click)).norm() < 1e-9);
        QCOMPARE(axial->viewCentre(), centreBefore);
        const QImage frame = axial->grabFramebuffer();
        frame.save(vsim::test::outputFolder("gui") + "/slice-crosshair.png");
        const QPointF blockAfter = vsim::test::brightCentroid(frame, kWhite, &after);
        QVERIFY2(near(blockBefore, blockAfter, 0.5 * axial->devicePixelRatioF()), qPrintable(where(blockBefore) + " -> " + where(blockAfter)));
        // The crosshair crosses at the click: the horizontal line stands for the coronal plane (green), the vertical
        // one for the sagittal (yellow); the voxel under the cursor is left free.
        const double ratio = axial->devicePixelRatioF();
        const QPoint at = device(axial, click).toPoint(), along(int(40 * ratio), 0), across(0, int(40 * ratio));
        QVERIFY(hasColour(frame, at + along, vsim::viz::planeColour(SliceOrientation::Coronal)));
        QVERIFY(hasColour(frame, at - along, vsim::viz::planeColour(SliceOrientation::Coronal)));
        QVERIFY(hasColour(frame, at + across, vsim::viz::planeColour(SliceOrientation::Sagittal)));
        QVERIFY(!hasColour(frame, at + QPoint(int(4 * ratio), 0), vsim::viz::planeColour(SliceOrientation::Coronal), 1));
        // Linked: the coronal view's slice moved to the click, its image did not.
        SliceView* coronal = view(SliceOrientation::Coronal);
        QVERIFY((coronal->cursor() - axial->cursor()).norm() < 1e-9);
    }

    void wheelAndKeysStepOneSlice()
    {
        SliceView* axial = view(SliceOrientation::Axial);
        const QPointF middle(axial->width() / 2.0, axial->height() / 2.0);
        const Eigen::Vector3d start = axial->cursor();
        const int number = axial->sliceNumber();
        wheel(axial, middle, 120);
        QVERIFY(std::abs(std::abs(axial->cursor().z() - start.z()) - 1.5) < 1e-9); // the z spacing
        QCOMPARE(std::abs(axial->sliceNumber() - number), 1);
        wheel(axial, middle, 60); // half a notch (a touchpad): no step yet
        QCOMPARE(std::abs(axial->sliceNumber() - number), 1);
        wheel(axial, middle, -180);
        QCOMPARE(axial->sliceNumber(), number);
        QTest::keyClick(axial, Qt::Key_Up);
        QCOMPARE(std::abs(axial->sliceNumber() - number), 1);
        QTest::keyClick(axial, Qt::Key_Down);
        QTest::keyClick(axial, Qt::Key_PageDown);
        QCOMPARE(std::abs(axial->sliceNumber() - number), 10);
        QTest::keyClick(axial, Qt::Key_Home);
        const int end = axial->sliceNumber();
        QVERIFY(end == 1 || end == axial->sliceCount());
        QCOMPARE(axial->sliceCount(), 80);
        QTest::keyClick(axial, Qt::Key_End);
        QCOMPARE(axial->sliceNumber(), end == 1 ? 80 : 1);
        QVERIFY(axial->overlayText(Qt::BottomLeftCorner).startsWith(QString("Im %1/80").arg(axial->sliceNumber())));
        SliceView* sagittal = view(SliceOrientation::Sagittal);
        const double x = sagittal->cursor().x();
        wheel(sagittal, middle, 120);
        QVERIFY(std::abs(std::abs(sagittal->cursor().x() - x) - 0.8) < 1e-9); // the x spacing
    }

    void zoomAboutTheMouseAndPan()
    {
        SliceView* axial = view(SliceOrientation::Axial);
        int count = 0;
        const double ratio = axial->devicePixelRatioF();
        const QPointF block = blockCentre(axial, &count);         // device pixels
        const QPointF mouseAt = block / ratio + QPointF(60.0, -40.0); // logical
        const Eigen::Vector3d under = axial->patientAt(mouseAt);
        const double field = axial->fieldOfView();
        wheel(axial, mouseAt, 120, Qt::ControlModifier);
        QVERIFY(std::abs(axial->fieldOfView() - field / 1.1) < 1e-9);
        QVERIFY((axial->patientAt(mouseAt) - under).norm() < 1e-6);
        const QPointF zoomed = blockCentre(axial, &count);
        const QPointF expected = device(axial, mouseAt) + 1.1 * (block - device(axial, mouseAt));
        QVERIFY2(near(zoomed, expected, ratio), qPrintable(where(zoomed) + " expected " + where(expected)));

        const QPointF from(300, 300), to(340, 275);
        mouse(axial, QEvent::MouseButtonPress, from, Qt::MiddleButton, Qt::MiddleButton);
        mouse(axial, QEvent::MouseMove, to, Qt::NoButton, Qt::MiddleButton);
        mouse(axial, QEvent::MouseButtonRelease, to, Qt::MiddleButton, Qt::NoButton);
        const QPointF panned = blockCentre(axial, &count);
        QVERIFY2(near(panned, zoomed + device(axial, to - from), ratio), qPrintable(where(panned) + " from " + where(zoomed)));

        axial->setFocus();
        QTest::keyClick(axial, Qt::Key_R);
        QVERIFY(std::abs(axial->fieldOfView() - field) < 1e-9);
        QVERIFY(near(blockCentre(axial, &count), block, 0.5 * ratio));
    }

    void overlaysSayWhatIsShown()
    {
        SliceView* axial = view(SliceOrientation::Axial);
        m_layout->setPatientText("DOE JOHN  ID 12345\n20260101  CT angiography\nCTA arterial phase");
        QCOMPARE(axial->overlayText(Qt::TopLeftCorner), QString("DOE JOHN  ID 12345\n20260101  CT angiography\nCTA arterial phase"));
        QTest::keyClick(axial, Qt::Key_2);
        QCOMPARE(axial->windowLevel().window, vsim::viz::kSoftTissuePreset.window);
        QCOMPARE(view(SliceOrientation::Coronal)->windowLevel().level, vsim::viz::kSoftTissuePreset.level); // linked
        QCOMPARE(axial->overlayText(Qt::TopRightCorner), QString("W 400  L 40"));
        QTest::keyClick(axial, Qt::Key_3);
        QCOMPARE(axial->overlayText(Qt::TopRightCorner), QString("W 1800  L 400"));

        // The value under the mouse: the block's 3000 HU, air beside it.
        const QPointF overBlock = axial->widgetAt(m_phantom.marker);
        mouse(axial, QEvent::MouseMove, overBlock, Qt::NoButton, Qt::NoButton);
        QVERIFY2(axial->overlayText(Qt::BottomRightCorner).startsWith("3000 HU"), qPrintable(axial->overlayText(Qt::BottomRightCorner)));
        QCOMPARE(*axial->valueAt(overBlock + QPointF(80, 0)), -1000.0);
        QVERIFY(!axial->valueAt(QPointF(-1e4, 0)));

        // The scale bar: a round length, a tenth to a quarter of the view's width, drawn that long.
        const double mmPerPixel = axial->fieldOfView() / axial->height();
        const double barMm = axial->scaleBarMm();
        const double mantissa = barMm / std::pow(10.0, std::floor(std::log10(barMm)));
        QVERIFY(std::abs(mantissa - 1) < 1e-9 || std::abs(mantissa - 2) < 1e-9 || std::abs(mantissa - 5) < 1e-9);
        QVERIFY(barMm <= 0.25 * axial->width() * mmPerPixel && barMm > 0.1 * axial->width() * mmPerPixel);
        const QImage frame = axial->grabFramebuffer();
        frame.save(vsim::test::outputFolder("gui") + QString("/slice-overlays-x%1.png").arg(axial->devicePixelRatioF()));
        const double ratio = axial->devicePixelRatioF();
        const int left = int(std::lround(0.55 * frame.width())), length = int(std::lround(ratio * barMm / mmPerPixel));
        const int row = int(std::lround(0.92 * frame.height()));
        int drawn = 0;
        for (int x = left + 3; x < left + length - 3; ++x)
            for (int y = row - 2; y <= row + 2; ++y)
                if (hasColour(frame, {x, y}, {1.0, 0.85, 0.2}, 0))
                {
                    ++drawn;
                    break;
                }
        QVERIFY2(drawn >= length - 8, qPrintable(QString("%1 of %2 bar pixels").arg(drawn).arg(length - 6)));
        QVERIFY(!hasColour(frame, {left + length + int(6 * ratio), row}, {1.0, 0.85, 0.2}));
    }

    void thickSlabShowsWhatIsNear()
    {
        SliceView* axial = view(SliceOrientation::Axial);
        // 6 mm off the block's centre (the block spans +-3.75 mm): the thin slice misses it, a 20 mm slab holds it.
        axial->setCursor(m_phantom.marker + Eigen::Vector3d(0.0, 0.0, 6.0));
        int count = 0;
        blockCentre(axial, &count);
        QCOMPARE(count, 0);
        m_layout->setSlabThickness(20.0);
        const QImage frame = axial->grabFramebuffer();
        frame.save(vsim::test::outputFolder("gui") + "/slice-slab-mip.png");
        const QPointF found = vsim::test::brightCentroid(frame, kWhite, &count);
        QVERIFY(count > 10);
        QVERIFY(near(found, device(axial, axial->widgetAt(m_phantom.marker)), 3.0 * axial->devicePixelRatioF()));
        QVERIFY(axial->overlayText(Qt::TopRightCorner).contains("MIP slab 20.0 mm"));
    }

    void unlinkedViewsKeepTheirOwn()
    {
        SliceView* axial = view(SliceOrientation::Axial);
        SliceView* coronal = view(SliceOrientation::Coronal);
        m_layout->setLinked(false);
        const Eigen::Vector3d coronalCursor = coronal->cursor();
        const QPointF click(0.25 * axial->width(), 0.25 * axial->height());
        mouse(axial, QEvent::MouseButtonPress, click, Qt::LeftButton, Qt::LeftButton);
        mouse(axial, QEvent::MouseButtonRelease, click, Qt::LeftButton, Qt::NoButton);
        QCOMPARE(coronal->cursor(), coronalCursor);
        QTest::keyClick(axial, Qt::Key_4);
        QCOMPARE(axial->windowLevel().level, vsim::viz::kLungPreset.level);
        QVERIFY(coronal->windowLevel().level != vsim::viz::kLungPreset.level);
        m_layout->setLinked(true);
        mouse(axial, QEvent::MouseButtonPress, click + QPointF(5, 5), Qt::LeftButton, Qt::LeftButton);
        mouse(axial, QEvent::MouseButtonRelease, click + QPointF(5, 5), Qt::LeftButton, Qt::NoButton);
        QVERIFY((coronal->cursor() - axial->cursor()).norm() < 1e-9);
        m_layout->applyWindowLevel(vsim::viz::kBonePreset);
    }

    void goingToAPointBringsItIntoView()
    {
        SliceView* axial = view(SliceOrientation::Axial);
        axial->setFieldOfView(20.0); // zoomed in on the volume centre: the block is off screen
        int count = 0;
        blockCentre(axial, &count);
        QCOMPARE(count, 0);
        m_layout->jumpTo(m_phantom.marker);
        QCOMPARE(axial->cursor(), m_phantom.marker);
        const QPointF found = blockCentre(axial, &count);
        QVERIFY(count > 10);
        QVERIFY(near(found, device(axial, QPointF(axial->width() / 2.0, axial->height() / 2.0)), 3.0 * axial->devicePixelRatioF()));
    }
};

VSIM_GUI_TEST_MAIN(TestSliceViews)
#include "tst_slice_views.moc"
