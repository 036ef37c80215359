#pragma once

// A simulation run as the run driver (sim/common/RunDriver.h) returns it and the study keeps it (a Run artifact):
// the axis it advanced along, its frames, which frames were kept, the run status, the metrics and how it was made.

#include "vsim/core/RunStatus.h"
#include "vsim/core/SimulationData.h"

#include <map>
#include <string>
#include <vector>

namespace vsim {

/// The quantity a run advances along and where it ends: simulated time in s, or a pressure in kPa for a load ramp.
struct RunAxis
{
    std::string quantity = "time"; ///< "time", "pressure"
    std::string unit = "s";        ///< the unit of positions and the target as printed
    double target = 0.0;           ///< the end of the run, in `unit`
};

/// One frame of a run: the solver's state after `step` steps, at `position` on the run's axis.
struct RunFrame
{
    int number = 0; ///< among all frames the run took (0 = the initial state), kept or not
    long step = 0;
    double position = 0.0; ///< in the axis unit
    SimulationData data;
};

/// How the run was made: enough to make it again.
struct RunProvenance
{
    std::string solver;
    std::map<std::string, std::string> parameters; ///< the solver's and the run control's, as text
    std::map<std::string, std::string> inputs;     ///< role -> artifact id
    std::string startedUtc;                        ///< ISO 8601
    double wallSeconds = 0.0;
};

struct SolverRun
{
    RunAxis axis;
    std::vector<RunFrame> frames;      ///< the kept frames, in order (empty when they were only streamed)
    std::vector<int> keptFrameNumbers; ///< which of the frames taken were kept (RunFrame::number)
    int framesTaken = 0;
    long steps = 0;
    RunStatus status;
    /// The solver's metrics of the final state, the status's (RunStatus::metrics) and run_steps, run_frames_taken,
    /// run_frames_kept, run_wall_seconds.
    std::map<std::string, double> metrics;
    RunProvenance provenance;
};

} // namespace vsim
