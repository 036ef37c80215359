#pragma once

// Edge flips in the prism-layer wall (WallMesh.cpp): an interior edge with exactly four elements of one material
// around it (the diagonal of a quad face that two prisms share, chosen by the smallest-index rule whatever the
// shape) is swapped for the other diagonal of its ring when that raises the smallest dihedral angle of the four:
// the 4-4 flip of tetrahedral mesh improvement (Freitag and Ollivier-Gooch, Int. J. Numer. Meth. Eng. 40, 1997;
// Klingner and Shewchuk, Proc. 16th Int. Meshing Roundtable, 2007). The four elements' envelope stays, so every
// boundary face (the lumen, where the pressure acts; the outer surface; the held ends) and every material face
// stays too. The new elements take the old ones' slots, nearest centroids first: the element count and each
// slot's material are unchanged, and an element's index still names the prism it lies in (index / 3).

#include "vsim/core/TetMesh.h"

#include <cstddef>
#include <vector>

namespace vsim::mesh::detail {

/// Flips the edges of the elements whose smallest dihedral angle is under `targetDeg` (above), `material` per
/// element (empty: one material); up to four sweeps. Returns the number of flips.
std::size_t flipEdgesOfFour(TetMesh& mesh, const std::vector<double>& material, double targetDeg);

} // namespace vsim::mesh::detail
