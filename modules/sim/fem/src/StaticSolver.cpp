#include "vsim/sim/fem/StaticSolver.h"

#include "vsim/core/Error.h"
#include "vsim/sim/fem/TangentSolver.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

namespace vsim::sim::fem {
namespace {

double freeNorm(const Eigen::VectorXd& v, const std::vector<std::uint8_t>& constrained)
{
    double sum = 0.0;
    for (Eigen::Index i = 0; i < v.size(); ++i)
        if (constrained.empty() || !constrained[std::size_t(i)])
            sum += v[i] * v[i];
    return std::sqrt(sum);
}

/// The co-rotational model seen by the static solve.
class CorotationalStatic : public StaticModel
{
public:
    explicit CorotationalStatic(CorotationalFem& model) : m_model(model) {}
    Eigen::VectorXd& positions() override { return m_model.positions(); }
    std::size_t updateElements() override { return m_model.updateElements(); }
    Eigen::VectorXd elasticForces() const override { return m_model.elasticForces(); }
    Eigen::Vector3d firstInvertedCentroid() const override { return m_model.firstInvertedCentroid(); }
    BlockSparseMatrix makeMatrix() const override { return m_model.makeMatrix(); }
    void assembleTangent(BlockSparseMatrix& matrix, bool consistent) const override
    {
        m_model.assemble(matrix, 0.0, 1.0);
        if (consistent)
            m_model.addRotationStiffness(matrix);
    }

private:
    CorotationalFem& m_model;
};

/// One update's linear solve on the host: the tangent assembled at the last element pass (the rotations' derivative
/// with rotationStiffness; the follower load's stiffness unless the solve is the symmetric PCG), then solved by
/// `linear`.
TangentSolveResult solveTangent(StaticModel& model, TangentSolver& linear, BlockSparseMatrix& stiffness,
                                std::optional<BlockSparseMatrix>& definite, const Eigen::VectorXd& residual,
                                Eigen::VectorXd& delta, double forceResidual, const StaticSolveSettings& settings,
                                const ExternalStiffness& externalStiffness)
{
    const bool symmetric = settings.linear == LinearSolver::ConjugateGradient;
    const bool consistent = settings.rotationStiffness;
    model.assembleTangent(stiffness, consistent);
    const bool fresh = linear.needsPreconditioner(forceResidual);
    if (externalStiffness && !symmetric)
        externalStiffness(model.positions(), stiffness);
    // The model's definite stand-in for its tangent, assembled only when a fresh GMRES preconditioner needs it:
    // with the follower load's stiffness the symmetric part was indefinite on the thrombus wall for the first
    // Newton updates, and so was the model's own tangent after the first long step; each fell back to an UMFPACK
    // LU 3-4x slower than the Cholesky (RESULTS.md, 2026-11-27 and 2026-11-28).
    const TangentSolver::StandIn standIn = [&]() -> const BlockSparseMatrix& {
        if (!definite)
            definite = model.makeMatrix();
        model.assembleDefiniteTangent(*definite, consistent);
        return *definite;
    };
    return linear.solve(stiffness, residual, delta, fresh,
                        solvesByGmres(settings.linear) ? standIn : TangentSolver::StandIn{},
                        forceResidual);
}

} // namespace

TangentSolveResult StaticModel::solveTangent(const Eigen::VectorXd&, Eigen::VectorXd&, double, const StaticSolveSettings&)
{
    throw Error("this model does not solve its own tangent");
}

StaticSolveReport solveStatic(CorotationalFem& model, const ExternalForces& external,
                              const std::vector<std::uint8_t>& constrained, const StaticSolveSettings& settings,
                              const ExternalStiffness& externalStiffness)
{
    CorotationalStatic adapter(model);
    return solveStatic(adapter, external, constrained, settings, externalStiffness);
}

StaticSolveReport solveStatic(StaticModel& model, const ExternalForces& external,
                              const std::vector<std::uint8_t>& constrained, const StaticSolveSettings& settings,
                              const ExternalStiffness& externalStiffness)
{
    StaticSolveReport report;
    const bool ownSolve = model.solvesItsTangent();
    if (ownSolve && settings.linear != LinearSolver::ConjugateGradient)
        throw Error("a model that solves its own tangent (the GPU) takes the conjugate-gradient static solve");
    BlockSparseMatrix stiffness = ownSolve ? BlockSparseMatrix{} : model.makeMatrix();
    TangentSolver linear(stiffness, constrained, settings, &model.positions());
    std::optional<BlockSparseMatrix> definite; // the preconditioner's matrix (CholeskyGmres)
    // The state at the model's positions: its element pass, inverted elements and residual force.
    Eigen::VectorXd residual, load;
    const auto evaluate = [&]() {
        const std::size_t inverted = model.updateElements();
        load = external ? external(model.positions()) : Eigen::VectorXd::Zero(model.positions().size());
        residual = model.elasticForces() + load;
        return std::make_pair(inverted, freeNorm(residual, constrained));
    };
    auto [inverted, norm] = evaluate();
    if (inverted > 0)
    {
        const Eigen::Vector3d where = 1e3 * model.firstInvertedCentroid();
        char place[96];
        std::snprintf(place, sizeof place, " (the first near %.1f, %.1f, %.1f mm)", where.x(), where.y(), where.z());
        throw Error(Pattern{"%1 elements are inverted at the start of the static solve%2",
                            {std::to_string(inverted), place}});
    }
    double reference = freeNorm(load, constrained); // the load at the start (a follower load changes after)
    if (reference == 0.0)
        reference = norm; // only prescribed displacements drive it
    // After a line search: whether its step says the solve has stalled (StaticSolveSettings::stallStep; a short step
    // that reached the tolerance has not); a stalled solve ends with this update counted and its residual recorded.
    const auto stalls = [&](double step) {
        report.smallestStep = std::min(report.smallestStep, step);
        const double residualNow = reference > 0.0 ? norm / reference : 0.0;
        if (step >= settings.stallStep || residualNow <= settings.tolerance)
            return false;
        report.stalled = true;
        ++report.updates;
        report.forceResidual = residualNow;
        report.residualHistory.push_back(residualNow);
        return true;
    };
    for (;; ++report.updates)
    {
        report.forceResidual = reference > 0.0 ? norm / reference : 0.0;
        report.residualHistory.push_back(report.forceResidual);
        if (settings.afterResidual)
            settings.afterResidual(report.updates, report.forceResidual);
        if (report.forceResidual <= settings.tolerance)
        {
            report.converged = true;
            break;
        }
        if (report.updates >= settings.maxUpdates)
            break;
        Eigen::VectorXd delta;
        TangentSolveResult solved;
        if (ownSolve)
            solved = model.solveTangent(residual, delta, linear.tolerance(), settings);
        else
            solved = solveTangent(model, linear, stiffness, definite, residual, delta, report.forceResidual, settings,
                                  externalStiffness);
        report.cgIterations += solved.iterations;
        report.factorisations += solved.factorised ? 1 : 0;
        if (solved.abandoned)
        {
            report.stalled = report.abandonedFirstSolve = true;
            break;
        }
        report.worstLinearResidual = std::max(report.worstLinearResidual, solved.relativeResidual);
        report.linearIterations.push_back(solved.iterations);
        report.linearResiduals.push_back(solved.relativeResidual);
        const Eigen::VectorXd start = model.positions();
        const double slope = delta.dot(residual); // the energy's decrease rate along delta (> 0: a descent)
        if (settings.directionalLineSearch && slope > 0.0)
        {
            // Matthies & Strang 1979: the step where the residual force has no component along the direction (the
            // potential energy's minimum on the line), by regula falsi from g(0) = delta . R > 0, accepted once
            // |g| <= g(0) / 2; steps that invert an element are halved. A stiffening wall law (Raghavan-Vorp)
            // makes the full step from rest overshoot many-fold, where the residual norm's backtracking crawls.
            double low = 0.0, lowSlope = slope, high = -1.0, highSlope = 0.0, step = 1.0;
            for (int trial = 0;; ++trial)
            {
                model.positions() = start + step * delta;
                const auto [trialInverted, trialNorm] = evaluate();
                if (trialInverted > 0)
                {
                    if (trial >= 40)
                    {
                        model.positions() = start;
                        evaluate();
                        throw Error("no step along the Newton direction keeps every element uninverted");
                    }
                    high = -1.0; // no sign information: shorten
                    step = low + 0.5 * (step - low);
                    continue;
                }
                const double g = delta.dot(residual);
                const bool beyond = g > 0.0 && high < 0.0 && step >= 1.0; // still descending at the full step
                if (std::abs(g) <= 0.5 * slope || beyond || trial >= 10)
                {
                    norm = trialNorm;
                    break;
                }
                if (g > 0.0)
                    low = step, lowSlope = g;
                else
                    high = step, highSlope = g;
                step = high < 0.0 ? std::min(1.0, 2.0 * step) : low + (high - low) * lowSlope / (lowSlope - highSlope);
            }
            if (stalls(step))
                break;
            continue;
        }
        // Backtracking: the full step unless it inverts an element or does not lower the residual force (Armijo
        // on its norm); halved up to 12 times, else the smallest step that inverts nothing is taken.
        double step = 1.0;
        for (int halving = 0;; ++halving, step *= 0.5)
        {
            model.positions() = start + step * delta;
            const auto [trialInverted, trialNorm] = evaluate();
            if ((trialInverted == 0 && trialNorm <= (1.0 - 1e-4 * step) * norm) || (halving >= 12 && trialInverted == 0))
            {
                norm = trialNorm;
                break;
            }
            if (halving >= 20)
            {
                model.positions() = start;
                evaluate();
                throw Error("no step along the Newton direction keeps every element uninverted");
            }
        }
        if (stalls(step))
            break;
    }
    return report;
}

StaticSolveReport solveStatic(CorotationalFem& model, const Eigen::VectorXd& externalForces,
                              const std::vector<std::uint8_t>& constrained, double tolerance, int maxUpdates,
                              int cgMaxIterations)
{
    ExternalForces fixed;
    if (externalForces.size() > 0)
        fixed = [&externalForces](const Eigen::VectorXd&) { return externalForces; };
    StaticSolveSettings settings;
    settings.tolerance = tolerance;
    settings.maxUpdates = maxUpdates;
    settings.cgMaxIterations = cgMaxIterations;
    return solveStatic(model, fixed, constrained, settings);
}

} // namespace vsim::sim::fem
