#pragma once

// The markers of a SliceView (SliceMarker.h) as VTK props in the view's slice coordinates: x along the view's right,
// y along its up, mm from the cursor, drawn in front of the image and the label overlay.

#include "vsim/viz/SliceMarker.h"
#include "vsim/viz/SliceOrientation.h"

#include <vtkSmartPointer.h>

#include <optional>
#include <vector>

class vtkActor;
class vtkRenderer;
class vtkTextActor;

namespace vsim::viz {

class SliceMarkerLayer
{
public:
    explicit SliceMarkerLayer(vtkRenderer* renderer);
    ~SliceMarkerLayer();

    void setMarkers(std::vector<SliceMarker> markers) { m_markers = std::move(markers); }
    const std::vector<SliceMarker>& markers() const { return m_markers; }
    /// Moves one marker (while it is dragged); false when there is no marker `id`.
    bool moveMarker(int id, const Eigen::Vector3d& pointMm);
    /// Redraws the rings of the markers within `thicknessMm` of the slice through `cursorMm` (mm per screen pixel
    /// sets the ring's size: 7 pixels).
    void update(const Eigen::Vector3d& cursorMm, const ScreenAxes& axes, double thicknessMm, double mmPerPixel);
    /// Device pixels per logical pixel (HiDPI): text sizes and line widths follow it.
    void setPixelScale(double scale);

    /// The id of the drawn marker whose centre lies within `radiusMm` of `pointMm` in the slice, nearest first.
    std::optional<int> pick(const Eigen::Vector3d& pointMm, double radiusMm) const;

private:
    vtkRenderer* m_renderer;
    std::vector<SliceMarker> m_markers;
    std::vector<int> m_drawn; // ids of the markers drawn in the current slice
    double m_pixelScale = 1.0;
    vtkSmartPointer<vtkActor> m_rings;
    std::vector<vtkSmartPointer<vtkTextActor>> m_texts;
};

} // namespace vsim::viz
