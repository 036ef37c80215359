#pragma once

#include "vsim/app/MaskSource.h"

// What several vascusim-cli commands share: picking artifacts and --param.

#include "CliCommands.h"
#include "vsim/core/Parameters.h"
#include "vsim/core/RunStatus.h"
#include "vsim/study/Study.h"

#include <array>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace vsim::cli {

/// The artifact to work on: `wanted`, else the newest undamaged one of `kind`; `missing` says what to do first.
std::string chooseArtifact(const study::Study& study, const std::string& wanted, study::ArtifactKind kind,
                           const std::string& missing);
/// `wanted`, else the newest undamaged artifact of `kind` that the step `command` made (any, when empty);
/// `missing` says what to do first.
std::string chooseMadeBy(const study::Study& study, const std::string& wanted, study::ArtifactKind kind,
                         const std::string& command, const std::string& missing);
/// `wanted`, else the newest centerlines (a skeleton made by the centerline step).
std::string chooseCenterlines(const study::Study& study, const std::string& wanted);
/// Opens --study for writing, waiting up to --wait seconds (default 0) for another writer's lock; throws
/// vsim::Error naming the holder when it is still held.
study::Study openStudyForWriting(const Arguments& arguments);
/// Opens --study (or `bundle`) for reading: works while another process writes it.
study::Study openStudyForReading(const std::string& bundle);
/// True for a NIfTI, NRRD or MetaImage file name (anything else is read as DICOM): app/MaskSource.h.
using app::isVolumeFile;
/// --wait in seconds (a number, "s" allowed), 0 when absent.
double waitSeconds(const Arguments& arguments);

/// The exit code of a simulation command whose run is saved as `artifact`: 3, with one line on stderr saying where
/// it stopped, when a guard stopped it (diverging, inverted elements; its last good state is what was saved), else 0.
int runExitCode(const RunStatus& status, const std::string& artifact);

/// Applies every --param key=value to the set.
void applyParameters(const Arguments& arguments, ParameterSet& parameters);

/// Parses `count` numbers separated by `separator` ("1.5,2,3"); throws vsim::Error naming --`option`.
std::vector<double> parseNumbers(const std::string& text, char separator, std::size_t count, const std::string& option);

template <typename T>
std::array<T, 3> parseTriple(const std::string& text, char separator, const std::string& option)
{
    const std::vector<double> values = parseNumbers(text, separator, 3, option);
    return {T(values[0]), T(values[1]), T(values[2])};
}

} // namespace vsim::cli
