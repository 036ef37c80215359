#pragma once

// A Run artifact's folder (runs/<id>/): frames/frame_NNNNNN.<vtu|vtp|vti> (NNNNNN: the frame's number among all
// the run took, so the kept ones show which they are), series.pvd (ParaView's collection: each kept frame at its
// position on the run's axis) and run.json (solver, axis, provenance, steps, the frames with each file's size and
// CRC-32, the run status, the metrics), written last: the manifest's checksum is run.json's, and run.json's are the
// frames'.

#include "vsim/core/SolverRun.h"

#include <filesystem>
#include <string>

namespace vsim::study {

/// Writes `run` into `runJson`'s folder (run.json last, each file synced) and removes frames of this writer's names
/// there that the run does not list (an earlier write under the same id). Throws vsim::Error when a file cannot be
/// written, and for a run whose frames are not in memory.
void writeRunFolder(const SolverRun& run, const std::filesystem::path& runJson);
/// Reads run.json and, with `withFrames`, every frame. Throws vsim::Error naming the file that cannot be read.
SolverRun readRunFolder(const std::filesystem::path& runJson, bool withFrames);
/// Reads kept frame `index` (0 = the first kept) of the run. Throws vsim::Error for an index out of range.
RunFrame readRunFrame(const std::filesystem::path& runJson, std::size_t index);
/// Why the run's frames are damaged (a file missing, of another size or checksum than run.json says), or "".
std::string checkRunFrames(const std::filesystem::path& runJson);
/// The files of a run folder this writer names (run.json, series.pvd, frames/frame_NNNNNN.ext) that exist: the only
/// ones VascuSim removes when the run leaves the study.
std::vector<std::filesystem::path> runFolderFiles(const std::filesystem::path& folder);

} // namespace vsim::study
