#pragma once

#include <string>
#include <utility>
#include <vector>

namespace vsim::app {

/// (component, version) for VascuSim, Qt, VTK, ITK, DCMTK, Eigen, the GPU plugin, CUDA and the GPUs found, in that
/// order.
std::vector<std::pair<std::string, std::string>> libraryVersions();

} // namespace vsim::app
