#pragma once

// The AAA sac as a study artifact, the same from the CLI (`sac`) and the workstation: its labels (1 lumen,
// 4 thrombus, 5 wall) with the figures in the provenance (the report and the measurement dock read them there).

#include "vsim/imaging/AneurysmSac.h"
#include "vsim/sim/fem/SacPeaks.h"
#include "vsim/study/Study.h"

#include <functional>
#include <map>
#include <optional>
#include <string>

namespace vsim::app {

/// Adds the sac measured from label `lumenId` on image `imageId` to the study (not saved); returns its id.
std::string recordAneurysmSac(study::Study& study, const imaging::AneurysmSac& sac, const std::string& imageId,
                              const std::string& lumenId, double wallThicknessMm);

/// The newest sac artifact's figures (key -> value, units in the keys); empty when the study has none.
std::map<std::string, double> newestSacFigures(const study::Study& study, std::string* sacId = nullptr);

/// The newest sac as the wall solver's region (sim/fem SacPeaks.h): points in its labels (1, 4, 5) between its upper
/// and lower ends (sac_top_z_mm, sac_bottom_z_mm), the distance along the centerline counted from the aorta at the
/// lowest renal artery's origin (the widest centerline point within 3 mm of lowest_renal_z_mm; the sac's upper end
/// without it), and the sac's local outer diameter and thrombus thickness along a point's radius (for the wall
/// strength); nothing when the study has no sac.
std::optional<sim::fem::SacRegion> newestSacRegion(const study::Study& study, const SkeletonGraph& centerlines);

/// The sac label's outer wall seen from a lumen vertex (mesh::OuterWallDistance): the distance along the normal
/// to the first point outside its labels (1, 4, 5) once thrombus or wall (4, 5) was crossed, in steps of a quarter
/// of the smallest voxel side up to 40 mm; -1 where the normal meets no thrombus or wall within 5 mm (outside the
/// sac).
std::function<double(const Eigen::Vector3d&, const Eigen::Vector3d&)> sacOuterWallDistance(const LabelVolume& sacLabels);

/// The newest label that is a lumen (not a sac's labels, not an organ grown from points); "" when none.
std::string newestLumenLabel(const study::Study& study);

/// The label the centerlines were traced from (a label among their provenance inputs, through the skeleton they came
/// from); else newestLumenLabel. A wall built from other centerlines' label, or from an imported copy of a sac
/// label, would name the wrong input in its provenance.
std::string lumenLabelOfCenterlines(const study::Study& study, const std::string& centerlinesId);

} // namespace vsim::app
