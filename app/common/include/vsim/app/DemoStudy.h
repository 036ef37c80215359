#pragma once

#include "vsim/core/ImageVolume.h"
#include "vsim/core/Progress.h"

#include <filesystem>

namespace vsim::app {

/// A synthetic abdominal CTA (192 x 192 x 160 voxels, 0.8 x 0.8 x 1.0 mm, LPS): air, body (soft tissue with a fat
/// rim), a vertebral column (bone), and a contrast-filled aorta (radius 10 mm) with a fusiform aneurysm (radius
/// 24 mm at mid height), plus 20 HU Gaussian noise from a fixed seed. Until the DICOM phantoms exist this is the
/// built-in demo the workstation opens.
CtVolume makeDemoVolume(const Progress& progress = {});

/// Returns the demo study's bundle, writing it first if it does not exist yet.
std::filesystem::path ensureDemoStudy(const std::filesystem::path& bundle, const Progress& progress = {});

/// The default location of the demo study: $XDG_DATA_HOME (or ~/.local/share)/VascuSim/demo.vsim.
std::filesystem::path defaultDemoStudyPath();

} // namespace vsim::app
