#pragma once

// Vessel networks from imaging: one conical segment per centerline edge, and nodes placed at points of the tree
// (the catheter tip, control points) by splitting the segment there.

#include "vsim/core/SkeletonGraph.h"
#include "vsim/core/VesselNetwork.h"

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace vsim::sim::network {

/// One segment per centerline edge: nodes and paths (mm) from the centerlines, lengths along the polylines, end
/// radii from `endRadiiMm` (per edge {start, end}, e.g. the cross-section measurements' equivalent radii) when
/// given, else the median centerline radius over the first and last quarter of the edge. The root is the end of
/// the largest radius. A skeleton can keep a small loop where vessels touch or a junction was crowded; the
/// network must be a tree, so the thinnest segment of each loop is left out (a maximum spanning tree by radius)
/// and named in `warnings`. `names` (per edge, or empty) become the segments' anatomical names. Throws
/// vsim::Error for empty centerlines or radii that are not positive (naming the edge).
VesselNetwork networkFromCenterlines(const SkeletonGraph& centerlines,
                                     const std::vector<std::array<double, 2>>& endRadiiMm = {},
                                     std::vector<std::string>* warnings = nullptr,
                                     const std::vector<std::string>& names = {});

/// How a segment is named for people: its anatomical name, else "unnamed (nodes a-b)" (a stored text: core
/// StoredText.h, translated where it is shown). (Not its nearest named
/// ancestor's: a tree rooted at the wrong end, e.g. an iliac artery's, would name every hepatic branch after it.)
std::string branchName(const VesselNetwork& network, int segment);

/// The segment nearest to `pointMm` (along its path) among those `eligible` accepts (all when empty) and the
/// distance (mm); {-1, inf} when there is none.
std::pair<int, double> nearestSegment(const VesselNetwork& network, const Eigen::Vector3d& pointMm,
                                      const std::function<bool(int)>& eligible = {});

/// The middle of a segment's path (mm).
Eigen::Vector3d segmentMiddle(const VesselNetwork& network, int segment);

/// A node at `pointMm`: an existing node within `snapMm`, else a new node splitting the nearest segment there
/// (path, length and radii divided at the point; an explicit resistance in proportion to length; result fields
/// dropped). Throws vsim::Error when the point is farther than `reachMm` from every segment.
int placeNode(VesselNetwork& network, const Eigen::Vector3d& pointMm, double snapMm, double reachMm);

/// A synthetic tree for validation and benchmarks: `segments` conical segments, each from a uniformly chosen
/// earlier node (seeded: the same tree on every machine), radii 0.3-3 mm tapering up to 30 %, lengths 2-22 mm,
/// root node 0; no outlet conditions.
VesselNetwork randomTree(int segments, std::uint32_t seed);

} // namespace vsim::sim::network
