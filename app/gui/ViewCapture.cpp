#include "ViewCapture.h"

#include "vsim/core/Error.h"
#include "vsim/core/OutputSafety.h"
#include "vsim/viz/VtkView.h"

#include <QDir>
#include <QFileInfo>
#include <QPainter>
#include <QProcess>
#include <QStandardPaths>
#include <QWidget>

#include <filesystem>
#include <vector>

namespace vsim::gui {

QImage captureView(QWidget* view)
{
    if (auto* vtk = qobject_cast<viz::VtkView*>(view))
        return vtk->grabFramebuffer();
    return view->grab().toImage();
}

QImage captureWindow(QWidget* window)
{
    QImage picture = window->grab().toImage(); // device pixels, its ratio set: the painter works in logical ones
    QPainter painter(&picture);
    for (viz::VtkView* view : window->findChildren<viz::VtkView*>())
    {
        if (!view->isVisible() || view->width() <= 0)
            continue;
        const QPoint at = view->mapTo(window, QPoint(0, 0));
        painter.drawImage(QRectF(at.x(), at.y(), view->width(), view->height()), view->grabFramebuffer());
    }
    return picture;
}

QString freeFilePath(const QString& folder, const QString& stem, const QString& extension)
{
    const QDir dir(folder);
    QString path = dir.filePath(stem + "." + extension);
    for (int n = 2; QFileInfo::exists(path); ++n)
        path = dir.filePath(QStringLiteral("%1-%2.%3").arg(stem).arg(n).arg(extension));
    return path;
}

MovieResult writeMovie(const QString& parent, const QString& stem, int frameCount, const std::function<QImage(int)>& frame,
                       double fps, const std::function<bool(int)>& keepGoing)
{
    MovieResult result;
    result.folder = QDir(parent).filePath(stem);
    for (int n = 2; QFileInfo::exists(result.folder); ++n)
        result.folder = QDir(parent).filePath(QStringLiteral("%1-%2").arg(stem).arg(n));
    claimOutputFolder(result.folder.toStdString(), "movie");
    std::vector<std::filesystem::path> written;
    for (int i = 0; i < frameCount; ++i)
    {
        if (!keepGoing(i))
        {
            written.push_back(std::filesystem::path(result.folder.toStdString()) / kOwnedFolderMarker); // ours too
            removeWrittenFiles(written, result.folder.toStdString());
            result.cancelled = true;
            return result;
        }
        const QString file = QDir(result.folder).filePath(QStringLiteral("frame-%1.png").arg(i + 1, 4, 10, QChar('0')));
        if (!frame(i).save(file, "PNG"))
            throw Error(Pattern{"could not write the movie frame %1", {file.toStdString()}});
        written.push_back(file.toStdString());
        ++result.frames;
    }
    const QString encoder = QStandardPaths::findExecutable("ffmpeg");
    if (encoder.isEmpty())
    {
        result.note = QStringLiteral("no MP4: ffmpeg (Debian package ffmpeg) is not installed; the frames are PNG");
        return result;
    }
    // H.264 in yuv420p plays everywhere; even frame sizes are required by the encoder (pad by one pixel if odd).
    const QString mp4 = QDir(result.folder).filePath("movie.mp4");
    QProcess ffmpeg;
    ffmpeg.start(encoder, {"-loglevel", "error", "-framerate", QString::number(fps), "-i",
                           QDir(result.folder).filePath("frame-%04d.png"), "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2",
                           "-c:v", "libx264", "-pix_fmt", "yuv420p", mp4});
    if (ffmpeg.waitForFinished(300000) && ffmpeg.exitStatus() == QProcess::NormalExit && ffmpeg.exitCode() == 0)
        result.mp4 = mp4;
    else
        result.note = QStringLiteral("no MP4: ffmpeg failed (%1)").arg(QString::fromLocal8Bit(ffmpeg.readAllStandardError()).trimmed());
    return result;
}

} // namespace vsim::gui
