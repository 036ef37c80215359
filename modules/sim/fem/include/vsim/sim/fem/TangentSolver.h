#pragma once

// One linear solve T dx = f per Newton update of the static solve (StaticSolver.h), by the strategy its settings
// name: conjugate gradients (block Jacobi, or the smoothed-aggregation V-cycle kept across updates by
// MultigridSetUpRule.h), a sparse direct factorisation per update (CHOLMOD of the symmetric part,
// UMFPACK LU), or GMRES on the full tangent preconditioned by a factorisation kept across updates near
// equilibrium: CHOLMOD's Cholesky of the model's definite stand-in for its tangent (StaticModel::
// assembleDefiniteTangent, without the follower load's stiffness) where that is positive definite, else UMFPACK's
// LU of the tangent. The last is the converged wall
// analysis's default. The follower pressure's load stiffness makes the tangent non-symmetric, which GMRES takes to
// the 1e-8 the issue asks (12-26 iterations with a fresh Cholesky of the model's tangent on the thrombus wall);
// CHOLMOD factorises the quadratic wall 2-4x faster than UMFPACK and solves it 2-10x faster (RESULTS.md); once the
// force residual is small the tangent hardly changes between updates, so one factorisation serves several.

#include "vsim/sim/fem/BlockSparseMatrix.h"
#include "vsim/sim/fem/Gmres.h"
#include "vsim/sim/fem/MultigridSetUpRule.h"
#include "vsim/sim/fem/StaticSolver.h"

#include <Eigen/Core>

#include <cstdint>
#include <memory>
#include <vector>

namespace vsim::sim::fem {

class SparseDirect;

class TangentSolver
{
public:
    /// `pattern`: the tangent's; `constrained`: 3 per node (1 = held; those components of dx are 0); `positions`
    /// (m, 3 per node): the model's, read when a multigrid hierarchy is set up (its rigid-body modes; needed for
    /// ConjugateGradient with Multigrid, else vsim::Error).
    TangentSolver(const BlockSparseMatrix& pattern, const std::vector<std::uint8_t>& constrained,
                  const StaticSolveSettings& settings, const Eigen::VectorXd* positions = nullptr);
    ~TangentSolver();
    TangentSolver(const TangentSolver&) = delete;
    TangentSolver& operator=(const TangentSolver&) = delete;
    /// CholeskyGmres: whether the update with relative force residual `forceResidual` needs a fresh preconditioner
    /// (none yet, the residual above reuseBelow, or the last solve with the kept one took over reuseIterations).
    bool needsPreconditioner(double forceResidual) const;
    /// Solves `tangent` dx = f; CholeskyGmres: with a fresh preconditioner when `fresh` (CHOLMOD of the symmetric
    /// part of `material` where given, else of the tangent; UMFPACK's LU of the tangent where that is not positive
    /// definite or does not bring GMRES to its tolerance), else the kept one with 3 x reuseIterations, then a fresh
    /// one if that did not converge. `material`: the model's definite stand-in for its tangent, without a follower
    /// load's stiffness (whose symmetric part is indefinite where the load is large against a soft material, the
    /// thrombus at 120 mmHg).
    /// Throws vsim::Error when a factorisation fails (a part of the wall not held).
    TangentSolveResult solve(const BlockSparseMatrix& tangent, const Eigen::VectorXd& f, Eigen::VectorXd& dx,
                             bool fresh = true, const BlockSparseMatrix* material = nullptr);
    /// The tolerance a solve is judged against (direct solves: 1e-8 on their residual check).
    double tolerance() const;

private:
    GmresResult gmres(const BlockSparseMatrix& tangent, const Eigen::VectorXd& f, Eigen::VectorXd& dx, int budget);
    /// CHOLMOD of `symmetric` (the model's tangent, or the tangent itself), else UMFPACK's LU of `tangent`.
    void factorisePreconditioner(const BlockSparseMatrix& symmetric, const BlockSparseMatrix& tangent);
    void factoriseLu(const BlockSparseMatrix& tangent);

    const StaticSolveSettings& m_settings;
    std::vector<std::uint8_t> m_constrained;
    std::unique_ptr<SparseDirect> m_direct, m_lu;
    SparseDirect* m_preconditioner = nullptr; // the kept factorisation (CholeskyGmres)
    int m_lastIterations = 0;
    const Eigen::VectorXd* m_positions;
    KeptMultigrid m_ownMultigrid;  // ConjugateGradient with Multigrid, without settings.keptMultigrid
    KeptMultigrid& m_multigrid;    // the one in use
};

} // namespace vsim::sim::fem
