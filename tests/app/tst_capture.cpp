// Layouts and capture (issue 20, item 4): the four layouts show the views they name at the sizes they promise; a
// screenshot of a view is its framebuffer, never overwrites an earlier one; a screenshot of the window holds the VTK
// views' pixels at their places (QWidget::grab alone shows them blank under Xvfb); a rotation movie turns the 3D
// view once around (72 PNG frames, the camera back where it was) and a cancelled movie leaves nothing behind.
// Marker phantom (MarkerPhantom.h); the pictures stay in test-output/gui-capture.
#include "GuiTestMain.h"
#include "MainWindow.h"
#include "MarkerPhantom.h"
#include "TestOutput.h"
#include "ViewCapture.h"
#include "ViewLayout.h"
#include "vsim/study/Study.h"
#include "vsim/viz/SliceView.h"
#include "vsim/viz/VolumeView3D.h"

#include <QDir>
#include <QSettings>

#include <filesystem>

using namespace vsim;
using viz::SliceOrientation;

namespace {

/// Mean absolute difference (0-255) between two pictures of the same size, over the three channels.
double meanDifference(const QImage& a, const QImage& b)
{
    double sum = 0.0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
        {
            const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
            sum += std::abs(qRed(p) - qRed(q)) + std::abs(qGreen(p) - qGreen(q)) + std::abs(qBlue(p) - qBlue(q));
        }
    return sum / (3.0 * a.width() * a.height());
}

} // namespace

class TestCapture : public QObject
{
    Q_OBJECT

