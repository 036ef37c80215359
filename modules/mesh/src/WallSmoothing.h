#pragma once

// Raises the smallest dihedral angles of the prism-layer wall (WallMesh.cpp) where its offset surfaces crowd (the
// iliac crotch: the outward normals of a saddle converge, the prisms twist and leave slivers among their tets).
// Local optimization-based smoothing (Freitag and Ollivier-Gooch, Int. J. Numer. Meth. Eng. 40, 1997): a node of a
// poor element moves to raise the smallest dihedral angle of the elements around it, by a pattern search in the plane
// across a given direction only: across its offset direction for a node off the lumen (the wall keeps its
// thickness), in its tangent plane for a lumen node (it slides along the surface the pressure acts on); the nodes of
// the held ends stay. Lengths in mm.

#include "vsim/core/TetMesh.h"

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace vsim::mesh::detail {

/// Moves the free nodes of elements whose smallest dihedral angle is under `targetDeg` in the plane across
/// `direction[v]` (unit; zero for a node that stays), each at most `maxMoveMm[v]` from `home[v]` (where it was
/// built; the current positions when `home` is empty), never inverting an element; six sweeps at most. Returns the
/// smallest dihedral angle (degrees) of the mesh as it was given.
double raiseDihedralAngles(TetMesh& mesh, const std::vector<Eigen::Vector3d>& direction, double targetDeg,
                           const std::vector<double>& maxMoveMm, const std::vector<Eigen::Vector3d>& home = {});

} // namespace vsim::mesh::detail
