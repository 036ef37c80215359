#pragma once

// Two small helpers of the guided segmentation, shared by its fronts (WaveFront), minimal paths (VesselPaths), local
// half level (LocalHalfLevel) and point windows (GuidedSegmentation).

#include "vsim/core/ImageVolume.h"

#include <Eigen/Core>

#include <string>

namespace vsim::imaging::detail {

/// A patient position as messages give it: "(x, y, z) mm", one decimal.
std::string mmText(const Eigen::Vector3d& p);
/// The smoothed HU (binomial 3 x 3 x 3, clamped at the border) at a voxel of the CT.
double smoothedHu(const CtVolume& ct, int i, int j, int k);

} // namespace vsim::imaging::detail
