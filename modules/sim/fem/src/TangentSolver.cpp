#include "vsim/sim/fem/TangentSolver.h"

#include "vsim/core/Error.h"
#include "vsim/sim/fem/ConjugateGradient.h"
#include "vsim/sim/fem/SparseDirect.h"

#include <algorithm>

namespace vsim::sim::fem {
namespace {

constexpr double kDirectTolerance = 1e-8; // a direct solve's residual check
// The tangent's own Cholesky is tried again once the force residual is under this fraction of the one at which it
// was last found indefinite: on the demo AAA wall it failed at 0.5 at the start of the second load increment, and the
// stand-in's Cholesky then took 23-29 GMRES iterations an update to the end; tried again at 0.10 it factorised, and
// the last four updates took 1, 11, 12 and 13 (5.6 s against 16.6 s; the run 101.5 -> 90.1 s, RESULTS.md 2026-12-03).
constexpr double kRetryTangentBelow = 0.25;

void factoriseOrThrow(SparseDirect& direct, const BlockSparseMatrix& matrix, const std::function<void()>& whileWaiting)
{
    if (!direct.factorize(matrix, whileWaiting))
        throw Error("the tangent stiffness could not be factorised (a part of the wall is not held by the fixed ends, "
                    "or the load is past the wall's limit)");
}

} // namespace

TangentSolver::~TangentSolver() = default;

TangentSolver::TangentSolver(const BlockSparseMatrix& pattern, const std::vector<std::uint8_t>& constrained,
                             const StaticSolveSettings& settings, const Eigen::VectorXd* positions)
    : m_settings(settings), m_constrained(constrained), m_positions(positions),
      m_ownMultigrid{nullptr, MultigridSetUpRule(settings.multigridSetUpAgainFactor)},
      m_multigrid(settings.keptMultigrid ? *settings.keptMultigrid : m_ownMultigrid)
{
    if (((settings.linear == LinearSolver::ConjugateGradient && settings.cgPreconditioner == CgPreconditioner::Multigrid) ||
         settings.linear == LinearSolver::MultigridGmres) &&
        positions == nullptr)
        throw Error("the multigrid preconditioner needs the model's positions");
    if (settings.linear == LinearSolver::SparseLu)
        m_direct = std::make_unique<SparseDirect>(pattern, constrained, SparseDirect::Kind::GeneralLu);
    else if (settings.linear != LinearSolver::ConjugateGradient && settings.linear != LinearSolver::MultigridGmres)
        m_direct = std::make_unique<SparseDirect>(pattern, constrained, SparseDirect::Kind::SymmetricCholesky);
}

AggregationMultigridSettings TangentSolver::multigridSettings() const
{
    AggregationMultigridSettings settings;
    settings.afterLevel = m_settings.cancelPoll;
    return settings;
}

double TangentSolver::tolerance() const
{
    switch (m_settings.linear)
    {
    case LinearSolver::ConjugateGradient:
        return 0.1 * m_settings.tolerance;
    case LinearSolver::CholeskyGmres:
    case LinearSolver::MultigridGmres:
        return m_settings.linearTolerance;
    default:
        return kDirectTolerance;
    }
}

bool TangentSolver::needsPreconditioner(double forceResidual) const
{
    // The tangent's own Cholesky describes the tangent well enough to be kept wherever it would be tried again.
    const double keepBelow = m_keptIsTangents ? std::max(m_settings.reuseBelow, m_settings.tangentCholeskyBelow)
                                              : m_settings.reuseBelow;
    return m_settings.linear == LinearSolver::CholeskyGmres &&
           (!m_preconditioner || forceResidual > keepBelow || m_lastIterations > m_settings.reuseIterations);
}

void TangentSolver::factorisePreconditioner(const BlockSparseMatrix& tangent, const StandIn& standIn,
                                            double forceResidual)
{
    const auto cholesky = [this](const BlockSparseMatrix& matrix) {
        const bool ok = m_direct->factorize(matrix, m_settings.cancelPoll);
        if (ok)
            m_preconditioner = m_direct.get();
        m_keptIsTangents = false;
        return ok;
    };
    // A failed attempt costs up to a whole factorisation: the tangent's own only once the residual is under the
    // load, and once found indefinite not again until the residual is well under the one at which it failed.
    if ((m_tangentDefinite || forceResidual < kRetryTangentBelow * m_indefiniteAt) &&
        forceResidual <= m_settings.tangentCholeskyBelow)
    {
        if (cholesky(tangent))
        {
            m_keptIsTangents = m_tangentDefinite = true;
            return;
        }
        m_tangentDefinite = false;
        m_indefiniteAt = forceResidual;
    }
    const bool standInWorthTrying = !m_standInFailed || forceResidual <= m_settings.tangentCholeskyBelow;
    if ((standIn && standInWorthTrying && cholesky(standIn())) || (!standIn && m_tangentDefinite && cholesky(tangent)))
        return;
    // Not positive definite: the tangent's own LU (the LU of the matrix that failed would leave GMRES as far from
    // the tangent as the Cholesky would have: 7.5e-8 after 200 iterations on a 1,500-vertex AAA wall, RESULTS.md).
    factoriseLu(tangent);
}

void TangentSolver::factoriseLu(const BlockSparseMatrix& tangent)
{
    // The symmetric part is not positive definite (regions a long step compressed, or the follower pressure's load
    // stiffness where the caller gave no tangent without it; a shifted Cholesky left GMRES at 1e-4 after 200
    // iterations, RESULTS.md): the tangent's own LU for this update.
    if (!m_lu)
        m_lu = std::make_unique<SparseDirect>(tangent, m_constrained, SparseDirect::Kind::GeneralLu);
    factoriseOrThrow(*m_lu, tangent, m_settings.cancelPoll);
    m_preconditioner = m_lu.get();
}

GmresResult TangentSolver::gmres(const BlockSparseMatrix& tangent, const Eigen::VectorXd& f, Eigen::VectorXd& dx,
                                 int budget)
{
    return solveGmres(
        tangent, f, dx, m_constrained,
        [this](const Eigen::VectorXd& r, Eigen::VectorXd& z) { m_preconditioner->solveOnly(r, z); },
        m_settings.linearTolerance, budget);
}

TangentSolveResult TangentSolver::solve(const BlockSparseMatrix& tangent, const Eigen::VectorXd& f, Eigen::VectorXd& dx,
                                        bool fresh, const StandIn& standIn, double forceResidual)
{
    TangentSolveResult result;
    dx = Eigen::VectorXd::Zero(f.size());
    switch (m_settings.linear)
    {
    case LinearSolver::ConjugateGradient:
    {
        if (m_settings.cgPreconditioner == CgPreconditioner::Multigrid)
        {
            if (!m_multigrid.hierarchy)
            {
                m_multigrid.hierarchy =
                    std::make_unique<AggregationMultigrid>(tangent, *m_positions, m_constrained, multigridSettings());
                m_multigrid.rule.setUp();
            }
            else
                m_multigrid.hierarchy->refreshFinest(tangent);
        }
        const ConjugateGradientResult cg = solveConjugateGradient(tangent, f, dx, m_constrained, tolerance(),
                                                                  m_settings.cgMaxIterations,
                                                                  m_multigrid.hierarchy.get());
        if (m_multigrid.hierarchy && m_multigrid.rule.setUpAgainAfter(cg.iterations))
            m_multigrid.hierarchy.reset(); // set up again from the next update's tangent
        result.iterations = cg.iterations;
        result.relativeResidual = cg.relativeResidual;
        result.converged = cg.converged;
        return result;
    }
    case LinearSolver::CholeskyGmres:
    {
        GmresResult solved;
        if (!fresh && m_preconditioner)
        {
            // A kept factorisation gets a short budget: past it, a fresh one is cheaper than more iterations.
            solved = gmres(tangent, f, dx, 3 * m_settings.reuseIterations);
            result.iterations = solved.iterations;
            m_lastIterations = solved.converged ? solved.iterations : m_settings.reuseIterations + 1;
        }
        if (fresh || !m_preconditioner || !solved.converged)
        {
            factorisePreconditioner(tangent, standIn, forceResidual);
            result.factorised = true;
            // The first update on the stand-in's Cholesky with its own budget: past it the load step is too large.
            const bool trial = m_solves == 0 && m_settings.firstSolveBudget > 0 && standIn &&
                               m_preconditioner == m_direct.get() && !m_keptIsTangents;
            solved = gmres(tangent, f, dx, trial ? m_settings.firstSolveBudget : m_settings.gmresMaxIterations);
            result.iterations += solved.iterations;
            ++m_solves;
            if (trial && !solved.converged)
            {
                result.abandoned = true;
                result.relativeResidual = solved.relativeResidual;
                return result;
            }
            if (!solved.converged && m_preconditioner == m_direct.get())
            {
                m_standInFailed = m_standInFailed || (standIn && !m_keptIsTangents);
                factoriseLu(tangent); // the symmetric part no longer describes the tangent
                solved = gmres(tangent, f, dx, m_settings.gmresMaxIterations);
                result.iterations += solved.iterations;
            }
            m_lastIterations = solved.iterations;
        }
        result.relativeResidual = solved.relativeResidual;
        result.converged = solved.converged;
        return result;
    }
    case LinearSolver::MultigridGmres:
    {
        // The V-cycle's finest level is the stand-in itself, re-taken each update; its coarse levels stay as set up
        // until the iterations say a new set-up pays (MultigridSetUpRule.h).
        const BlockSparseMatrix& standInMatrix = standIn ? standIn() : tangent;
        if (!m_multigrid.hierarchy)
        {
            m_multigrid.hierarchy =
                std::make_unique<AggregationMultigrid>(standInMatrix, *m_positions, m_constrained, multigridSettings());
            m_multigrid.rule.setUp();
            result.factorised = true;
        }
        else
            m_multigrid.hierarchy->refreshFinest(standInMatrix);
        const AggregationMultigrid& cycle = *m_multigrid.hierarchy;
        const GmresResult solved = solveGmres(
            tangent, f, dx, m_constrained,
            [&](const Eigen::VectorXd& r, Eigen::VectorXd& z) { cycle.apply(standInMatrix, r, z); },
            m_settings.linearTolerance, m_settings.gmresMaxIterations);
        if (m_multigrid.rule.setUpAgainAfter(solved.iterations))
            m_multigrid.hierarchy.reset();
        result.iterations = solved.iterations;
        result.relativeResidual = solved.relativeResidual;
        result.converged = solved.converged;
        return result;
    }
    default:
        factoriseOrThrow(*m_direct, tangent, m_settings.cancelPoll);
        result.relativeResidual = m_direct->solve(f, dx);
        result.factorised = true;
        result.converged = result.relativeResidual <= kDirectTolerance;
        return result;
    }
}

} // namespace vsim::sim::fem
