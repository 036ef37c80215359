#pragma once

// Segmentation of the vessel the clinician means, from points: include points (automatic for the abdominal aorta),
// exclude points (heart, vein, kidney, bone), stop planes and a path-length limit.
//
// Method: competitive geodesic wave propagation. Every point grows its own front in order of path length (Dijkstra
// on the 26-neighbour voxel graph, mm) through voxels whose lightly smoothed HU lies in the point's own intensity
// window (half-way between its blood and the tissue around it, up to blood + margin, so calcium and cortical bone
// stay out; voxels touching bone or calcium brighter than that are refused too; a thin cross-section goes on down to
// a thin-vessel level where each voxel stands out of its own surroundings). Fronts compete: a voxel belongs to
// the first front that reaches it, so an exclude point in the right ventricle claims the ventricle before the
// pulmonary trunk's front gets there. The front of an include point advances in waves (shells of path length);
// each wave's connected components are the vessel's cross-sections, linked to the components they grew from.
// A leak (into the heart, a touching vein, the aorta beside the pulmonary trunk) passes a neck and widens: a
// cross-section whose area exceeds a factor times the narrowest of the 12 before it is cut back to that neck and
// not grown further. Work is confined to a box
// around the points (the path-length limit), not the whole volume.
// References: wave-front propagation with explosion control as in airway tree segmentation (Tschirren et al.,
// IEEE TMI 24(12), 2005; Kiraly et al., Acad. Radiol. 9(10), 2002); competitive region growing from labelled seeds
// (seeded region growing, Adams and Bischof, IEEE PAMI 16(6), 1994).

#include "vsim/core/ImageVolume.h"
#include "vsim/core/Parameters.h"
#include "vsim/core/Progress.h"
#include "vsim/imaging/VesselSegmentation.h"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace vsim::imaging {

enum class SegmentationTarget
{
    Aorta,   ///< the aorta within the scan, its branches to branch_length_mm
    Hepatic, ///< the hepatic artery tree: the aorta near its point only, the tree from the other points
    All,     ///< every contrast vessel connected to the include points, to the path-length limit
};
std::string segmentationTargetName(SegmentationTarget target);
/// Throws vsim::Error listing the known targets.
SegmentationTarget segmentationTargetFromName(const std::string& name);

/// A plane the include fronts do not cross: voxels with (p - point) . normal > 0 are not grown.
struct StopPlane
{
    Eigen::Vector3d pointMm = Eigen::Vector3d::Zero();
    Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
};

struct SegmentationRequest
{
    SegmentationTarget target = SegmentationTarget::All;
    std::vector<Eigen::Vector3d> includeMm; ///< patient frame; empty for target aorta: the automatic point
    std::vector<Eigen::Vector3d> excludeMm;
    std::vector<StopPlane> stops;
    std::optional<double> maxLengthMm;      ///< path length from the include points; unset: the target's default
};

/// The declarations of the guided segmentation's parameters (GUI form, --param, provenance).
std::vector<ParameterSpec> guidedSegmentationParameters();

/// Segments from points. The label holds 1 for the vessel lumen. figures: lower_hu, upper_hu, volume_ml, voxels,
/// leaks_cut, thin_bursts_blocked, waves, work_voxels, and per point its window (include_N_lower_hu, _upper_hu, the
/// thin-vessel level _thin_hu, _radius_mm); warnings name every leak cut (where, the area jump) and a front stopped by the
/// length limit. Throws vsim::Error for a point outside the volume or not in a bright vessel (with what to try),
/// data not in HU, and vsim::Cancelled.
SegmentationResult segmentFromPoints(const CtVolume& ct, const ParameterSet& parameters,
                                     const SegmentationRequest& request, const Progress& progress = {});

/// The automatic abdominal aorta point (src/AortaFinder.cpp): in slices 4 mm apart, the round pieces of enhanced
/// blood (smoothed 150..600 HU, 14..56 mm, filling 85 % of their equivalent disc, not bordered by cortex over
/// 600 HU as a vertebral body's core is) with bone behind them (the vertebral body: 30 % of a 30 x 30 mm window over
/// 200 HU, in the slice or one within 12 mm: at a disc) and none in front; the middle of the longest chain of such
/// pieces lining up slice after slice (of equal chains the brighter). Throws vsim::Error, naming --seed, when no
/// chain of three is found.
Eigen::Vector3d findAbdominalAortaPoint(const CtVolume& ct);

} // namespace vsim::imaging
