// Layouts and capture (View > Layout, View > Capture): screenshots of the active view or of the window, and movies of
// the 3D view turning once around or of the played run, into the capture folder (ViewCapture.h: free names, a
// folder per movie, never an overwrite).
#include "FileLocations.h"
#include "MainWindow.h"
#include "RunPlayer.h"
#include "ViewCapture.h"
#include "ViewLayout.h"
#include "vsim/core/Error.h"
#include "vsim/core/OutputSafety.h"
#include "vsim/viz/VolumeView3D.h"

#include <QActionGroup>
#include <QApplication>
#include <QDateTime>
#include <QDir>
#include <QFileDialog>
#include <QMenu>
#include <QProgressDialog>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>

namespace vsim::gui {
namespace {

constexpr int kRotationFrames = 72; // 5 degrees a frame
constexpr double kMovieFps = 24.0;

/// "capture 2026-11-29 10-15-03": a portable stem that sorts by time.
QString timeStamp(const QString& what)
{
    return portableFileName(what + " " + QDateTime::currentDateTime().toString("yyyy-MM-dd HH-mm-ss"));
}

} // namespace

void MainWindow::createLayoutAndCaptureMenus(QMenu* view)
{
    QMenu* layouts = view->addMenu(tr("&Layout"));
    auto* layoutChoices = new QActionGroup(layouts);
    const std::pair<LayoutMode, QString> modes[] = {{LayoutMode::TwoByTwo, tr("2 x 2")},
                                                    {LayoutMode::OneByOne, tr("1 x 1 (the active view)")},
                                                    {LayoutMode::OneByThree, tr("1 x 3 (axial, coronal, sagittal)")},
                                                    {LayoutMode::VolumePlusSlices, tr("3D + MPR")},
                                                    {LayoutMode::VolumePlusCpr, tr("3D + CPR (along the vessel)")}};
    for (const auto& [mode, name] : modes)
    {
        QAction* choice = layouts->addAction(name);
        choice->setCheckable(true);
        choice->setChecked(mode == LayoutMode::TwoByTwo);
        choice->setObjectName(QStringLiteral("layout%1Action").arg(int(mode)));
        layoutChoices->addAction(choice);
        connect(choice, &QAction::triggered, this, [this, mode] {
            if (mode == LayoutMode::OneByOne)
                m_views->setMainView(m_views->activeView());
            if (mode == LayoutMode::VolumePlusCpr)
                showVesselView();
            else
                m_views->setLayoutMode(mode);
        });
    }

    QMenu* capture = view->addMenu(tr("&Capture"));
    QAction* shot = capture->addAction(tr("Screenshot of the Active &View"), this, [this] { saveScreenshot(m_views->activeView()); });
    shot->setShortcut(QKeySequence(tr("Ctrl+Shift+S", "screenshot of the view")));
    capture->addAction(tr("Screenshot of the &Window"), this, [this] { saveScreenshot(nullptr); });
    capture->addAction(tr("Movie of the 3D &Rotation"), this, [this] { saveMovie(MovieSource::Rotation); });
    m_documentActions << capture->addAction(tr("Movie of the Played &Run"), this, [this] { saveMovie(MovieSource::PlayedRun); });
    capture->addSeparator();
    capture->addAction(tr("Capture &Folder..."), this, [this] {
        const QString folder = QFileDialog::getExistingDirectory(this, tr("Capture folder"), captureFolder());
        if (!folder.isEmpty())
            QSettings().setValue("capture/folder", folder);
    });
}

QString MainWindow::captureFolder() const
{
    const QString chosen = QSettings().value("capture/folder").toString();
    if (!chosen.isEmpty() && QFileInfo(chosen).isDir())
        return chosen;
    // The default: "VascuSim captures" in the user's documents, a folder of our own.
    const QString folder = QDir(startFolder("capture-default")).filePath("VascuSim captures");
    claimOutputFolder(folder.toStdString(), "captures");
    return folder;
}

QString MainWindow::saveScreenshot(QWidget* view)
{
    try
    {
        const QImage picture = view ? captureView(view) : captureWindow(this);
        const QString file = freeFilePath(captureFolder(), timeStamp(view ? view->objectName() : QStringLiteral("window")), "png");
        if (picture.isNull() || !picture.save(file, "PNG"))
            throw Error(Pattern{"could not write %1", {file.toStdString()}});
        statusBar()->showMessage(tr("Screenshot saved: %1").arg(file), 8000);
        return file;
    }
    catch (const std::exception& error)
    {
        showError(tr("Screenshot"), QString::fromStdString(textForPeople(error)));
        return {};
    }
}

MovieResult MainWindow::saveMovie(MovieSource source)
{
    viz::VolumeView3D* volume = m_views->volumeView();
    const bool run = source == MovieSource::PlayedRun;
    if (run && (!m_runPlayer || m_runPlayer->frameCount() == 0))
    {
        showError(tr("Movie"), tr("Open a run first (double-click it in the study tree): the movie plays its frames."));
        return {};
    }
    const int frames = run ? m_runPlayer->frameCount() : kRotationFrames;
    const int startFrame = run ? m_runPlayer->frame() : 0;
    QProgressDialog progress(tr("Writing the movie frames..."), tr("Cancel"), 0, frames, this);
    progress.setWindowModality(Qt::WindowModal);
    progress.setMinimumDuration(500);
    MovieResult result;
    try
    {
        result = writeMovie(
            captureFolder(), timeStamp(run ? QStringLiteral("run movie") : QStringLiteral("rotation movie")), frames,
            [&](int i) {
                if (run)
                    m_runPlayer->setFrame(i); // draws the frame in every view
                else if (i > 0)
                    volume->orbit(360.0 / kRotationFrames);
                return captureView(volume);
            },
            kMovieFps,
            [&](int i) {
                progress.setValue(i);
                return !progress.wasCanceled();
            });
    }
    catch (const std::exception& error)
    {
        showError(tr("Movie"), QString::fromStdString(textForPeople(error)));
    }
    if (!run)
        volume->orbit(360.0 / kRotationFrames); // back where it started (72 x 5 degrees)
    else
        m_runPlayer->setFrame(startFrame);
    progress.setValue(frames);
    if (result.cancelled)
        statusBar()->showMessage(tr("Movie cancelled: its frames were removed"), 8000);
    else if (result.frames > 0)
        statusBar()->showMessage(tr("Movie saved: %1 frames in %2%3")
                                     .arg(result.frames)
                                     .arg(result.folder)
                                     .arg(result.mp4.isEmpty() ? " (" + result.note + ")" : QString()),
                                 12000);
    return result;
}

} // namespace vsim::gui
