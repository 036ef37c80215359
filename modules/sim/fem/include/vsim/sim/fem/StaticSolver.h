#pragma once

// Static equilibrium f_elastic(x) + f_external(x) = 0 for the free components, by repeated linearised solves
// T dx = f, with T the model's tangent (the co-rotational model: R K R^T, optionally + the rotations' derivative,
// then a full Newton iteration; the quadratic hyperelastic model: its consistent tangent) - d f_ext / dx (a
// follower load's stiffness), the element pass and the loads updated between them, each by conjugate gradients
// (block Jacobi or the smoothed-aggregation V-cycle; on the symmetric part alone, without the load's stiffness: a
// modified Newton iteration that takes more updates), a sparse direct factorisation (SparseDirect.h)
// or GMRES with a kept Cholesky preconditioner (TangentSolver.h), with a line search. Constrained components keep
// the positions they have (prescribed displacements are set before the call). A model may assemble and solve its
// tangent elsewhere (the CUDA static wall, StaticModel::solvesItsTangent): the same iteration, its linear solves on
// the GPU.

#include "vsim/sim/fem/BackwardEuler.h"
#include "vsim/sim/fem/CorotationalFem.h"
#include "vsim/sim/fem/MultigridSetUpRule.h"

#include <Eigen/Core>

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace vsim::sim::fem {

struct StaticSolveSettings;

/// A smoothed-aggregation hierarchy kept across the static solves of one mesh (the quasi-static ramp's equilibria):
/// set up at the first update that needs one and again by its rule; the owner resets it when the mesh changes.
struct KeptMultigrid
{
    std::unique_ptr<AggregationMultigrid> hierarchy;
    MultigridSetUpRule rule{2.0}; ///< BackwardEulerSettings::multigridSetUpAgainFactor's default
};

struct TangentSolveResult
{
    int iterations = 0;            ///< Krylov iterations (0: a direct solve)
    double relativeResidual = 0.0; ///< |f - T dx| / |f| on the free components
    bool factorised = false;       ///< this solve factorised the tangent (MultigridGmres: set up its hierarchy)
    bool converged = false;        ///< the residual reached the solve's tolerance
    /// StaticSolveSettings::firstSolveBudget ran out: no direction, and the solve gives up (not a linear solve's
    /// result: the run status does not record it).
    bool abandoned = false;
};

/// What the static solve needs of a model (CorotationalFem through an adapter, QuadraticFem directly).
class StaticModel
{
public:
    virtual ~StaticModel() = default;
    /// Current positions, 3 entries per node (m).
    virtual Eigen::VectorXd& positions() = 0;
    /// The element pass at the current positions; returns the number of inverted elements.
    virtual std::size_t updateElements() = 0;
    /// Elastic forces (N) of the last element pass.
    virtual Eigen::VectorXd elasticForces() const = 0;
    /// Centroid (m) of the first inverted element of the last pass; NaN when none.
    virtual Eigen::Vector3d firstInvertedCentroid() const = 0;
    /// The pattern of the model's matrices.
    virtual BlockSparseMatrix makeMatrix() const = 0;
    /// Writes the tangent -d f_elastic / dx of the last element pass into `matrix` (the pattern's); `consistent`:
    /// the full derivative where the model's usual one leaves a part out (the co-rotational rotations).
    virtual void assembleTangent(BlockSparseMatrix& matrix, bool consistent) const = 0;
    /// The symmetric positive definite stand-in for the tangent that the GMRES preconditioner factorises by
    /// Cholesky (without a follower load's stiffness): by default the usual tangent; a model whose tangent turns
    /// indefinite (regions a long Newton step compressed) projects its element parts onto their positive parts.
    virtual void assembleDefiniteTangent(BlockSparseMatrix& matrix, bool consistent) const
    {
        assembleTangent(matrix, consistent);
    }
    /// Whether the model assembles and solves its own tangent (the consistent one, symmetric: ConjugateGradient
    /// only); then makeMatrix and assembleTangent are not called.
    virtual bool solvesItsTangent() const { return false; }
    /// Solves T dx = f with T the consistent tangent of the last element pass, by PCG with `settings`' preconditioner
    /// from dx = 0 to |f - T dx| <= tolerance |f| on the free components or settings.cgMaxIterations.
    virtual TangentSolveResult solveTangent(const Eigen::VectorXd& f, Eigen::VectorXd& dx, double tolerance,
                                            const StaticSolveSettings& settings);
};

struct StaticSolveReport
{
    int updates = 0;            ///< linearised solves
    int cgIterations = 0;       ///< Krylov iterations summed over the solves (0 for the direct solvers)
    int factorisations = 0;     ///< sparse factorisations (direct solvers and the GMRES preconditioner)
    double forceResidual = 0.0; ///< |free residual force| / |free external force| (or / first residual) at the end
    double worstLinearResidual = 0.0; ///< largest relative residual of a linear solve (direct: its check A x - b)
    std::vector<double> residualHistory; ///< the relative force residual before each update and at the end
    std::vector<int> linearIterations;   ///< per update: the Krylov iterations of its linear solve (0: direct)
    std::vector<double> linearResiduals; ///< per update: its linear solve's relative residual
    double smallestStep = 1.0;  ///< the smallest fraction of a Newton step the line search took
    bool stalled = false;       ///< given up: the line search's step fell under StaticSolveSettings::stallStep,
                                ///< or abandonedFirstSolve
    bool abandonedFirstSolve = false; ///< given up: the first update's GMRES did not converge within firstSolveBudget
    bool converged = false;
};

enum class LinearSolver
{
    ConjugateGradient, ///< PCG (cgPreconditioner) to 0.1 x the force tolerance, at most cgMaxIterations, on the
                       ///< model's tangent without the follower load's stiffness (symmetric; with rotationStiffness
                       ///< the co-rotational energy's Hessian, which is symmetric too)
    SparseCholesky,    ///< CHOLMOD supernodal Cholesky of the tangent's symmetric part, ordering once, per update
    SparseLu,          ///< UMFPACK multifrontal LU (the tangent with a follower load's stiffness)
    CholeskyGmres,     ///< GMRES on the full tangent to linearTolerance, preconditioned by CHOLMOD's Cholesky of
                       ///< the model's tangent (TangentSolver.h), kept across updates near equilibrium
    MultigridGmres     ///< GMRES on the full tangent to linearTolerance, preconditioned by one smoothed-aggregation
                       ///< V-cycle of the model's definite stand-in (no factorisation: the candidate for the GPU,
                       ///< not a default)
};

/// Whether `linear` is one of the GMRES solves on the full tangent (they take the model's definite stand-in).
inline bool solvesByGmres(LinearSolver linear)
{
    return linear == LinearSolver::CholeskyGmres || linear == LinearSolver::MultigridGmres;
}

/// Settings of solveStatic; set the members by name (the defaults are the validation cases').
struct StaticSolveSettings
{
    double tolerance = 1e-9; ///< relative force residual to reach
    int maxUpdates = 20;
    LinearSolver linear = LinearSolver::ConjugateGradient;
    int cgMaxIterations = 20000;
    /// ConjugateGradient: block Jacobi, or one smoothed-aggregation V-cycle (AggregationMultigrid.h) set up from
    /// the first update's tangent and again by MultigridSetUpRule.h with multigridSetUpAgainFactor.
    CgPreconditioner cgPreconditioner = CgPreconditioner::BlockJacobi;
    double multigridSetUpAgainFactor = 2.0;
    /// Multigrid: the hierarchy to use and keep across solves (its own rule then applies); null: one per solve.
    KeptMultigrid* keptMultigrid = nullptr;
    double linearTolerance = 1e-8; ///< CholeskyGmres: each linear solve's relative residual |T dx - f| / |f|
    int gmresMaxIterations = 200;
    /// CholeskyGmres: refactorise after a solve that needed more (a fresh CHOLMOD factorisation of the quadratic
    /// thrombus wall costs about 27 iterations with it, and a fresh solve takes 12-26: RESULTS.md, 2026-11-27)
    int reuseIterations = 25;
    double reuseBelow = 0.1;       ///< CholeskyGmres: keep a factorisation only below this force residual
    /// CholeskyGmres: factorise the tangent's own symmetric part (follower load's stiffness included) below this
    /// force residual, before the model's definite stand-in, and keep that factorisation below it (TangentSolver.h;
    /// at the start, residual 1, the thrombus wall's was indefinite: 7.4 s lost, RESULTS.md 2026-12-01)
    double tangentCholeskyBelow = 0.7;
    /// The model's consistent tangent (co-rotational: + the derivative of the element rotations,
    /// CorotationalFem::addRotationStiffness): a full Newton iteration (quadratic convergence), with a direct
    /// solver that takes a non-symmetric matrix where the tangent is not symmetric.
    bool rotationStiffness = false;
    /// Line search: the step where the residual has no component along the Newton direction (Matthies & Strang
    /// 1979; for stiffening hyperelastic laws) instead of backtracking on the residual norm.
    bool directionalLineSearch = false;
    /// Give up (not converged, `stalled`) once a line search's step is under this fraction of the Newton step (0:
    /// never). Past a stiffening law's overshoot the tangent can be indefinite and the Newton
    /// direction lead nowhere: on the demo AAA wall at the full pressure from rest the steps were 0.0018, 2e-5, 4e-5
    /// ... for 15 updates at a force residual of 8.3, where the caller's smaller load increment converges.
    double stallStep = 0.0;
    /// CholeskyGmres: the first update's GMRES iterations with the Cholesky of the model's definite stand-in (0: no
    /// limit of its own; gmresMaxIterations, then the tangent's LU). Where they do not suffice, the follower load's
    /// stiffness outweighs the wall's at this load step, and the solve gives up at once (not converged, `stalled`,
    /// `abandonedFirstSolve`) for the caller to take a smaller one, without the LU: on the demo AAA wall at the full
    /// pressure from rest 200 iterations left 2.3e-7 and the increment then stalled (4 + 14 + 14 s lost), at half
    /// the pressure 48 sufficed; cli_sac's thrombus wall takes 25 at the full pressure (RESULTS.md, 2026-12-02).
    int firstSolveBudget = 0;
    /// Called with the update count and the relative force residual each time a residual is computed (progress;
    /// it may throw vsim::Cancelled, which leaves the model at the last state evaluated).
    std::function<void(int updates, double forceResidual)> afterResidual;
    /// Called while a preconditioner is set up, seconds each on a clinical wall: every 50 ms of a direct
    /// factorisation (SparseDirect.h) and after each level of a multigrid hierarchy (AggregationMultigrid.h). It may
    /// throw vsim::Cancelled, which leaves at once and the model at the last state evaluated. Empty: the
    /// factorisations run on the calling thread.
    std::function<void()> cancelPoll;
};

/// A co-rotational model whose static solve runs elsewhere (the CUDA static wall): it solves its own tangent and
/// keeps what it set up (its multigrid hierarchy) across solves of the same mesh.
class RemoteStaticModel : public StaticModel
{
public:
    /// Takes the positions and the element rotations (the rotation extraction's warm start) of `model`, which has
    /// the mesh this one was made from.
    virtual void takeStateOf(const CorotationalFem& model) = 0;
};

/// Makes a model that solves its own tangent elsewhere from the co-rotational model's current state and its
/// constrained components (3 per node, 1 = held). Throws vsim::Error when it cannot.
using StaticModelFactory = std::function<std::unique_ptr<RemoteStaticModel>(
    const CorotationalFem& model, const std::vector<std::uint8_t>& constrained)>;

/// External forces (N, 3 per node) at the given positions (m): a follower pressure depends on them.
using ExternalForces = std::function<Eigen::VectorXd(const Eigen::VectorXd& positions)>;
/// Subtracts d f_ext / dx at the given positions from the tangent (a follower load's stiffness).
using ExternalStiffness = std::function<void(const Eigen::VectorXd& positions, BlockSparseMatrix& tangent)>;

/// Solves for equilibrium under `external` (empty: no load, prescribed displacements alone), each step shortened
/// (halved) until it inverts no element and lowers the residual force. Throws vsim::Error when an element is
/// inverted at the start or the direct factorisation fails.
StaticSolveReport solveStatic(StaticModel& model, const ExternalForces& external,
                              const std::vector<std::uint8_t>& constrained, const StaticSolveSettings& settings,
                              const ExternalStiffness& externalStiffness = {});
/// The same for the co-rotational model.
StaticSolveReport solveStatic(CorotationalFem& model, const ExternalForces& external,
                              const std::vector<std::uint8_t>& constrained, const StaticSolveSettings& settings,
                              const ExternalStiffness& externalStiffness = {});

/// The same under fixed external forces (empty: none), by conjugate gradients.
StaticSolveReport solveStatic(CorotationalFem& model, const Eigen::VectorXd& externalForces,
                              const std::vector<std::uint8_t>& constrained, double tolerance = 1e-9,
                              int maxUpdates = 20, int cgMaxIterations = 20000);

} // namespace vsim::sim::fem
