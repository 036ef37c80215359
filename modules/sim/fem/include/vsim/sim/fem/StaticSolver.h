#pragma once

// Static equilibrium of the co-rotational model: f_elastic(x) + f_external = 0 for the free components, by
// repeated linearised solves R K R^T dx = f (rotations updated between them) by block-Jacobi conjugate gradients.
// Constrained components keep the positions they have (prescribed displacements
// are set before the call).

#include "vsim/sim/fem/CorotationalFem.h"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace vsim::sim::fem {

struct StaticSolveReport
{
    int updates = 0;           ///< linearised solves
    int cgIterations = 0;      ///< summed over the solves
    double forceResidual = 0.0; ///< |free residual force| / |free external force| (or / first residual) at the end
    bool converged = false;
};

/// Solves for equilibrium to `tolerance` (relative force residual) in at most `maxUpdates` linearised solves
/// of at most `cgMaxIterations` each. Throws vsim::Error when an element inverts.
StaticSolveReport solveStatic(CorotationalFem& model, const Eigen::VectorXd& externalForces,
                              const std::vector<std::uint8_t>& constrained, double tolerance = 1e-9,
                              int maxUpdates = 20, int cgMaxIterations = 20000);

} // namespace vsim::sim::fem
