#pragma once

// Layer 3 of the vessel segmentation: a sparse-field level set (ITK's threshold-segmentation level set) that
// moves the region-growing boundary onto the partial-volume half level with a curvature term that smooths the
// voxel staircase and noise bumps (thesis ch. 4.1, "level-set refinement").

#include "vsim/core/ImageVolume.h"

#include <cstdint>
#include <vector>

namespace vsim::imaging {

struct LevelSetSettings
{
    double lowerContrast = 0.5;  ///< boundary level, as a fraction of blood - tissue (the speed's zero)
    double upperContrast = 2.0;  ///< bright limit (bone, calcium), same units
    double curvatureWeight = 0.2; ///< curvature term against the intensity term (both per mm)
    int iterations = 20;          ///< 0 leaves the mask as it is
    double maxRmsChange = 0.01;   ///< stops earlier once the front moves less than this (voxels per step)
};

/// Evolves the boundary of `mask` (1 inside, `contrast`'s grid: (HU - tissue) / (blood - tissue) of the denoised
/// CT, so that 0 is tissue and 1 is blood) and returns the voxels inside the final zero level; `mask` is untouched
/// when `settings.iterations` is 0. `elapsedIterations`, when given, receives how many steps ran.
std::vector<std::uint8_t> refineWithLevelSet(const RealVolume& contrast, const std::vector<std::uint8_t>& mask,
                                             const LevelSetSettings& settings, int* elapsedIterations = nullptr);

} // namespace vsim::imaging
