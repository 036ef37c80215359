#pragma once

// Structured tetrahedral meshes for the validation cases and benchmarks: a grid of hexahedra, each split into six
// tetrahedra around its main diagonal (Kuhn / Freudenthal), which conform across neighbouring cells. SI units.

#include <Eigen/Core>

#include <array>
#include <vector>

namespace vsim::sim::fem {

struct StructuredTetMesh
{
    std::vector<Eigen::Vector3d> points;   ///< m
    std::vector<std::array<int, 4>> tets;  ///< positively oriented
    std::array<int, 3> cells{};            ///< hexahedra per axis
    bool periodicJ = false;                ///< a full tube: j wraps around (no seam nodes)
    /// Node (i, j, k): i + (n0 + 1)(j + nj k), nj = n1 + 1 (or n1 when periodic, j taken modulo n1).
    int node(int i, int j, int k) const
    {
        const int nodesJ = periodicJ ? cells[1] : cells[1] + 1;
        return i + (cells[0] + 1) * (j % nodesJ + nodesJ * k);
    }
};

/// A box [0, size] (m) of cells[0] x cells[1] x cells[2] hexahedra.
StructuredTetMesh boxTetMesh(const Eigen::Vector3d& size, const std::array<int, 3>& cells);

/// A closed tube wall around z: radii inner..outer (m), length (m); cells along r, around (>= 3) and along z.
StructuredTetMesh tubeWallTetMesh(double inner, double outer, double length, const std::array<int, 3>& cells);

/// A sector of a thick-walled tube around z: radii inner..outer (m), angles 0..angle (rad), heights 0..height (m),
/// cells along r, angle and z (node index i runs along r, j along the angle, k along z).
StructuredTetMesh annulusSectorTetMesh(double inner, double outer, double angle, double height,
                                       const std::array<int, 3>& cells);

} // namespace vsim::sim::fem
