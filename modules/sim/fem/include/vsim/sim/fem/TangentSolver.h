#pragma once

// One linear solve T dx = f per Newton update of the static solve (StaticSolver.h), by the strategy its settings
// name: conjugate gradients (block Jacobi, or the smoothed-aggregation V-cycle kept across updates by
// MultigridSetUpRule.h), a sparse direct factorisation per update (CHOLMOD of the symmetric part,
// UMFPACK LU), or GMRES on the full tangent preconditioned by a factorisation kept across updates near
// equilibrium. The last is the converged wall analysis's default; its preconditioner is, in this order:
// - CHOLMOD's Cholesky of the tangent's own symmetric part, follower load's stiffness included, once the force
//   residual is under tangentCholeskyBelow (0.7), and where it was found not positive definite only once the
//   residual is under a quarter of the one at which it failed (kRetryTangentBelow in TangentSolver.cpp): the
//   follower load's non-symmetric part is small (on cli_sac's thrombus wall GMRES took 4 iterations with it fresh
//   against 13-14 with the stand-in, and 13-20 with it kept for four more updates);
// - CHOLMOD's Cholesky of the model's definite stand-in for its tangent (StaticModel::assembleDefiniteTangent,
//   without the follower load's stiffness), built only when asked for: the first, overshooting updates from rest
//   leave regions compressed where the tangent's symmetric part is indefinite (12-50 iterations with it);
// - UMFPACK's LU of the tangent, where neither is positive definite or GMRES does not converge. Once GMRES has
//   not converged with the stand-in in a solve, the stand-in is not tried again while the force residual is over
//   tangentCholeskyBelow: far from equilibrium on the demo AAA wall (no thrombus, a 16 kPa load on a wide sac) it
//   failed at each update, 200 iterations (about 20 s) before each LU (RESULTS.md, 2026-12-02).
// The follower pressure's load stiffness makes the tangent non-symmetric, which GMRES takes to the 1e-8 the issue
// asks; CHOLMOD factorises the quadratic wall 2-4x faster than UMFPACK and solves it 2-10x faster (RESULTS.md); once
// the force residual is small the tangent hardly changes between updates, so one factorisation serves several.
// MultigridGmres, not a default: GMRES on the full tangent preconditioned by one smoothed-aggregation V-cycle of the
// model's definite stand-in (the finest level re-taken each update, the hierarchy kept by MultigridSetUpRule.h), no
// factorisation: the candidate for the GPU, which has no sparse direct solver. On cli_sac's thrombus wall it needs
// about 390 iterations an update (125 s against 47 s on 2 cores, RESULTS.md 2026-12-02); where the stand-in is far
// from an indefinite tangent it does not converge at all (nor does GMRES with the stand-in's Cholesky).

#include "vsim/sim/fem/AggregationMultigrid.h"
#include "vsim/sim/fem/BlockSparseMatrix.h"
#include "vsim/sim/fem/Gmres.h"
#include "vsim/sim/fem/MultigridSetUpRule.h"
#include "vsim/sim/fem/StaticSolver.h"

#include <Eigen/Core>

#include <cstdint>
#include <functional>
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
    /// (none yet, the residual above reuseBelow (above tangentCholeskyBelow where the kept one is the tangent's own
    /// Cholesky), or the last solve with the kept one took over reuseIterations).
    bool needsPreconditioner(double forceResidual) const;
    /// The model's definite stand-in for its tangent (without a follower load's stiffness), assembled when called.
    using StandIn = std::function<const BlockSparseMatrix&()>;
    /// Solves `tangent` dx = f; CholeskyGmres: with a fresh preconditioner when `fresh` (the order above; the
    /// tangent's own Cholesky only while `forceResidual` is under settings.tangentCholeskyBelow, the stand-in's
    /// where `standIn` is given), else the kept one with 3 x reuseIterations, then a fresh one if that did not
    /// converge; the first fresh one on the stand-in's Cholesky with settings.firstSolveBudget where that is set,
    /// `abandoned` when it does not converge within it. Throws vsim::Error when a factorisation fails (a part of the
    /// wall not held).
    TangentSolveResult solve(const BlockSparseMatrix& tangent, const Eigen::VectorXd& f, Eigen::VectorXd& dx,
                             bool fresh = true, const StandIn& standIn = {}, double forceResidual = 0.0);
    /// The tolerance a solve is judged against (direct solves: 1e-8 on their residual check).
    double tolerance() const;

private:
    GmresResult gmres(const BlockSparseMatrix& tangent, const Eigen::VectorXd& f, Eigen::VectorXd& dx, int budget);
    /// The first of the preconditioners above that factorises.
    void factorisePreconditioner(const BlockSparseMatrix& tangent, const StandIn& standIn, double forceResidual);
    void factoriseLu(const BlockSparseMatrix& tangent);
    AggregationMultigridSettings multigridSettings() const; ///< the defaults with the settings' Cancel poll

    const StaticSolveSettings& m_settings;
    std::vector<std::uint8_t> m_constrained;
    std::unique_ptr<SparseDirect> m_direct, m_lu;
    SparseDirect* m_preconditioner = nullptr; // the kept factorisation (CholeskyGmres)
    int m_lastIterations = 0;
    int m_solves = 0;              // CholeskyGmres solves with a fresh preconditioner so far
    bool m_tangentDefinite = true; // no Cholesky of the tangent's symmetric part has failed since the last that worked
    double m_indefiniteAt = 0.0;   // the force residual at which it last failed
    bool m_keptIsTangents = false; // the kept factorisation is the tangent's own Cholesky
    bool m_standInFailed = false;  // GMRES did not converge with the stand-in's Cholesky in this solve
    const Eigen::VectorXd* m_positions;
    KeptMultigrid m_ownMultigrid;  // ConjugateGradient with Multigrid, without settings.keptMultigrid
    KeptMultigrid& m_multigrid;    // the one in use
};

} // namespace vsim::sim::fem
