#pragma once

// The St. Venant-Kirchhoff element (thesis ch. 4.3: Green-Lagrange strain E = (F^T F - I) / 2, second
// Piola-Kirchhoff stress S = lambda tr(E) I + 2 mu E) for the linear tetrahedron: nodal forces f_a = -V F S g_a,
// the consistent tangent (material and geometric parts) and the energy V (lambda/2 tr(E)^2 + mu tr(E^2)).
// Rotation-invariant without a polar decomposition, but stiff under compression and softening past about 40 %
// compression; the co-rotational model is the default.

#include <Eigen/Core>

#include <array>

namespace vsim::sim::fem {

/// Forces (N, node-major) and the tangent's 10 distinct 3x3 blocks (the 4 diagonal ones, then (0,1) (0,2) (0,3)
/// (1,2) (1,3) (2,3); N/m) of an element with deformation gradient `f`, shape gradients `g` (1/m, row per node)
/// and rest volume `volume` (m^3).
void stVenantKirchhoffElement(const Eigen::Matrix3d& f, const Eigen::Matrix<double, 4, 3>& g, double volume,
                              double lambda, double mu, Eigen::Matrix<double, 12, 1>& forces,
                              std::array<Eigen::Matrix3d, 10>& blocks);

/// Elastic energy (J) of the element.
double stVenantKirchhoffEnergy(const Eigen::Matrix3d& f, double volume, double lambda, double mu);

/// Cauchy stress (Pa) sigma = F S F^T / det F.
Eigen::Matrix3d stVenantKirchhoffCauchy(const Eigen::Matrix3d& f, double lambda, double mu);

} // namespace vsim::sim::fem
