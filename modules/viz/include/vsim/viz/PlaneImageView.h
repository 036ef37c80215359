#pragma once

#include "vsim/viz/SliceOrientation.h"
#include "vsim/viz/VtkView.h"

#include <QPointF>
#include <QString>

#include <optional>
#include <utility>
#include <vector>

namespace vsim::viz {

/// A 2D picture of CT values in a VTK view: the straightened CPR or the cross-section of a vessel view
/// (imaging/CurvedReformation.h). Square pixels of a size in mm, the whole picture fitted to the view, window/level,
/// a caption, a horizontal marker line (the position along a CPR) and a circle about the centre (the lumen caliper
/// on a cross-section). A left click reports the picture position in mm from its top-left corner; the wheel reports
/// steps (one per notch); right drag changes window/level.
class PlaneImageView : public VtkView
{
    Q_OBJECT
public:
    explicit PlaneImageView(QWidget* parent = nullptr);
    ~PlaneImageView() override;

    /// Shows `values` (HU, row-major from the top row) of `width` x `height` pixels of `pixelMm`.
    void setPicture(int width, int height, double pixelMm, const std::vector<float>& values);
    int pictureWidth() const { return m_width; }
    int pictureHeight() const { return m_height; }
    double pixelMm() const { return m_pixelMm; }
    void setWindowLevel(const WindowLevel& windowLevel);
    WindowLevel windowLevel() const { return m_windowLevel; }
    void setCaption(const QString& text);
    QString caption() const { return m_caption; }
    /// A horizontal line across the picture at `rowMm` from the top (none: hidden).
    void setMarkerRow(std::optional<double> rowMm);
    /// A circle of `radiusMm` about the picture's centre (none: hidden).
    void setCentreCircle(std::optional<double> radiusMm);
    /// A caliper (yellow, ticks at its ends) between two picture positions (mm from the top-left pixel's centre);
    /// none: hidden.
    void setCaliper(std::optional<std::pair<QPointF, QPointF>> endsMm);
    /// The widget position (logical pixels) of a picture position (mm from the top-left corner), and back.
    QPointF widgetAt(const QPointF& pictureMm) const;
    QPointF pictureAt(const QPointF& widgetPosition) const;

signals:
    void clicked(const QPointF& pictureMm);
    void stepped(int steps);

protected:
    void resizeGL(int width, int height) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;

private:
    void updateCamera();
    void updateLines();
    double millimetresPerPixel() const;

    struct Pipeline;
    std::unique_ptr<Pipeline> m_pipeline;
    int m_width = 0, m_height = 0;
    double m_pixelMm = 1.0;
    WindowLevel m_windowLevel = kCtaPreset;
    QString m_caption;
    std::optional<double> m_markerRowMm, m_circleMm;
    std::optional<std::pair<QPointF, QPointF>> m_caliperMm;
    QPointF m_dragStart;
    WindowLevel m_dragStartWindowLevel;
    int m_wheelRemainder = 0;
};

} // namespace vsim::viz
