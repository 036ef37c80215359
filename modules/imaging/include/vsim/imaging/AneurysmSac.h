#pragma once

// The AAA sac from the lumen: the aorta's outer contour, the thrombus between it and the lumen, an assumed-thickness
// wall inside the contour, and the figures by the clinical definitions (SVS 2018: the maximum diameter outer wall to
// outer wall, perpendicular to the centerline).
//
// Method. The aortic lumen is followed slice by slice (the largest lumen cross-section, then the piece nearest the
// previous slice's, until it splits at the bifurcation). In each axial slice rays leave the lumen's centroid every
// degree and run outwards from the lumen's edge until the smoothed HU falls below the fat level (half-way between
// the thrombus and fat, -30 HU) or rises 35 HU above the wall's own level (the median of its first 2 mm; capped at
// 150 HU): a touching disc, vein, organ or bone. Rays longer than 1.5 x the contour's median are replaced from their
// neighbours, then the radii are median-filtered over +-10 degrees and over +-4 neighbouring slices. Wall = voxels within the wall thickness inside the contour;
// thrombus = the rest outside the lumen. The outer contour's centerline: the contours' centroids, smoothed over
// +-5 mm; every perpendicular cross-section is resampled at 0.5 mm and its largest caliper is its diameter.
// The sac: the contiguous part around the widest section whose outer diameter exceeds 1.5 x the neck's, the neck
// being the outer diameter at the lowest renal artery's origin (src/SacLandmarks.h; without the renal arteries in
// the label: the narrowest outer diameter in the 80 mm above the widest section; 30 mm when there is no neck). Its
// volume: the perpendicular areas integrated along the centerline. Also: neck length and angulation, the common
// iliac outer diameters.

#include "vsim/core/ImageVolume.h"
#include "vsim/core/Progress.h"

#include <Eigen/Core>

#include <map>
#include <string>
#include <vector>

namespace vsim::imaging {

struct AneurysmSac
{
    LabelVolume labels;                            ///< 1 lumen, 4 thrombus, 5 wall (the phantoms' truth values)
    std::map<std::string, double> figures;         ///< units in the keys; see figureDefinitions
    std::map<std::string, std::string> definitions; ///< the definition of each figure, as printed
    Eigen::Vector3d maxDiameterCentreMm = Eigen::Vector3d::Zero();
    std::vector<std::string> warnings;
};

/// The definition of each figure measureAneurysmSac reports (by key), as the CLI, the dock and the report print it;
/// `forPeople`: in the reader's language (core Localized.h), else English as the study keeps it.
std::map<std::string, std::string> aneurysmSacDefinitions(bool forPeople = false);

/// Throws vsim::Error when the lumen label holds no aorta-sized cross-section (>= 50 mm2) or when over 20 % of the
/// rays meet no outer edge within 60 mm (no fat around the aorta: no contour to measure), vsim::Cancelled.
AneurysmSac measureAneurysmSac(const CtVolume& ct, const LabelVolume& lumen, double wallThicknessMm,
                               const Progress& progress = {});

} // namespace vsim::imaging
