#include "vsim/sim/fem/FemRun.h"

#include "vsim/core/Error.h"
#include "vsim/sim/fem/WallSimulation.h"

#include <algorithm>

namespace vsim::sim::fem {

void addPeakMetrics(FemRunResult& result, const std::vector<std::uint8_t>& counted)
{
    const TetMesh& last = result.frames.back();
    const auto& vonMises = last.cellFields.at("von_mises_kpa");
    const auto& principal = last.cellFields.at("max_principal_kpa");
    std::size_t peak = vonMises.size();
    double largestPrincipal = -1e300;
    for (std::size_t t = 0; t < vonMises.size(); ++t)
        if (counted.empty() || counted[t])
        {
            if (peak == vonMises.size() || vonMises[t] > vonMises[peak])
                peak = t;
            largestPrincipal = std::max(largestPrincipal, principal[t]);
        }
    if (peak == vonMises.size())
        throw Error("the wall has no element to take its peak stress from");
    Eigen::Vector3d where = Eigen::Vector3d::Zero();
    for (int node : last.tets[peak])
        where += 0.25 * last.points[std::size_t(node)];
    const auto& displacement = last.pointFields.at("displacement_mm");
    result.metrics["peak_von_mises_kpa"] = vonMises[peak];
    result.metrics["peak_von_mises_x_mm"] = where.x();
    result.metrics["peak_von_mises_y_mm"] = where.y();
    result.metrics["peak_von_mises_z_mm"] = where.z();
    result.metrics["peak_max_principal_kpa"] = largestPrincipal;
    result.metrics["max_displacement_mm"] = *std::max_element(displacement.begin(), displacement.end());
}

FemRunResult runFem(const FemRunSetup& setup, const Progress& overall)
{
    // With an equilibrium after the path, the path takes the first 70 % of the progress bar.
    const double pathShare = setup.equilibriumTolerance > 0.0 ? 0.7 : 1.0;
    const Progress progress = overall.subRange(0.0, pathShare);
    if (!setup.pressurePa)
        throw Error("the run has no pressure curve");
    WallSimulation simulation(setup.wall, setup.material, setup.integrator, setup.loaded);
    if (setup.tearing)
        simulation.setTearStrength(setup.tearStressPa);
    if (setup.stepper)
        simulation.setStepper(setup.stepper);
    FemRunResult result;
    const double h = setup.integrator.timeStep;
    auto addFrame = [&](double time, double pressure) {
        result.frames.push_back(simulation.frame());
        result.frameTimesS.push_back(time);
        result.framePressuresPa.push_back(pressure);
    };
    addFrame(0.0, setup.pressurePa(0.0));
    RunStatus& status = result.status;
    int stepsRun = 0;
    double onsetPressure = -1.0;
    for (int step = 1; step <= setup.steps; ++step)
    {
        progress.throwIfCancelled();
        const double time = step * h, pressure = setup.pressurePa(time);
        simulation.setPressure(pressure);
        const WallSimulation::StepOutcome outcome = simulation.step();
        status.recordSolve(outcome.report.cgIterations, outcome.report.cgResidual, setup.integrator.cgTolerance,
                           setup.integrator.cgMaxIterations);
        result.stepIterations.push_back(outcome.report.cgIterations);
        result.stepResiduals.push_back(outcome.report.cgResidual);
        if (!outcome.guard.empty())
        {
            result.stopReason = outcome.guard + " at step " + std::to_string(step) + " (t = " + std::to_string(time) +
                                " s, pressure " + std::to_string(pressure * 1e-6) + " MPa); the last good state is kept";
            status.stoppedBy = RunStatus::StoppedBy::Guard;
            status.stopMessage = outcome.guard + " at step " + std::to_string(step) + "; the last good state is kept";
            break;
        }
        stepsRun = step;
        if (outcome.tornNow > 0)
        {
            if (onsetPressure < 0.0)
                onsetPressure = pressure;
            result.entropyCurve.push_back({pressure, simulation.entropy().value()});
            if (setup.entropyEnd > 0.0 && simulation.entropy().value() >= setup.entropyEnd)
            {
                result.stopReason = "the fracture entropy reached " + std::to_string(simulation.entropy().value()) +
                                    " (end condition " + std::to_string(setup.entropyEnd) + ")";
                status.stoppedBy = RunStatus::StoppedBy::EndCondition;
                status.stopMessage = result.stopReason;
                addFrame(time, pressure);
                break;
            }
        }
        if (step % std::max(1, setup.frameEvery) == 0 || step == setup.steps)
            addFrame(time, pressure);
        progress.report(double(step) / setup.steps, "simulating");
    }
    const double lastTime = stepsRun * h;
    if (!result.stopReason.empty() && result.frameTimesS.back() != lastTime)
        addFrame(lastTime, setup.pressurePa(lastTime)); // the last good state
    if (setup.equilibriumTolerance > 0.0 && result.stopReason.empty())
    {
        const RunStatus path = status;
        result.metrics["path_steps"] = double(stepsRun);
        result.metrics["path_capped_steps"] = double(path.unconvergedSolves);
        result.metrics["path_mean_cg_iterations"] = path.solves ? double(path.iterations) / double(path.solves) : 0.0;
        std::string failure;
        const StaticSolveReport equilibrium =
            simulation.equilibrate(setup.equilibriumTolerance, setup.equilibriumMaxUpdates, &failure,
                                   overall.subRange(pathShare, 1.0));
        // The figures' status is the equilibrium's: its direct solves (each recorded at the worst check
        // |A x - b| / |b| of the solve) and the force residual of the state the figures come from.
        status = RunStatus{};
        for (int update = 0; update < equilibrium.updates; ++update)
            status.recordSolve(0, equilibrium.worstLinearResidual, 1e-8, 0);
        status.forceTolerance = setup.equilibriumTolerance;
        result.equilibriumResiduals = equilibrium.residualHistory;
        result.metrics["equilibrium_updates"] = double(equilibrium.updates);
        if (failure.empty())
        {
            status.forceResidual = equilibrium.forceResidual;
            result.frames.back() = simulation.frame();
        }
        else
        {
            // The path's state is kept: its own residual (the first of the history) goes with its figures; none
            // computed (the solve failed before its first residual) counts as 100 %.
            status.forceResidual = equilibrium.residualHistory.empty() ? 1.0 : equilibrium.residualHistory.front();
            status.stoppedBy = RunStatus::StoppedBy::Guard;
            status.stopMessage = "the equilibrium solve failed (" + failure + "); the figures are the load path's";
            result.stopReason = status.stopMessage;
        }
    }

    addPeakMetrics(result);
    result.metrics["steps"] = stepsRun;
    result.metrics["mean_cg_iterations"] = status.solves ? double(status.iterations) / double(status.solves) : 0.0;
    result.metrics["final_pressure_kpa"] = setup.pressurePa(lastTime) * 1e-3;
    status.reachedQuantity = "pressure";
    status.reachedUnit = "kPa";
    status.reached = setup.pressurePa(lastTime) * 1e-3;
    status.target = setup.pressurePa(setup.steps * h) * 1e-3;
    for (const auto& [key, value] : status.metrics())
        result.metrics[key] = value;
    if (setup.tearing)
    {
        result.metrics["torn_elements"] = double(simulation.entropy().tornElements());
        result.metrics["fracture_entropy"] = simulation.entropy().value();
        result.metrics["tear_onset_pressure_mpa"] = onsetPressure >= 0.0 ? onsetPressure * 1e-6 : -1.0;
    }
    return result;
}

} // namespace vsim::sim::fem
