#pragma once

#include "vsim/core/Progress.h"

#include <filesystem>

namespace vsim::app {

/// Returns the demo study's bundle, writing it first if it does not exist yet: the `aaa` CT phantom at full
/// size (512 x 512 x 400, 0.7 x 0.7 x 1.0 mm, 20 HU noise, seed 1) written as DICOM next to the bundle, imported
/// through the DICOM import like any patient series, then the files it wrote removed (nothing else). Throws
/// vsim::Error when `bundle` is a folder holding files VascuSim did not write.
std::filesystem::path ensureDemoStudy(const std::filesystem::path& bundle, const Progress& progress = {});

/// The default location of the demo study: $XDG_DATA_HOME (or ~/.local/share)/VascuSim/demo.vsim.
std::filesystem::path defaultDemoStudyPath();

} // namespace vsim::app
