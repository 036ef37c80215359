#pragma once

// What several vascusim-cli commands share: picking artifacts and --param.

#include "CliCommands.h"
#include "vsim/core/Parameters.h"
#include "vsim/study/Study.h"

#include <map>
#include <string>

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
/// Applies every --param key=value to the set.
void applyParameters(const Arguments& arguments, ParameterSet& parameters);

} // namespace vsim::cli