    gui::MainWindow* m_window = nullptr;
    QString m_folder;

private slots:
    void initTestCase()
    {
        m_folder = test::outputFolder("gui-capture") + "/captures";
        QDir(m_folder).removeRecursively(); // this suite's own output from an earlier run
        QDir().mkpath(m_folder);
        QSettings().setValue("capture/folder", m_folder);
        const std::filesystem::path bundle = std::filesystem::path(test::outputFolder("gui-capture").toStdString()) / "capture.vsim";
        std::filesystem::remove_all(bundle);
        study::Study study = study::Study::create(bundle, "capture");
        study.addImage(test::markerPhantom().image, "marker CT", {});
        study.save();
        m_window = new gui::MainWindow();
        m_window->resize(1200, 900);
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window));
        QSignalSpy idle(&m_window->tasks(), &gui::TaskRunner::idle);
        QVERIFY(m_window->openStudy(QString::fromStdString(bundle.string())));
        QVERIFY(idle.wait(30000));
        m_window->views()->applyWindowLevel(viz::kBonePreset);
        m_window->views()->jumpTo(test::markerPhantom().marker);
    }

    void cleanupTestCase() { delete m_window; }

    void layoutsShowWhatTheyName()
    {
        gui::ViewLayout* views = m_window->views();
        viz::SliceView* axial = views->sliceView(SliceOrientation::Axial);
        viz::SliceView* coronal = views->sliceView(SliceOrientation::Coronal);
        viz::SliceView* sagittal = views->sliceView(SliceOrientation::Sagittal);
        QWidget* volume = views->volumeView();

        views->setMainView(coronal);
        views->setLayoutMode(gui::LayoutMode::OneByOne);
        QApplication::processEvents();
        QVERIFY(coronal->isVisible() && !axial->isVisible() && !volume->isVisible());
        QVERIFY(coronal->width() >= views->width() - 4 && coronal->height() >= views->height() - 4);

        views->setLayoutMode(gui::LayoutMode::OneByThree);
        QApplication::processEvents();
        QVERIFY(axial->isVisible() && coronal->isVisible() && sagittal->isVisible() && !volume->isVisible());
        QVERIFY(std::abs(axial->width() - sagittal->width()) <= 2 && axial->y() == sagittal->y());

        views->setLayoutMode(gui::LayoutMode::VolumePlusSlices);
        QApplication::processEvents();
        QVERIFY(volume->isVisible() && axial->isVisible());
        QVERIFY(std::abs(volume->width() - 2 * axial->width()) <= 4);
        QVERIFY(volume->height() >= 3 * axial->height());

        views->setLayoutMode(gui::LayoutMode::TwoByTwo);
        QApplication::processEvents();
        QVERIFY(axial->isVisible() && coronal->isVisible() && sagittal->isVisible() && volume->isVisible());
        QVERIFY(axial->x() < volume->x() && axial->y() < coronal->y());
    }

    void screenshotsOfAViewAndTheWindow()
    {
        viz::SliceView* axial = m_window->views()->sliceView(SliceOrientation::Axial);
        const QString first = m_window->saveScreenshot(axial);
        const QString second = m_window->saveScreenshot(axial);
        QVERIFY(!first.isEmpty() && !second.isEmpty() && first != second); // never overwritten
        const QImage shot(first);
        const QImage framebuffer = axial->grabFramebuffer();
        QCOMPARE(shot.size(), framebuffer.size());
        QVERIFY(meanDifference(shot, framebuffer) < 1.0);
        int white = 0;
        test::brightCentroid(shot, 200, &white);
        QVERIFY2(white > 10, "the marker block is in the picture");

        const QString windowFile = m_window->saveScreenshot(nullptr);
        const QImage window(windowFile);
        QVERIFY(!window.isNull());
        const qreal ratio = framebuffer.devicePixelRatio();
        const QPoint at = axial->mapTo(m_window, QPoint(0, 0)) * ratio;
        const QImage crop = window.copy(QRect(at, framebuffer.size()));
        const double difference = meanDifference(crop, framebuffer);
        qInfo("window screenshot %d x %d: the axial view's place differs from its framebuffer by %.2f (0-255)",
              window.width(), window.height(), difference);
        QVERIFY(difference < 2.0);
    }

    void rotationMovieTurnsOnceAround()
    {
        viz::VolumeView3D* volume = m_window->views()->volumeView();
        volume->showAnteriorView(160.0);
        const viz::CameraState before = volume->cameraState();
        const gui::MovieResult movie = m_window->saveMovie(gui::MainWindow::MovieSource::Rotation);
        QCOMPARE(movie.frames, 72);
        QVERIFY(!movie.cancelled);
        QVERIFY(movie.mp4.isEmpty() != movie.note.isEmpty()); // an MP4, or the reason there is none
        qInfo("rotation movie: %d frames in %s; %s", movie.frames, qPrintable(movie.folder),
              qPrintable(movie.mp4.isEmpty() ? movie.note : movie.mp4));
        const QDir folder(movie.folder);
        QCOMPARE(folder.entryList({"frame-*.png"}).size(), 72);
        const QImage first(folder.filePath("frame-0001.png")), quarter(folder.filePath("frame-0019.png"));
        // Turned 90 degrees about the vertical: the block, off the volume's centre, moves across the picture.
        int seen = 0, seenQuarter = 0;
        const QPointF blockFirst = test::brightCentroid(first, 200, &seen), blockQuarter = test::brightCentroid(quarter, 200, &seenQuarter);
        qInfo("the block at (%.1f, %.1f) in frame 1, (%.1f, %.1f) in frame 19", blockFirst.x(), blockFirst.y(), blockQuarter.x(), blockQuarter.y());
        QVERIFY(seen > 4 && seenQuarter > 4);
        QVERIFY(std::abs(blockFirst.x() - blockQuarter.x()) > 10.0 && std::abs(blockFirst.y() - blockQuarter.y()) < 3.0);
        const viz::CameraState after = volume->cameraState();
        for (int a = 0; a < 3; ++a)
            QVERIFY(std::abs(after.position[std::size_t(a)] - before.position[std::size_t(a)]) < 1e-6 * (1.0 + std::abs(before.position[std::size_t(a)])));
    }

    void cancelledMovieLeavesNothing()
    {
        int made = 0;
        const gui::MovieResult movie = gui::writeMovie(
            m_folder, "cancelled", 20, [&](int) { ++made; return QImage(16, 16, QImage::Format_RGB32); }, 24.0,
            [](int i) { return i < 5; });
        QVERIFY(movie.cancelled);
        QCOMPARE(made, 5);
        QVERIFY(!QFileInfo::exists(movie.folder));
    }
};

VSIM_GUI_TEST_MAIN(TestCapture)
#include "tst_capture.moc"
