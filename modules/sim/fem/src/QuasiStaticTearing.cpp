#include "vsim/sim/fem/QuasiStaticTearing.h"

#include "vsim/core/Error.h"
#include "WallDriverRun.h"
#include "vsim/sim/fem/QuasiStaticTearingSolver.h"

#include <algorithm>

namespace vsim::sim::fem {
FemRunResult runQuasiStaticTearing(const QuasiStaticTearingSetup& setup, const Progress& progress)
{
    QuasiStaticTearingSolver solver(setup);
    RunControl control; // key frames only (and the first and the last)
    control.maxSteps = 4L * long((setup.endPa - setup.startPa) / std::max(setup.incrementPa, 1e-300)) + 16L + 2L * setup.maxTears;
    SolverRun run = detail::runOnWall(solver, setup.wall, control, progress);

    FemRunResult result;
    detail::moveFrames(run, result, [&](const RunFrame& frame) { // pseudo-time: the equilibria solved
        return std::pair{double(solver.solvesAfter(frame.step)), solver.pressureAfter(frame.step)};
    });
    result.status = run.status;
    // The figures are the last converged equilibrium's: its pressure is what the run reached.
    result.status.reached = solver.lastGoodPressurePa() * 1e-3;
    if (result.status.stoppedBy != RunStatus::StoppedBy::End)
        result.stopReason = result.status.stopMessage;
    result.entropyCurve = solver.entropyCurve();
    result.metrics = solver.metrics();
    addPeakMetrics(result);
    for (const auto& [key, value] : result.status.metrics())
        result.metrics[key] = value;
    result.record = std::move(run);
    return result;
}

} // namespace vsim::sim::fem
