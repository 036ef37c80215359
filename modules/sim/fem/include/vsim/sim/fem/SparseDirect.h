#pragma once

// A direct solve of an assembled 3x3-block matrix on the free degrees of freedom: the matrix copied into Eigen's
// compressed format with the constrained rows and columns left out, a fill-reducing ordering found once for the
// pattern, and a factorisation per matrix: simplicial LDL^T (AMD) for a symmetric one, supernodal LU (COLAMD) for
// the tangent with the follower pressure's load stiffness, which is not symmetric. The converged equilibrium of
// the physiological analysis (issue 16) needs it: conjugate gradients on a thin wall stall far above 1e-8.

#include "vsim/sim/fem/BlockSparseMatrix.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

#include <cstdint>
#include <vector>

namespace vsim::sim::fem {

class SparseDirect
{
public:
    enum class Kind
    {
        SymmetricLdlt, ///< reads the lower triangle; the matrix must be symmetric (positive definite in practice)
        GeneralLu      ///< any non-singular matrix
    };
    /// The free degrees of freedom: `constrained` (3 per node, 1 = fixed; empty: none) of the matrix's nodes.
    SparseDirect(const BlockSparseMatrix& pattern, const std::vector<std::uint8_t>& constrained, Kind kind);
    /// Factorises `matrix` (the pattern's). Returns false when the factorisation fails (singular, or not positive
    /// definite for LDL^T).
    bool factorize(const BlockSparseMatrix& matrix);
    /// x = A^-1 b on the free components; constrained components of x are 0. Returns ||A x - b|| / ||b|| (free).
    double solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const;
    std::size_t freeCount() const { return m_freeDofs.size(); }

private:
    Eigen::SparseMatrix<double> copy(const BlockSparseMatrix& matrix) const;

    Kind m_kind;
    std::vector<std::int64_t> m_freeIndex; // per degree of freedom: its free index, -1 when constrained
    std::vector<std::int64_t> m_freeDofs;  // per free index: the degree of freedom
    Eigen::SparseMatrix<double> m_matrix;
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> m_ldlt;
    Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> m_lu;
    bool m_analysed = false;
};

} // namespace vsim::sim::fem
