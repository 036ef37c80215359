#include "vsim/sim/fem/FemRun.h"

#include "vsim/core/Error.h"
#include "WallDriverRun.h"
#include "vsim/sim/fem/WallPathSolver.h"

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

namespace detail {

SolverRun runOnWall(Solver& solver, const TetMesh& wall, const RunControl& control, const Progress& progress)
{
    SimulationInput input;
    input.data.emplace("wall", wall);
    SolverRun run = runSolver(solver, input, ParameterSet(std::vector<ParameterSpec>{}), control, progress);
    if (run.status.stoppedBy == RunStatus::StoppedBy::Cancel)
        throw Cancelled();
    return run;
}

void moveFrames(SolverRun& run, FemRunResult& result,
                const std::function<std::pair<double, double>(const RunFrame&)>& timeAndPressure)
{
    for (RunFrame& frame : run.frames)
    {
        const auto [time, pressure] = timeAndPressure(frame);
        result.frames.push_back(std::get<TetMesh>(std::move(frame.data)));
        frame.data = TetMesh{};
        result.frameTimesS.push_back(time);
        result.framePressuresPa.push_back(pressure);
    }
}

} // namespace detail

FemRunResult runFem(const FemRunSetup& setup, const Progress& progress)
{
    WallPathSolver solver(setup, {});
    RunControl control;
    control.frameEverySteps = std::max(1, setup.frameEvery);
    control.maxSteps = long(setup.steps);
    SolverRun run = detail::runOnWall(solver, setup.wall, control, progress);

    FemRunResult result;
    detail::moveFrames(run, result, [&](const RunFrame& frame) {
        return std::pair{frame.position, solver.pressureAt(frame.position)};
    });
    result.stopReason = solver.stopReason();
    result.stepIterations = solver.stepIterations();
    result.stepResiduals = solver.stepResiduals();
    result.entropyCurve = solver.entropyCurve();
    result.equilibriumResiduals = solver.equilibriumResiduals();
    result.metrics = solver.metrics();
    addPeakMetrics(result);
    RunStatus& status = result.status;
    status = run.status;
    result.metrics["mean_cg_iterations"] = status.solves ? double(status.iterations) / double(status.solves) : 0.0;
    // The wall's figures are read against the pressure the run reached, not its simulated time.
    status.reachedQuantity = "pressure";
    status.reachedUnit = "kPa";
    status.reached = solver.pressureAt(solver.position()) * 1e-3;
    status.target = solver.pressureAt(setup.steps * setup.integrator.timeStep) * 1e-3;
    for (const auto& [key, value] : status.metrics())
        result.metrics[key] = value;
    result.record = std::move(run);
    return result;
}

SolverRun runOf(const FemRunResult& result)
{
    SolverRun run = result.record;
    if (run.frames.size() != result.frames.size())
    {
        run.axis = {"pressure", "kPa", result.status.target};
        run.frames.clear(), run.keptFrameNumbers.clear();
        for (std::size_t f = 0; f < result.frames.size(); ++f)
        {
            RunFrame& frame = run.frames.emplace_back();
            frame.number = int(f), frame.step = long(f), frame.position = result.framePressuresPa[f] * 1e-3;
            run.keptFrameNumbers.push_back(int(f));
        }
        run.framesTaken = int(result.frames.size());
        run.provenance.solver = "fem";
    }
    for (std::size_t f = 0; f < result.frames.size(); ++f)
        run.frames[f].data = result.frames[f];
    run.status = result.status;
    run.metrics = result.metrics;
    return run;
}

} // namespace vsim::sim::fem
