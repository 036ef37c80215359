#pragma once

// What the wall's three driver-run entry points share (runFem, runStaticWall, runQuasiStaticTearing): the wall as
// the solver's input, a cancel thrown on as their callers expect, and the run's frames moved into the result.

#include "vsim/sim/common/RunDriver.h"
#include "vsim/sim/fem/FemRun.h"

#include <functional>
#include <utility>

namespace vsim::sim::fem::detail {

/// Runs `solver` on `wall` (input "wall", no parameters of its own) under `control`. Throws vsim::Cancelled when
/// the user cancelled (the driver's record of it is not wanted by these callers), vsim::Error for bad input.
SolverRun runOnWall(Solver& solver, const TetMesh& wall, const RunControl& control, const Progress& progress);

/// Moves the run's frames into `result` with the time (s, or the entry point's pseudo-time) and the pressure (Pa)
/// `timeAndPressure` gives each; the run keeps the frames' numbers, steps and positions (its record).
void moveFrames(SolverRun& run, FemRunResult& result,
                const std::function<std::pair<double, double>(const RunFrame&)>& timeAndPressure);

} // namespace vsim::sim::fem::detail
