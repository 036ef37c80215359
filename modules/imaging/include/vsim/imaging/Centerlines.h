#pragma once

// Vessel centerlines (thesis ch. 4.1): a fast-marching arrival time from the root of the vessel tree over a speed
// image that is fastest on the medial axis (ITK FastMarching), minimal paths back-tracked from every skeleton node
// by steepest descent of the arrival time (written here: ITK's minimal-path module is not in Debian), and
// least-squares cubic B-spline smoothing.

#include "vsim/core/ImageVolume.h"
#include "vsim/core/Parameters.h"
#include "vsim/core/Progress.h"
#include "vsim/core/SkeletonGraph.h"

#include <optional>
#include <utility>

namespace vsim::imaging {

/// speed_power, bspline_knot_spacing_mm, sample_step_mm.
std::vector<ParameterSpec> centerlineParameters();

/// One centerline per skeleton edge (or only the path between `fromTo` nodes), as a graph with the skeleton's
/// nodes: each edge's points are the smoothed centerline (mm, about sample_step_mm apart), its voxels the nearest
/// voxels, its radii the distance to the lumen boundary. The root is the endpoint of largest radius. Throws
/// vsim::Error for an empty label or skeleton, or nodes that are not connected through the lumen.
SkeletonGraph extractCenterlines(const LabelVolume& label, std::uint8_t value, const SkeletonGraph& skeleton,
                                 const ParameterSet& parameters,
                                 const std::optional<std::pair<int, int>>& fromTo = std::nullopt,
                                 const Progress& progress = {});

/// Smooths a polyline (mm) with a least-squares cubic B-spline (uniform knots about `knotSpacingMm` apart, ends
/// kept) and resamples it about every `stepMm`.
std::vector<Eigen::Vector3d> smoothWithBSpline(const std::vector<Eigen::Vector3d>& points, double knotSpacingMm,
                                               double stepMm);

} // namespace vsim::imaging
