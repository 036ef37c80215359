#pragma once

// The linear (4-node) tetrahedron: constant strain, the standard strain-displacement matrix B (not the thesis's
// printed eq. 4.15, which is garbled; see SEED-NOTES.md), element stiffness K_e = V B^T D B (thesis eq. 4.9-4.11).

#include "vsim/sim/fem/ElasticMaterial.h"

#include <Eigen/Core>

#include <array>

namespace vsim::sim::fem {

using Matrix12d = Eigen::Matrix<double, 12, 12>;
using Vector12d = Eigen::Matrix<double, 12, 1>;
using StrainMatrix = Eigen::Matrix<double, 6, 12>;

/// Where an element's 3x3 block (a, b), a != b, sits among the 10 distinct ones the models store: the 4 diagonal
/// blocks first, then (0,1) (0,2) (0,3) (1,2) (1,3) (2,3); block (b, a) is its transpose.
inline constexpr int kUpperBlockIndex[4][4] = {{-1, 4, 5, 6}, {4, -1, 7, 8}, {5, 7, -1, 9}, {6, 8, 9, -1}};

/// What an element keeps from its rest shape.
struct TetRest
{
    Eigen::Matrix3d restEdgesInverse;  ///< inverse of [X1-X0, X2-X0, X3-X0] (1/m): F = [x1-x0, ...] * this
    Eigen::Matrix<double, 4, 3> gradients; ///< shape-function gradients, one row per node (1/m)
    double volume = 0.0;               ///< m^3
    Matrix12d stiffness;               ///< K_e = V B^T D B, N/m, node-major (x0 y0 z0 x1 ...)
};

/// Rest data of the tetrahedron with corners `rest` (m, positive orientation). Throws vsim::Error for a
/// degenerate or inverted element (volume <= 1e-6 of its edge length cubed).
TetRest restTetrahedron(const std::array<Eigen::Vector3d, 4>& rest, const ElasticMaterial& material);

/// The 6x12 strain-displacement matrix of shape-function gradients (Voigt xx, yy, zz, xy, yz, zx; engineering
/// shear).
StrainMatrix strainDisplacement(const Eigen::Matrix<double, 4, 3>& gradients);

} // namespace vsim::sim::fem
