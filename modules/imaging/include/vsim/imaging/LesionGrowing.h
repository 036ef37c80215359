#pragma once

// A liver lesion from points inside it (issue 19, item 2: the tumour label for coverage and feeders), within the
// liver label. A hepatocellular carcinoma or metastasis on a portal-venous CT is a heterogeneous blob: a necrotic
// centre, an enhancing rim near the liver's own density, vessels through it. The organ window around the points
// (OrganGrowing.h) holds the centre only (recall 0.13-0.24 on IRCAD 1.17); the boundary that separates a lesion from
// the liver is where the tissue leaves the parenchyma's own range. On IRCAD 1.17 from one point near each tumour's
// centre: Dice 0.743 and 0.830 against the reference masks, 96 and 93 % of the label inside them (2026-11-29).
//
// Method: the CT smoothed by a Gaussian of `lesion_smoothing_mm` in a box of `lesion_reach_mm` around the points;
// the parenchyma level L and spread s: the peak of the histogram of the liver label's smoothed HU in the box and its
// full width at half maximum / 2.355 (the lesion's voxels in the label widen one tail, enhanced vessels the
// other); the lesion level T (the median within 5 mm of the points). A hypodense lesion
// (T < L) grows from the points through the liver voxels at or below L - max(k s, (L - T) / 4) (k =
// `lesion_sigmas`; a quarter of the contrast at least, where the smoothing's blur of the edge would carry a
// boundary nearer L outwards), a hyperdense one at or above L + max(k s, (T - L) / 4); then an opening by reconstruction of `lesion_opening_mm` (bridges along
// vessels and to neighbouring lesions cut), a closing of `lesion_closing_mm` and the enclosed cavities filled (the
// enhancing rim and vessels inside taken in), all within the liver. Balls by exact distances (MaskOps.h).

#include "vsim/core/ImageVolume.h"
#include "vsim/core/Parameters.h"
#include "vsim/core/Progress.h"

#include <Eigen/Core>

#include <map>
#include <string>
#include <vector>

namespace vsim::imaging {

std::vector<ParameterSpec> lesionGrowingParameters();

struct LesionGrowing
{
    LabelVolume label;                     ///< 1 in the lesion, on the CT's grid
    std::map<std::string, double> figures; ///< volume_ml, parenchyma_hu, parenchyma_sd_hu, lesion_hu, threshold_hu
    std::vector<std::string> warnings;
};

/// Grows the lesion from `pointsMm` (patient frame) within `liver`'s non-zero voxels (any grid: sampled at the
/// CT's voxel centres). Throws vsim::Error for no point, a point off the CT or outside the liver, or points whose
/// tissue is within the parenchyma's range (nothing to tell apart).
LesionGrowing growLesion(const CtVolume& ct, const std::vector<Eigen::Vector3d>& pointsMm, const LabelVolume& liver,
                         const ParameterSet& parameters, const Progress& progress = {});

} // namespace vsim::imaging
