// The views put a marker where the patient frame says. A CT stored with a flipped direction matrix (x and y
// reversed, as RAS-ordered scanners write it) holds a bright 5x5x5 voxel block at a known LPS position q, computed
// from the geometry alone. In each MPR the marker must appear at centre + ((q - cursor) . right, (q - cursor) . up)
// * pixels-per-mm, with right/up of the radiological convention (axial: right = patient left, up = anterior;
// coronal: right = left, up = superior; sagittal: right = anterior, up = superior), within 3 device pixels; in the
// anterior 3D view at centre + ((q - c).x, (q - c).z) * pixels-per-mm within 4 pixels. Screenshots are kept.
#include "GuiTestMain.h"
#include "MainWindow.h"
#include "MarkerPhantom.h"
#include "TestOutput.h"
#include "ViewLayout.h"
#include "vsim/study/Study.h"
#include "vsim/viz/SliceView.h"
#include "vsim/viz/VolumeView3D.h"

#include <QImage>
#include <QSignalSpy>

#include <filesystem>

using vsim::viz::SliceOrientation;

namespace {

using vsim::test::brightCentroid;
using vsim::test::Phantom;
using vsim::test::markerPhantom;

/// Checks that the white marker's centroid in `frame` lies within `tolerance` pixels of `expected`.
void verifyMarkerAt(const QImage& frame, int threshold, const QPointF& expected, double tolerance)
{
    int count = 0;
    const QPointF found = brightCentroid(frame, threshold, &count);
    QVERIFY2(count > 10, "the marker must be visible");
    QVERIFY2(std::hypot(found.x() - expected.x(), found.y() - expected.y()) <= tolerance,
             qPrintable(QString("marker at (%1, %2), expected (%3, %4)")
                            .arg(found.x()).arg(found.y()).arg(expected.x()).arg(expected.y())));
}

} // namespace

class TestOrientation : public QObject
{
    Q_OBJECT

    vsim::gui::MainWindow* m_window = nullptr;
    Phantom m_phantom;

private slots:
    void initTestCase()
    {
        m_phantom = markerPhantom();
        const std::filesystem::path bundle =
            std::filesystem::path(vsim::test::outputFolder("gui").toStdString()) / "orientation.vsim";
        std::filesystem::remove_all(bundle);
        vsim::study::Study study = vsim::study::Study::create(bundle, "orientation");
        study.addImage(m_phantom.image, "marker CT", {});
        study.save();

        m_window = new vsim::gui::MainWindow();
        m_window->resize(1200, 900);
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window));
        QSignalSpy idle(&m_window->tasks(), &vsim::gui::TaskRunner::idle);
        QVERIFY(m_window->openStudy(QString::fromStdString(bundle.string())));
        QVERIFY(idle.wait(30000));
        QVERIFY(m_window->document().hasStudy());
    }

    void cleanupTestCase()
    {
        delete m_window;
    }

    void markerAppearsWhereThePatientFrameSays_data()
    {
        QTest::addColumn<int>("orientation");
        QTest::addColumn<QString>("leftRightTopBottom");
        QTest::newRow("axial") << int(SliceOrientation::Axial) << "RLAP";
        QTest::newRow("coronal") << int(SliceOrientation::Coronal) << "RLSI";
        QTest::newRow("sagittal") << int(SliceOrientation::Sagittal) << "PASI";
    }

    void markerAppearsWhereThePatientFrameSays()
    {
        QFETCH(int, orientation);
        QFETCH(QString, leftRightTopBottom);
        vsim::viz::SliceView* view = m_window->views()->sliceView(SliceOrientation(orientation));
        QCOMPARE(view->edgeLabel(Qt::LeftEdge) + view->edgeLabel(Qt::RightEdge) + view->edgeLabel(Qt::TopEdge) +
                     view->edgeLabel(Qt::BottomEdge),
                 leftRightTopBottom);

        // Truth of the convention, written out here rather than taken from the view.
        Eigen::Vector3d right, up;
        Eigen::Vector3d cursor = m_phantom.image.geometry().indexToPatient({49.5, 44.5, 39.5}); // volume centre
        if (orientation == int(SliceOrientation::Axial))
            right = {1, 0, 0}, up = {0, -1, 0}, cursor.z() = m_phantom.marker.z();
        else if (orientation == int(SliceOrientation::Coronal))
            right = {1, 0, 0}, up = {0, 0, 1}, cursor.y() = m_phantom.marker.y();
        else
            right = {0, -1, 0}, up = {0, 0, 1}, cursor.x() = m_phantom.marker.x();
        view->setCursor(cursor);
        view->setFieldOfView(160.0);
        view->setWindowLevel(vsim::viz::kBonePreset);

        const QImage frame = view->grabFramebuffer();
        frame.save(vsim::test::outputFolder("gui") + "/mpr-" + QTest::currentDataTag() + ".png");
        const double pixelsPerMm = frame.height() / 160.0;
        const Eigen::Vector3d offset = m_phantom.marker - cursor;
        const QPointF expected(0.5 * frame.width() + offset.dot(right) * pixelsPerMm,
                               0.5 * frame.height() - offset.dot(up) * pixelsPerMm);
        verifyMarkerAt(frame, 200, expected, 3.0);
    }

    void markerAppearsInTheAnteriorVolumeRendering()
    {
        vsim::viz::VolumeView3D* view = m_window->views()->volumeView();
        view->showAnteriorView(160.0);
        const QImage frame = view->grabFramebuffer();
        frame.save(vsim::test::outputFolder("gui") + "/volume-anterior.png");
        const double pixelsPerMm = frame.height() / 160.0;
        const Eigen::Vector3d offset = m_phantom.marker - view->volumeCentre();
        const QPointF expected(0.5 * frame.width() + offset.x() * pixelsPerMm, 0.5 * frame.height() - offset.z() * pixelsPerMm);
        verifyMarkerAt(frame, 120, expected, 4.0);
    }
};

VSIM_GUI_TEST_MAIN(TestOrientation)
#include "tst_orientation.moc"
