#pragma once

// Landmarks of the AAA sac (AneurysmSac.h) found on the lumen label's axial sections: the lowest renal artery's
// origin (the neck's landmark) and the common iliac arteries below the bifurcation with their outer diameters.

#include "AorticSections.h"

#include <map>
#include <optional>
#include <string>

namespace vsim::imaging::detail {

/// The section (index into `sections`, superior first) of the lowest renal artery's origin above section `peak`:
/// the first section, going up from the peak, whose lumen piece reaches sideways (within 45 degrees of the patient's
/// left-right axis) more than 3.5 mm beyond its equivalent radius, the renal artery leaving the aorta in that slice.
/// nullopt when no section does (the label lacks the renal arteries).
std::optional<std::size_t> lowestRenalSection(const std::vector<Section>& sections, const VolumeGeometry& g,
                                              std::size_t peak);

/// The common iliac arteries below the aorta's last section: the lumen followed down while the two iliacs touch, to
/// the first slice with two pieces near it (the crotch), then each followed down (the nearest piece within 10 mm)
/// for 50 mm. Their outer
/// contours are traced as the aorta's; the diameter is the median of the perpendicular outer diameters 10 to 40 mm
/// of centerline below the crotch. Keys "left_common_iliac_diameter_mm" and "right_..." (patient left: +x in
/// LPS); an iliac not followed 40 mm has no key.
std::map<std::string, double> commonIliacDiameters(const CtVolume& ct, const LabelVolume& lumen,
                                                   const std::vector<Section>& aorta);

} // namespace vsim::imaging::detail
