#pragma once

// A direct solve of an assembled 3x3-block matrix on the free degrees of freedom: the matrix copied into a
// compressed-column matrix with the constrained rows and columns left out (the copy's pattern and the block entry
// behind each value found once), a fill-reducing ordering found once for the pattern, and a factorisation per
// matrix by SuiteSparse: CHOLMOD's supernodal Cholesky for a symmetric
// positive definite matrix, UMFPACK's multifrontal LU for the tangent with the follower pressure's load
// stiffness, which is not symmetric (both on BLAS). The converged equilibrium of the physiological analysis
// (issue 16) needs it: conjugate gradients on a thin wall stall far above 1e-8, and Eigen's own simplicial LDL^T
// and supernodal LU took about 20 s and 40 s per factorisation on 15k quadratic tets (31k nodes) on 2 cores.

#include "vsim/sim/fem/BlockSparseMatrix.h"

#include <Eigen/SparseCore>

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace vsim::sim::fem {

class SparseDirect
{
public:
    enum class Kind
    {
        SymmetricCholesky, ///< Cholesky of the symmetric part (A + A^T) / 2, which must be positive definite
        GeneralLu      ///< any non-singular matrix
    };
    /// The free degrees of freedom: `constrained` (3 per node, 1 = fixed; empty: none) of the matrix's nodes.
    SparseDirect(const BlockSparseMatrix& pattern, const std::vector<std::uint8_t>& constrained, Kind kind);
    ~SparseDirect();
    SparseDirect(const SparseDirect&) = delete;
    SparseDirect& operator=(const SparseDirect&) = delete;
    /// Factorises `matrix` (the pattern's). Returns false when the factorisation fails (singular, or not positive
    /// definite for the Cholesky kind). With `whileWaiting` the factorisation runs on a thread of its own and
    /// whileWaiting is called every 50 ms until it ends; when it throws (vsim::Cancelled: a Cancel during seconds
    /// of factorisation), the exception leaves at once, the factorisation is left to finish unseen and dropped,
    /// and this object holds no factors until the next factorize().
    bool factorize(const BlockSparseMatrix& matrix, const std::function<void()>& whileWaiting = {});
    /// x = A^-1 b on the free components; constrained components of x are 0. Returns ||A x - b|| / ||b|| (free).
    double solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const;
    /// The same without the residual check (a preconditioner's solve).
    void solveOnly(const Eigen::VectorXd& b, Eigen::VectorXd& x) const;
    std::size_t freeCount() const { return m_freeDofs.size(); }
    Kind kind() const { return m_kind; }

private:
    struct Factors;
    /// Per stored value of the copy: the slots of block (row node, column node) and of its transpose, and the
    /// entry in the first.
    struct Source
    {
        std::uint32_t slot, transposedSlot;
        std::uint8_t row, column;
    };
    void copyValues(const BlockSparseMatrix& matrix);
    void configure(Factors& factors) const; ///< the solvers' settings on fresh factors

    Kind m_kind;
    std::vector<std::int64_t> m_freeIndex; // per degree of freedom: its free index, -1 when constrained
    std::vector<std::int64_t> m_freeDofs;  // per free index: the degree of freedom
    Eigen::SparseMatrix<double> m_matrix; // the free part (the Cholesky kind: the lower triangle of its symmetric part)
    std::vector<Source> m_sources;
    std::shared_ptr<Factors> m_factors; ///< shared with a factorisation's thread while it runs
    bool m_analysed = false, m_naturalOrdering = false;
};

} // namespace vsim::sim::fem
