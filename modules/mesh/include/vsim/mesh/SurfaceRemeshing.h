#pragma once

// A lumen surface fit for the wall mesh. Quadric decimation (the thesis's "compression", VesselSurface.h) keeps
// the shape with few vertices but leaves long slivers on straight tubes (edges of 100+ mm along the aorta) that
// become flat prisms and invert under any load; vertex clustering on a uniform grid merges the walls of thin
// vessels. This is an isotropic remesher in the spirit of Botsch & Kobbelt 2004 ("A remeshing approach to
// multiresolution modeling"): split every edge longer than 4/3 of the target (red-green refinement, so the
// surface stays conforming and keeps its topology), collapse edges shorter than 4/5 of it where the surface stays
// a manifold and no triangle turns over, flip edges to the Delaunay criterion where the two triangles are nearly
// coplanar, and relax vertices tangentially; repeated a few times.

#include "vsim/core/SkeletonGraph.h"
#include "vsim/core/TriangleMesh.h"

#include <functional>

namespace vsim::mesh {

/// The edge length (mm) at which a surface of `areaMm2` has about `vertices` vertices (equilateral triangles:
/// two triangles of sqrt(3)/4 h^2 per vertex).
double edgeForVertexBudget(double areaMm2, double vertices);

/// Smallest interior angle (degrees) over the triangles of `surface`.
double minTriangleAngle(const TriangleMesh& surface);

/// The target edge length (mm) at a point.
using EdgeSizing = std::function<double(const Eigen::Vector3d& pointMm)>;

/// A sizing that follows the vessels: `fraction` of the radius of the nearest centerline point, at most
/// `largestMm` (thin vessels keep several edges around their circumference; wide ones stay within the budget).
EdgeSizing vesselSizing(const SkeletonGraph& centerlines, double fraction, double largestMm);

/// `surface` (closed, outward-oriented, mm) remeshed towards edges of `sizing` (0.1..50 mm; clamped, no error).
/// Throws vsim::Error for an empty surface.
TriangleMesh remeshIsotropic(const TriangleMesh& surface, const EdgeSizing& sizing, int rounds = 5);

} // namespace vsim::mesh
