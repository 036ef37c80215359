#include "vsim/sim/fem/WallPathSolver.h"

#include "vsim/core/Error.h"
#include "vsim/core/Parameters.h"
#include "vsim/core/StoredText.h"

namespace vsim::sim::fem {

WallPathSolver::WallPathSolver(FemRunSetup setup, std::vector<ParameterSpec> parameters)
    : m_setup(std::move(setup)), m_parameters(std::move(parameters))
{
    m_setup.wall = {};
}

WallPathSolver::~WallPathSolver() = default;

void WallPathSolver::initialize(const SimulationInput& input, const ParameterSet&)
{
    if (!m_setup.pressurePa)
        throw Error("the run has no pressure curve");
    m_simulation = std::make_unique<WallSimulation>(input.get<TetMesh>("wall"), m_setup.material, m_setup.integrator,
                                                    m_setup.loaded);
    if (m_setup.tearing)
        m_simulation->setTearStrength(m_setup.tearStressPa);
    if (m_setup.stepper)
        m_simulation->setStepper(m_setup.stepper);
    m_step = 0, m_onsetPressurePa = -1.0;
    m_stopReason.clear(), m_stepIterations.clear(), m_stepResiduals.clear(), m_equilibriumResiduals.clear();
    m_entropyCurve.clear(), m_pathMetrics.clear();
}

StepOutcome WallPathSolver::step(RunStatus& status, const Progress& progress)
{
    const int step = m_step + 1;
    const double time = step * m_setup.integrator.timeStep, pressure = m_setup.pressurePa(time);
    m_simulation->setPressure(pressure);
    const WallSimulation::StepOutcome outcome = m_simulation->step();
    status.recordSolve(outcome.report.cgIterations, outcome.report.cgResidual, m_setup.integrator.cgTolerance,
                       m_setup.integrator.cgMaxIterations);
    m_stepIterations.push_back(outcome.report.cgIterations);
    m_stepResiduals.push_back(outcome.report.cgResidual);
    if (!outcome.guard.empty())
    {
        m_stopReason = storedText(Pattern{"%1 at step %2 (t = %3 s, pressure %4 MPa); the last good state is kept",
                                          {outcome.guard, std::to_string(step), numberText(time),
                                           numberText(pressure * 1e-6)}});
        return StepOutcome::guard(storedText(Pattern{"%1 at step %2; the last good state is kept",
                                                     {outcome.guard, std::to_string(step)}}));
    }
    m_step = step;
    if (outcome.tornNow > 0)
    {
        if (m_onsetPressurePa < 0.0)
            m_onsetPressurePa = pressure;
        const double entropy = m_simulation->entropy().value();
        m_entropyCurve.push_back({pressure, entropy});
        if (m_setup.entropyEnd > 0.0 && entropy >= m_setup.entropyEnd)
        {
            m_stopReason = storedText(Pattern{"the fracture entropy reached %1 (end condition %2)",
                                              {numberText(entropy), numberText(m_setup.entropyEnd)}});
            return {StepOutcome::Kind::EndCondition, m_stopReason};
        }
    }
    if (step == m_setup.steps && m_setup.equilibriumTolerance > 0.0)
        return equilibrate(status, progress);
    return {};
}

StepOutcome WallPathSolver::equilibrate(RunStatus& status, const Progress& progress)
{
    const RunStatus path = status;
    m_pathMetrics["path_steps"] = double(m_step);
    m_pathMetrics["path_capped_steps"] = double(path.unconvergedSolves);
    m_pathMetrics["path_mean_cg_iterations"] = path.solves ? double(path.iterations) / double(path.solves) : 0.0;
    std::string failure;
    const StaticSolveReport equilibrium =
        m_simulation->equilibrate(m_setup.equilibriumTolerance, m_setup.equilibriumMaxUpdates, &failure,
                                  progress.subRange(axisProgressShare(), 1.0));
    // The figures' status is the equilibrium's: its direct solves (each recorded at the worst check |A x - b| / |b|
    // of the solve) and the force residual of the state the figures come from.
    status = RunStatus{};
    for (int update = 0; update < equilibrium.updates; ++update)
        status.recordSolve(0, equilibrium.worstLinearResidual, 1e-8, 0);
    status.forceTolerance = m_setup.equilibriumTolerance;
    m_equilibriumResiduals = equilibrium.residualHistory;
    m_pathMetrics["equilibrium_updates"] = double(equilibrium.updates);
    if (failure.empty())
    {
        status.forceResidual = equilibrium.forceResidual;
        return {StepOutcome::Kind::Finished, {}};
    }
    // The path's state is kept (equilibrate restored it): its own residual (the first of the history) goes with its
    // figures; none computed (the solve failed before its first residual) counts as 100 %.
    status.forceResidual = equilibrium.residualHistory.empty() ? 1.0 : equilibrium.residualHistory.front();
    m_stopReason = storedText(
        Pattern{"the equilibrium solve failed (%1); the figures are the load path's", {failure}});
    return StepOutcome::guard(m_stopReason);
}

std::map<std::string, double> WallPathSolver::metrics() const
{
    std::map<std::string, double> metrics = m_pathMetrics;
    metrics["steps"] = m_step;
    metrics["final_pressure_kpa"] = m_setup.pressurePa(position()) * 1e-3;
    if (m_setup.tearing)
    {
        metrics["torn_elements"] = double(m_simulation->entropy().tornElements());
        metrics["fracture_entropy"] = m_simulation->entropy().value();
        metrics["tear_onset_pressure_mpa"] = m_onsetPressurePa >= 0.0 ? m_onsetPressurePa * 1e-6 : -1.0;
    }
    return metrics;
}

} // namespace vsim::sim::fem
