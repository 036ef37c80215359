#pragma once

// A simulation run as files ParaView opens, in a folder of the caller's choice (the CLI's --out): the same layout as
// a Run artifact in a study (run.json, frames/frame_NNNNNN.<vtu|vtp|vti>, series.pvd; modules/study/README.md) and
// metrics.json beside it, the document the command printed.

#include "vsim/core/SolverRun.h"

#include <filesystem>
#include <string>

namespace vsim::study {

/// Writes `run` (its frames in memory) and `metricsJson` into `folder`, a run folder the caller claimed
/// (claimOutputFolder "run"): frames of an earlier run there are replaced and its surplus frames removed (only files
/// of this writer's names). Throws vsim::Error when a file cannot be written.
void writeRunSeries(const std::filesystem::path& folder, const SolverRun& run, const std::string& metricsJson);

} // namespace vsim::study
