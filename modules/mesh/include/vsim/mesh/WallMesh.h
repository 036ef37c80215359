#pragma once

// The tetrahedral vessel wall of the mechanics solver (thesis ch. 4.3): the lumen surface offset outward along its
// vertex normals by the wall thickness, each triangle and its offset a prism split into three tetrahedra (the
// smallest-index diagonal rule of Dompierre et al. 1999, so neighbouring prisms conform), one element layer
// through the wall. The closed ends of the segmented lumen are cut open one vessel radius inside each centerline
// endpoint (triangles beyond the cut plane are removed, so the open rim follows the triangles); the nodes of each
// open end form a fixed set. All in mm (patient frame).
// With the aneurysm sac's outer wall (an OuterWallDistance from the sac label) the wall is two prism layers: the
// wall of the given thickness inside the outer contour, and between it and the lumen the intraluminal thrombus
// (cell field "material" 1; the wall 0). Where the outer contour lies less than 1.5 wall thicknesses from the lumen
// (no thrombus to speak of, or outside the sac) both layers are wall, the inner one half a wall thickness. Where the
// inner layer would stand more than 5 times as tall as its shortest lumen edge is long (a thick thrombus over a fine
// lumen), it is split into as many equal sub-layers as that takes, everywhere (at most 8), when that raises the
// wall's smallest dihedral angle (where the inner layer is thin the sub-layers are flat: on a coarse lumen they can
// lose more than the tall prisms gain).
// Where the offsets crowd (a saddle such as the iliac crotch) or a thick thrombus layer makes tall prisms, the nodes
// off the held ends move to raise the smallest dihedral angles under 10 degrees (src/WallSmoothing.h): those off the
// lumen at most half a wall thickness across their offset direction, the lumen nodes a tenth of their edge along
// the surface; the diagonal two prisms share is flipped where the other one is better (src/WallFlips.h).

#include "vsim/core/SkeletonGraph.h"
#include "vsim/core/TetMesh.h"
#include "vsim/core/TriangleMesh.h"

#include <Eigen/Core>

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace vsim::mesh {

/// One open end of the vessel tree: a centerline endpoint, the direction out of the vessel there and its radius.
struct VesselEnd
{
    Eigen::Vector3d point;    ///< mm
    Eigen::Vector3d outward;  ///< unit
    double radiusMm = 0.0;
};

/// The ends of a centerline graph: its degree-1 nodes, with the direction of the last few mm of their edge.
std::vector<VesselEnd> vesselEnds(const SkeletonGraph& centerlines);

/// The sac's outer wall seen from the lumen: for a lumen vertex (mm) and its outward unit normal the distance (mm)
/// along the normal to the outer wall surface, negative where the vertex is not in the sac.
using OuterWallDistance = std::function<double(const Eigen::Vector3d& pointMm, const Eigen::Vector3d& normal)>;

struct WallMesh
{
    /// The wall (mm). Point fields: "wall_layer" (0 lumen side, l / (sub-layers + 1) between the layers, 1 outside),
    /// "end_set" (0 free, k for end k - 1); with a thrombus layer the cell field "material" (0 wall, 1 thrombus).
    TetMesh mesh;
    std::vector<std::vector<int>> endNodes; ///< per end, its nodes (both layers)
    double minDihedralDeg = 0.0;            ///< smallest dihedral angle of any element
    double minDihedralUnsmoothedDeg = 0.0;  ///< the same before the nodes moved and edges flipped (src/WallSmoothing.h)
    std::size_t nodesSmoothed = 0;          ///< nodes moved to raise the smallest angles
    std::size_t edgeFlips = 0;              ///< 4-4 edge flips (src/WallFlips.h)
    double largestSmoothingMoveMm = 0.0;    ///< the largest such move (mm)
    double meanMinDihedralDeg = 0.0;        ///< mean over elements of their smallest dihedral angle
    std::size_t slivers = 0;                ///< elements with a dihedral angle under 5 degrees
    Eigen::Vector3d worstElementMm = Eigen::Vector3d::Zero(); ///< centroid of the element with the smallest angle
    std::size_t inverted = 0;               ///< elements that could not be oriented positively (offset folded)
    std::size_t thrombusElements = 0;       ///< elements of the thrombus material
    double maxThrombusMm = 0.0;             ///< thickest thrombus layer (mm)
    int innerSubLayers = 1;                 ///< prism layers through the inner (thrombus) layer (with the outer wall)
    int innerSubLayersByAspect = 1;         ///< what the inner prisms' aspect asked (kept when it raised the angle)
    std::vector<std::string> warnings;
};

/// Builds the wall of `lumen` (closed or open, outward-oriented triangles, mm) with `thicknessMm`, opening it at
/// `ends`; with `outerWall` the thrombus layer inside the sac (above). Throws vsim::Error for an empty surface, a
/// thickness outside 0.1..10 mm, or an end that cuts nothing.
WallMesh buildWallMesh(const TriangleMesh& lumen, const std::vector<VesselEnd>& ends, double thicknessMm,
                       const OuterWallDistance& outerWall = {});

/// The faces of the wall on the lumen side, oriented out of the solid (into the lumen): where blood pressure acts.
std::vector<std::array<int, 3>> lumenFaces(const TetMesh& wall);

/// Smallest dihedral angle (degrees) of the tetrahedron with corners a, b, c, d.
double minDihedralAngle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                        const Eigen::Vector3d& d);

} // namespace vsim::mesh
