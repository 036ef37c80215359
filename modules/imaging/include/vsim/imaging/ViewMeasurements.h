#pragma once

// The figures of a measurement drawn on a view (vsim/core/ViewMeasurement.h): a ruler's length, an angle, an
// elliptical ROI's CT statistics. The ROI samples its plane on a square grid of the image's finest voxel spacing,
// centred on the ellipse, and takes the CT value of the voxel nearest each sample inside it (what the view shows in
// nearest-neighbour display); the area is the ellipse's, pi a b.

#include "vsim/core/ImageVolume.h"
#include "vsim/core/ViewMeasurement.h"

namespace vsim::imaging {

/// Fills `measurement`'s figures; the ROI reads `ct` (unused for rulers and angles). Throws vsim::Error for a wrong
/// number of points, coincident angle points, or an ROI with no sample inside the volume.
void measure(ViewMeasurement& measurement, const CtVolume& ct);

} // namespace vsim::imaging
