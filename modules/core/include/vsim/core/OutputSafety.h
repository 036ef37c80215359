#pragma once

// Where VascuSim may write. It never deletes or overwrites what it did not create: an output folder is new, empty,
// or carries VascuSim's marker file for the same purpose; an output file is new, or replaced only when the user
// asked (--overwrite, or a confirmation in the GUI); a folder is never replaced. Every writer checks its paths with
// these functions before it computes anything, so that a refusal loses no work.

#include <filesystem>
#include <string>
#include <vector>

namespace vsim {

/// The marker file VascuSim writes into every folder it creates for output ("vascusim <purpose>").
inline constexpr const char* kOwnedFolderMarker = ".vascusim-folder";

/// True when `folder` carries VascuSim's marker for `purpose` (e.g. "run", "phantom", "demo", "study").
bool isOwnedFolder(const std::filesystem::path& folder, const std::string& purpose);

/// Makes `folder` ready for VascuSim's `purpose`: creates it (and its parents) when missing and marks it; marks an
/// empty one; accepts one already marked for `purpose`. Throws vsim::Error naming the path when the folder holds
/// anything else, is a file, or cannot be created.
void claimOutputFolder(const std::filesystem::path& folder, const std::string& purpose);

/// What claimOutputFolder would refuse, without touching the disk: a command checks its output folder before it
/// computes anything (a refusal costs no time) and claims it when it writes (a run that fails leaves nothing).
/// Throws vsim::Error naming the path, as claimOutputFolder does (and for a folder below a file).
void checkOutputFolder(const std::filesystem::path& folder, const std::string& purpose);

/// Checks that `file` may be written: it is absent, or present, a regular file and `overwrite` is true.
/// Throws vsim::Error naming the path (and --overwrite) otherwise; its folder must exist or be creatable.
void checkOutputFile(const std::filesystem::path& file, bool overwrite);

/// Removes exactly the listed files (those VascuSim wrote), then each folder under `root` (and `root` itself)
/// that is left empty. Anything else in those folders stays. Returns the number of files removed.
std::size_t removeWrittenFiles(const std::vector<std::filesystem::path>& files, const std::filesystem::path& root);

} // namespace vsim
