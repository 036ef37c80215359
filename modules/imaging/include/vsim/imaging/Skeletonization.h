#pragma once

// Unit-width vessel skeletons (thesis ch. 4.1): topology-preserving 3D thinning that keeps curve ends, then the
// VDSM post-processing that removes crowded points, spur pruning, and the graph of endpoints, junctions and
// edges with radii from the distance map.

#include "vsim/core/ImageVolume.h"
#include "vsim/core/Parameters.h"
#include "vsim/core/Progress.h"
#include "vsim/core/SkeletonGraph.h"

namespace vsim::imaging {

/// prune_factor, min_branch_mm.
std::vector<ParameterSpec> skeletonParameters();

/// Sequential directional thinning to a curve skeleton (in the manner of Lee, Kashyap & Chu 1994): in six
/// sub-iterations per pass, border voxels facing one direction are removed when they are simple points
/// (Bertrand & Malandain: one 26-connected object component and one 6-connected background component in the
/// neighbourhood; this keeps components, tunnels and cavities) and not curve ends (one object neighbour).
/// Returns 1 on skeleton voxels. Throws vsim::Cancelled.
LabelVolume thinToCurves(const LabelVolume& label, std::uint8_t value, const Progress& progress = {});

/// Skeleton voxels with more than two skeleton neighbours (26) that touch another such voxel: VDSM's crowded
/// points. Zero for a unit-width skeleton.
std::size_t countCrowdedVoxels(const LabelVolume& skeleton);

/// VDSM post-processing (thesis ch. 4.1, SEED-NOTES): crowded points form 26-connected regions; a region's exit
/// points are skeleton voxels of degree <= 2 next to it; its centre is the spatial median (the region voxel with
/// the least summed distance to the others); the shortest paths from the centre to each exit are kept and every
/// other crowded point is deleted. The paths are routed so that different paths never touch except at the centre
/// (else the junction stays crowded), through the region and, where it offers no such route, through `lumen`
/// voxels next to it (optional, the vessel label: value 1). Repeats until no crowded point is left (or nothing
/// changes); crowded voxels the routing could not separate are then deleted where they are simple points of the
/// skeleton (topology kept). Returns the number of voxels changed.
std::size_t removeCrowdedPoints(LabelVolume& skeleton, const LabelVolume* lumen = nullptr);

struct SkeletonResult
{
    SkeletonGraph graph;
    LabelVolume skeleton;          ///< 1 on skeleton voxels after VDSM and pruning
    std::size_t thinnedVoxels = 0; ///< skeleton voxels straight after thinning
    std::size_t crowdedAfterThinning = 0;
    std::size_t crowdedAfterVdsm = 0;
    std::size_t prunedBranches = 0;
};

/// Thinning, VDSM, spur pruning (end branches shorter than max(min_branch_mm, prune_factor x the radius at their
/// junction)), and the graph with mm polylines and radii (distance to the lumen boundary). Throws vsim::Error for
/// an empty label.
SkeletonResult extractSkeleton(const LabelVolume& label, std::uint8_t value, const ParameterSet& parameters,
                               const Progress& progress = {});

} // namespace vsim::imaging
