#pragma once

// How the 3D view draws volumes (transfer functions): the CT rendered in CTA colours, the CT as a maximum
// intensity projection, and a field on a grid (a smoke run's density) as smoke.

#include <vtkSmartPointer.h>

class vtkColorTransferFunction;
class vtkVolumeProperty;

namespace vsim::viz::detail {

/// CTA (HU): air and soft tissue transparent, contrast blood red and bone ivory, opaque; shaded.
vtkSmartPointer<vtkVolumeProperty> ctaRenderedProperty();

/// The maximum intensity projection (HU): grey from above soft tissue and its noise's maxima along a ray (200) to
/// dense contrast (700), clear below.
vtkSmartPointer<vtkVolumeProperty> ctaMaximumIntensityProperty();

/// Smoke over [low, high] (the field's unit): clear at `low`, grey-white and denser towards `high`, at most 0.6 a
/// voxel so that the far side shows through; unshaded. The colour function (for the legend) is the property's.
vtkSmartPointer<vtkVolumeProperty> smokeProperty(double low, double high);

} // namespace vsim::viz::detail
