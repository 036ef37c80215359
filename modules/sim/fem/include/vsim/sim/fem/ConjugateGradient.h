#pragma once

// Preconditioned conjugate gradients for the symmetric positive (semi-)definite systems of the implicit step,
// with constrained degrees of freedom filtered out (Baraff & Witkin 1998, "modified PCG": the filter zeroes the
// constrained components of the residual and of every search direction, so they keep their starting value).

#include "vsim/sim/fem/AggregationMultigrid.h"
#include "vsim/sim/fem/BlockSparseMatrix.h"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace vsim::sim::fem {

struct ConjugateGradientResult
{
    int iterations = 0;
    double relativeResidual = 0.0; ///< |S(b - A x)| / |S b| at the end (/ the first residual when S b = 0)
    bool converged = false;
};

/// Solves A x = b from the starting guess in `x` (warm start) to |S(b - A x)| <= tolerance |S b| or
/// `maxIterations`, with the 3x3 block-diagonal (block Jacobi) preconditioner, or one V-cycle of `multigrid` (set
/// up with the same constraints, its finest level refreshed from `a`). `constrained` (one byte per degree of
/// freedom, empty: none) marks components that keep their value in `x`.
ConjugateGradientResult solveConjugateGradient(const BlockSparseMatrix& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                                               const std::vector<std::uint8_t>& constrained, double tolerance,
                                               int maxIterations, const AggregationMultigrid* multigrid = nullptr);

} // namespace vsim::sim::fem
