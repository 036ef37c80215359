#pragma once

// The exact squared Euclidean distance transform on a box of voxels (Felzenszwalb & Huttenlocher, Theory of
// Computing 8, 2012): one pass per axis of the lower envelope of parabolas, spacing per axis in mm. For margins
// and dilations around a region without touching the rest of a volume.

#include <array>
#include <vector>

namespace vsim {

/// `values` (dims[0] x dims[1] x dims[2], x fastest): 0 at the sites, anything else elsewhere; on return the
/// squared distance (mm^2) from every voxel to the nearest site (infinity when there is none).
void squaredDistanceTransform(std::vector<double>& values, const std::array<int, 3>& dims, const std::array<double, 3>& spacingMm);

} // namespace vsim
