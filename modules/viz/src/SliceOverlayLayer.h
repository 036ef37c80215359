#pragma once

// What a SliceView draws over the image besides markers and fields: the crosshair (two lines through the cursor in
// the colours of the planes they stand for, with a gap around the cursor so that the voxel under it stays visible),
// a scale bar of a round length, and the four corner texts (patient / study / series, window / level, slice,
// value under the mouse). Lines live in the view's slice coordinates: x along the view's right, y along its up,
// mm from the plane origin at the camera's focal point.

#include <QString>

#include <Eigen/Core>
#include <vtkSmartPointer.h>

#include <array>

class vtkActor;
class vtkRenderer;
class vtkTextActor;

namespace vsim::viz {

class SliceOverlayLayer
{
public:
    explicit SliceOverlayLayer(vtkRenderer* renderer);
    ~SliceOverlayLayer();

    /// Colours (RGB 0-1) of the horizontal and the vertical crosshair line.
    void setCrosshairColours(const Eigen::Vector3d& horizontal, const Eigen::Vector3d& vertical);
    void setCrosshairShown(bool shown);
    bool crosshairShown() const { return m_crosshairShown; }
    /// Redraws the crosshair at `crosshairMm` and the scale bar for a view `widthPixels` x `heightPixels` of
    /// `mmPerPixel`, the focal point at slice coordinates (0, 0).
    void update(const Eigen::Vector2d& crosshairMm, int widthPixels, int heightPixels, double mmPerPixel);
    /// The scale bar's length (mm): 1, 2 or 5 x 10^k, at most a quarter of the view's width.
    double scaleBarMm() const { return m_scaleBarMm; }

    /// Device pixels per logical pixel (HiDPI): text sizes and line widths follow it.
    void setPixelScale(double scale);

    /// The text in a corner (Qt::TopLeftCorner ...), several lines allowed.
    void setCornerText(Qt::Corner corner, const QString& text);
    QString cornerText(Qt::Corner corner) const { return m_cornerTexts[std::size_t(corner)]; }

private:
    vtkRenderer* m_renderer;
    bool m_crosshairShown = true;
    double m_scaleBarMm = 0.0;
    double m_pixelScale = 1.0;
    std::array<Eigen::Vector3d, 2> m_crosshairColours; // horizontal, vertical
    vtkSmartPointer<vtkActor> m_crosshair;
    vtkSmartPointer<vtkActor> m_scaleBar;
    vtkSmartPointer<vtkTextActor> m_scaleText;
    std::array<vtkSmartPointer<vtkTextActor>, 4> m_corners; // by Qt::Corner
    std::array<QString, 4> m_cornerTexts;
};

/// The largest 1, 2 or 5 x 10^k not above `limit` (> 0).
double roundLengthBelow(double limit);

} // namespace vsim::viz
