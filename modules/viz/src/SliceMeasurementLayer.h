#pragma once

// The measurements of a SliceView (rulers, angles, ROIs; vsim/core/ViewMeasurement.h) as VTK props in the view's
// slice coordinates (x along the view's right, y along its up, mm from the plane origin), drawn where they were
// made: a measurement shows in a view whose plane is parallel to its own and within one slice thickness of its
// points. The one being drawn (the rubber band) shows in the view it is drawn in.

#include "vsim/viz/SliceMeasurement.h"
#include "vsim/viz/SliceOrientation.h"

#include <vtkSmartPointer.h>

#include <string>
#include <vector>

class vtkActor;
class vtkRenderer;
class vtkTextActor;

namespace vsim::viz {

class SliceMeasurementLayer
{
public:
    explicit SliceMeasurementLayer(vtkRenderer* renderer);
    ~SliceMeasurementLayer();

    void setMeasurements(std::vector<ShownMeasurement> measurements) { m_measurements = std::move(measurements); }
    const std::vector<ShownMeasurement>& measurements() const { return m_measurements; }
    /// The measurement being drawn (points so far, the last one following the mouse); empty: none.
    void setPending(const ViewMeasurement& pending) { m_pending = pending; }
    void clearPending() { m_pending.pointsMm.clear(); }
    /// Redraws for the slice through `originMm` with `axes` and `thicknessMm`.
    void update(const Eigen::Vector3d& originMm, const ScreenAxes& axes, double thicknessMm);
    /// Device pixels per logical pixel (HiDPI): text sizes and line widths follow it.
    void setPixelScale(double scale);
    /// How many measurements the current slice shows.
    int shownCount() const { return m_shown; }

private:
    vtkRenderer* m_renderer;
    std::vector<ShownMeasurement> m_measurements;
    ViewMeasurement m_pending;
    int m_shown = 0;
    double m_pixelScale = 1.0;
    vtkSmartPointer<vtkActor> m_lines;
    std::vector<vtkSmartPointer<vtkTextActor>> m_texts;
};

} // namespace vsim::viz
