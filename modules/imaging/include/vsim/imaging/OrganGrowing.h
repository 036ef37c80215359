#pragma once

// Semi-automatic organ labels from points (issue 19, item 2: the liver and its tumours for perfusion territories
// and coverage): the user places points inside the organ; the label grows from them through the voxels whose
// smoothed HU lies in the points' own intensity window, is opened to cut the thin bridges a window leaves to
// touching organs of the same density (stomach, heart, spleen, kidney), and closed to take in what the window left
// out inside (small vessels, noise). Editable afterwards with the label tools.
//
// Method: the CT smoothed (binomial 3 x 3 x 3, as the guided segmentation) in a box of `reach_mm` around the
// points; the window is the median of the smoothed HU within 7 mm of each point, plus or minus `window_sigmas` robust standard deviations (1.4826 x the
// median absolute deviation, at least 8 HU); 6-connected growing from the points; an opening of `opening_mm`
// (erosion, the part still connected to the points, dilation within the grown voxels: an opening by
// reconstruction); a closing of `closing_mm`; the enclosed cavities filled. Seeded region growing after Adams and
// Bischof (IEEE PAMI 16(6), 1994); the robust window as in the guided vessel segmentation.

#include "vsim/core/ImageVolume.h"
#include "vsim/core/Parameters.h"
#include "vsim/core/Progress.h"

#include <Eigen/Core>

#include <map>
#include <string>
#include <vector>

namespace vsim::imaging {

std::vector<ParameterSpec> organGrowingParameters();

struct OrganGrowing
{
    LabelVolume label;                      ///< 1 in the organ, on the CT's grid
    std::map<std::string, double> figures;  ///< volume_ml, window_low_hu, window_high_hu, seed_median_hu
    std::vector<std::string> warnings;
};

/// Grows the organ from `pointsMm` (patient frame). Throws vsim::Error for no point, a point off the CT, or points
/// whose window holds nothing.
OrganGrowing growOrgan(const CtVolume& ct, const std::vector<Eigen::Vector3d>& pointsMm, const ParameterSet& parameters,
                       const Progress& progress = {});

} // namespace vsim::imaging
