#pragma once

// Pictures of what the workstation shows: one view or the whole window as PNG, and movies (a PNG sequence, and an
// MP4 when Debian's ffmpeg is on PATH). VTK views are read from their OpenGL framebuffers (QWidget::grab does not
// see them under every platform plugin), and laid over the window's own picture at their places. Nothing is
// overwritten: a picture gets a free name ("<stem>.png", "<stem>-2.png", ...), a movie a new folder of its own,
// marked as VascuSim's; a cancelled movie removes the frames it wrote.

#include <QImage>
#include <QString>

#include <functional>

class QWidget;

namespace vsim::gui {

/// The picture of one widget: a VTK view's framebuffer, or the widget's own rendering (device pixels).
QImage captureView(QWidget* view);
/// The picture of a window with every visible VTK view inside it drawn in.
QImage captureWindow(QWidget* window);
/// "<folder>/<stem>.<extension>", or with "-2", "-3", ... when taken.
QString freeFilePath(const QString& folder, const QString& stem, const QString& extension);

struct MovieResult
{
    QString folder;      ///< the movie's own folder (frames frame-0001.png ...)
    int frames = 0;      ///< frames written
    QString mp4;         ///< the encoded movie; empty when no encoder was found or it failed
    QString note;        ///< why there is no MP4, or the encoder's complaint
    bool cancelled = false;
};

/// Writes `frameCount` frames made by `frame(i)` into a new folder "<parent>/<stem>" (or "-2", ...) at `fps`
/// frames per second; `keepGoing(i)` is asked before each frame (progress and Cancel) and a false removes the
/// frames written. Throws vsim::Error when the folder cannot be made.
MovieResult writeMovie(const QString& parent, const QString& stem, int frameCount, const std::function<QImage(int)>& frame,
                       double fps, const std::function<bool(int)>& keepGoing);

} // namespace vsim::gui
