#pragma once

// The one loop every solver runs in (ARCHITECTURE.md, "Solvers"): initialize, a first frame, steps until the axis
// reaches its target (or the solver finishes, meets an end condition, a guard fires, the step limit is passed or the
// user cancels), frames every N steps and/or every so much of the axis, progress, and the run-status record of every
// run: converged, solves and iterations, residuals, what stopped it, what it reached against its target. A guard or a
// cancel ends the run normally: the last frame is the last good state (the driver snapshots the solver after the
// solver restored it) and `status` says why it stopped. A frame holding a value that is not finite is a guard too;
// the frame before it stays the last one.

#include "vsim/core/Parameters.h"
#include "vsim/core/Progress.h"
#include "vsim/core/RunStatus.h"
#include "vsim/core/SolverRun.h"
#include "vsim/sim/common/Solver.h"

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace vsim::sim {

struct RunControl
{
    int frameEverySteps = 0;  ///< a frame every N steps (0: not by steps)
    double frameEvery = 0.0;  ///< a frame each time the axis passes a multiple of this (axis unit; 0: not by axis)
    int keepEvery = 1;        ///< keep every Nth frame taken (large runs); the first and the last are always kept
    long maxSteps = 1000000;  ///< a run that has not ended after this many steps stops (a guard: step collapse)
    bool keepFramesInMemory = true; ///< false: frames go only to `frameSink` (the Run writer streams them to disk)
    /// Called with every kept frame as it is taken (the Run writer, a live view). Its vsim::Cancelled cancels the
    /// run; any other exception leaves runSolver (a frame that cannot be written stops the run with its error).
    std::function<void(const RunFrame&)> frameSink;
};

/// The run-control parameters as declarations (frame_every_steps, frame_every, keep_every, max_steps) for forms and
/// --param, and the control they set.
std::vector<ParameterSpec> runControlParameters();
RunControl runControlFrom(const ParameterSet& parameters);

/// Runs `solver` on `input` with `parameters` (its own declarations) under `control`. Throws vsim::Error when
/// initialize() refuses the input or the parameters; everything after that ends normally, with the status saying how.
SolverRun runSolver(Solver& solver, const SimulationInput& input, const ParameterSet& parameters,
                    const RunControl& control, const Progress& progress = {});

} // namespace vsim::sim
