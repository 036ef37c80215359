#pragma once

// The rotation of an element's deformation gradient (the R of F = R S, polar decomposition) by the iteration of
// Mueller, Bender, Chentanez & Macklin 2016, "A robust method to extract the rotational part of deformations"
// (MIG '16, eq. 3-5): it maximises tr(R^T F) and warm-starts from the previous step's rotation, where an SVD per
// element would dominate the step. Near the solution the step is scaled by the exact Hessian (a Newton step:
// quadratic convergence, 2-3 iterations per time step instead of their linear rate of 1/3).

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace vsim::sim::fem {

/// Updates `rotation` (unit quaternion, warm start) to the rotation closest to `deformation`; at most
/// `maxIterations` steps, stopping once the correction angle is below `tolerance` radians.
void extractRotation(const Eigen::Matrix3d& deformation, Eigen::Quaterniond& rotation, int maxIterations = 20,
                     double tolerance = 1e-10);

} // namespace vsim::sim::fem
