#pragma once

// vascusim-cli simulate smoke (issue 21).

#include "CommandLine.h"
#include "vsim/core/Progress.h"

namespace vsim::cli {

/// Runs a smoke scenario on the study, adds the Run, prints its document; --out writes the frame series.
int simulateSmoke(const Arguments& arguments, const Progress& progress);

} // namespace vsim::cli
