#pragma once

// Contrast-vessel segmentation of a CTA in layers (thesis ch. 4.1, "multi-layer extraction"):
//  1. HU window + region growing from a seed (automatic: the largest bright component that survives an erosion,
//     i.e. a thick tubular one such as the aorta), the threshold half-way between the blood and the tissue
//     around it (the 50 % partial-volume iso-level);
//  2. multi-scale Hessian vesselness (Frangi, ITK) recovers thin branches the window lost;
//  3. hole filling and bone exclusion (voxels near bone or calcium above the window);
//  4. recursive Gaussian refinement of the label's boundary (more smoothing = smoother surface).
// The level-set refinement the issue lists as a layer is not implemented yet.

#include "vsim/core/ImageVolume.h"
#include "vsim/core/Parameters.h"
#include "vsim/core/Progress.h"

#include <Eigen/Core>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace vsim::imaging {

/// The declarations of every segmentation parameter (GUI form, --param, provenance).
std::vector<ParameterSpec> segmentationParameters();

struct SegmentationResult
{
    LabelVolume label;                     ///< 1 = vessel lumen, 0 = background; the CT's grid
    Eigen::Vector3d seedMm = Eigen::Vector3d::Zero(); ///< the seed used (given or found), patient frame
    bool seedFound = false;                ///< true when the seed was found automatically
    std::map<std::string, double> figures; ///< blood_hu, tissue_hu, threshold_hu, volume_ml, voxels, ...
    std::vector<std::string> warnings;
};

/// Segments the contrast-filled vessels connected to `seedMm` (or to the automatic seed). Throws vsim::Error
/// with what was wrong and what to try for data that is not CT HU, a volume without a contrast-filled vessel,
/// a seed outside the volume or outside any bright vessel, and vsim::Cancelled when cancelled.
SegmentationResult segmentVessels(const CtVolume& ct, const ParameterSet& parameters,
                                  const std::optional<Eigen::Vector3d>& seedMm = std::nullopt,
                                  const Progress& progress = {});

/// Dice coefficient 2|A and B| / (|A| + |B|) of the voxels equal to `valueA` in `a` and `valueB` in `b`
/// (same grid); 1 when both are empty. Throws vsim::Error for different grids.
double diceCoefficient(const LabelVolume& a, std::uint8_t valueA, const LabelVolume& b, std::uint8_t valueB);

} // namespace vsim::imaging
