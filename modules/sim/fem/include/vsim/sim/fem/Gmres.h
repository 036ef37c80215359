#pragma once

// Restarted GMRES (Saad & Schultz 1986) with right preconditioning, for the non-symmetric Newton tangent (the
// follower pressure's load stiffness) on the free degrees of freedom: constrained components of the right-hand
// side, of every Krylov vector and of x stay 0. Right preconditioning minimises the true residual |b - A x|, so
// the tolerance is on the residual the issue asks for (relative 1e-8), not on a preconditioned one; the true
// residual is recomputed at every restart and at the end.

#include "vsim/sim/fem/BlockSparseMatrix.h"

#include <Eigen/Core>

#include <cstdint>
#include <functional>
#include <vector>

namespace vsim::sim::fem {

struct GmresResult
{
    int iterations = 0;            ///< matrix-vector products (one per Krylov vector)
    double relativeResidual = 0.0; ///< |b - A x| / |b| on the free components, recomputed at the end
    bool converged = false;
};

/// z = M^-1 r (an approximation of A^-1; constrained components of z 0).
using Preconditioner = std::function<void(const Eigen::VectorXd& r, Eigen::VectorXd& z)>;

/// Solves A x = b from x = 0 to |b - A x| <= tolerance |b| (free components) or `maxIterations`.
GmresResult solveGmres(const BlockSparseMatrix& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                       const std::vector<std::uint8_t>& constrained, const Preconditioner& preconditioner,
                       double tolerance, int maxIterations, int restart = 50);

} // namespace vsim::sim::fem
