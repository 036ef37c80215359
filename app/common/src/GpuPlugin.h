#pragma once

// Finds and loads the GPU plugin (GpuPluginApi.h) once per process. Internal to app/common.
//
// Where it looks: $VASCUSIM_GPU_PLUGIN when set (a file), otherwise <executable's folder>/../VSIM_GPU_PLUGIN_DIR/
// libvascusim-gpu.so: /usr/lib/x86_64-linux-gnu/vascusim/ for the installed package (Debian's private library
// folder), build/<preset>/lib/x86_64-linux-gnu/vascusim/ in a build tree.

#include "vsim/app/GpuPluginApi.h"

#include <string>

namespace vsim::app {

/// The plugin's table, or nullptr when it is not installed or was refused (gpuPluginStatus() says which).
const GpuPluginApi* gpuPlugin();

/// One line for people: "loaded from <file>", "not installed (<file> is absent)" or "refused: <reason>".
std::string gpuPluginStatus();

/// Why there is no GPU backend, for a run that asked for one: "no CUDA backend: the GPU plugin is ..." or "there is
/// no CUDA device". Empty when there is one.
std::string gpuUnavailableReason();

} // namespace vsim::app
