#pragma once

// Smoothed-aggregation algebraic multigrid (Vanek, Mandel & Brezina 1996) for the elastic systems of the wall
// solver, used as a PCG preconditioner: one V-cycle per application, with Chebyshev smoothing of the block-Jacobi
// scaled operator (Adams, Brezina, Hu & Tuminaro 2003). The near-null space is the six rigid-body modes of the
// nodes, so a coarse level corrects the translations and rotations of whole aggregates, which block Jacobi alone
// spreads over hundreds of iterations in a thin wall.
//
// Set up on the host from one matrix. The finest level is the caller's current matrix at every application (its
// diagonal blocks re-taken by refreshFinest); the prolongators and coarse operators stay as set up. That keeps the
// V-cycle a fixed symmetric positive definite operator, so PCG stays valid while the co-rotational matrix turns
// with the wall; its iteration count says when a new set-up pays. The CUDA backend uploads the same hierarchy and
// runs the same cycle.

#include "vsim/sim/fem/BlockSparseMatrix.h"

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <cstdint>
#include <functional>
#include <vector>

namespace vsim::sim::fem {

struct AggregationMultigridSettings
{
    double strengthThreshold = 0.08; ///< strong coupling: |A_ij| >= theta sqrt(|A_ii| |A_jj|), block Frobenius norms
    int coarsestDofs = 1000;         ///< below this many unknowns the level is solved directly
    int maxLevels = 10;
    int chebyshevDegree = 2;            ///< pre- and post-smoothing polynomial degree
    double chebyshevLowerFraction = 1.0 / 30.0; ///< the smoothed interval [fraction, 1] x the largest eigenvalue
    std::function<void()> afterLevel; ///< called as each level is set up (a Cancel's poll: it may throw)
};

using SparseRows = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;

struct MultigridLevel
{
    int dofs = 0;
    SparseRows matrix;       ///< the Galerkin operator (empty at level 0: the caller's matrix, masked)
    SparseRows prolongation; ///< from the next coarser level (rows: this level's unknowns; empty on the coarsest)
    SparseRows restriction;  ///< the prolongation's transpose
    std::vector<int> blockStart;       ///< diagonal block k holds unknowns [blockStart[k], blockStart[k + 1])
    std::vector<int> inverseStart;     ///< block k's inverse at inverseBlocks[inverseStart[k]], row-major
    std::vector<double> inverseBlocks; ///< the inverses of the diagonal blocks (block Jacobi)
    double largestEigenvalue = 0.0;    ///< of D^-1 A, estimated and raised by 10 % (Chebyshev's upper bound)
};

class AggregationMultigrid
{
public:
    /// The hierarchy of `a` (3 unknowns per node at `positions`, m), with the unknowns marked in `constrained` (one
    /// byte per unknown; empty: none) held: their rows and columns are the identity's.
    AggregationMultigrid(const BlockSparseMatrix& a, const Eigen::VectorXd& positions,
                         const std::vector<std::uint8_t>& constrained, AggregationMultigridSettings settings = {});

    /// Re-takes the finest level's diagonal blocks from `a` (same pattern as at set-up).
    void refreshFinest(const BlockSparseMatrix& a);
    /// z = one V-cycle applied to r, the finest level's operator being `a` (masked); z is zero where held.
    void apply(const BlockSparseMatrix& a, const Eigen::VectorXd& r, Eigen::VectorXd& z) const;

    const std::vector<MultigridLevel>& levels() const { return m_levels; }
    const AggregationMultigridSettings& settings() const { return m_settings; }
    /// The coarsest level's inverse, dense (the CUDA backend applies it as a product).
    Eigen::MatrixXd coarsestInverse() const;
    /// 1 at a free unknown of the finest level, 0 at a held one.
    const Eigen::VectorXd& freeMask() const { return m_free; }
    /// Stored entries of all levels over those of the finest (the finest counted as scalar entries).
    double operatorComplexity() const { return m_operatorComplexity; }

private:
    void multiply(const BlockSparseMatrix& a, std::size_t level, const Eigen::VectorXd& x, Eigen::VectorXd& y) const;
    void smooth(const BlockSparseMatrix& a, std::size_t level, Eigen::VectorXd& x, const Eigen::VectorXd& b,
                bool fromZero) const;
    void cycle(const BlockSparseMatrix& a, std::size_t level, const Eigen::VectorXd& b, Eigen::VectorXd& x) const;

    AggregationMultigridSettings m_settings;
    std::vector<MultigridLevel> m_levels;
    Eigen::VectorXd m_free;
    Eigen::LLT<Eigen::MatrixXd> m_coarsest;
    double m_operatorComplexity = 1.0;
};

} // namespace vsim::sim::fem
