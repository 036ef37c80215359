#pragma once

// A simulation run as files ParaView opens: frames/frame_NNNN.vtu, series.pvd (the frames with their times) and
// metrics.json, in a folder of the caller's choice.

#include "vsim/core/TetMesh.h"

#include <filesystem>
#include <string>
#include <vector>

namespace vsim::study {

/// Writes `frames` (one per time in `times`, s) and `metricsJson` into `folder`, a run folder the caller claimed
/// (claimOutputFolder "run"): frames of an earlier run there are replaced, and its surplus frames removed.
/// Throws vsim::Error when a file cannot be written or the counts differ.
void writeRunSeries(const std::filesystem::path& folder, const std::vector<TetMesh>& frames,
                    const std::vector<double>& times, const std::string& metricsJson);

} // namespace vsim::study
