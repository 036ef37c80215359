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
    std::array<int, 3> cells{};            ///< hexahedra per axis; node (i, j, k) is i + (n0+1)(j + (n1+1) k)
    int node(int i, int j, int k) const { return i + (cells[0] + 1) * (j + (cells[1] + 1) * k); }
};

/// A box [0, size] (m) of cells[0] x cells[1] x cells[2] hexahedra.
StructuredTetMesh boxTetMesh(const Eigen::Vector3d& size, const std::array<int, 3>& cells);

/// A sector of a thick-walled tube around z: radii inner..outer (m), angles 0..angle (rad), heights 0..height (m),
/// cells along r, angle and z (node index i runs along r, j along the angle, k along z).
StructuredTetMesh annulusSectorTetMesh(double inner, double outer, double angle, double height,
                                       const std::array<int, 3>& cells);

} // namespace vsim::sim::fem
