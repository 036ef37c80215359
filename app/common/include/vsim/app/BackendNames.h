#pragma once

// The backends a run may ask for (`--backend auto|cpu|cuda`): one list for the pipelines' choice
// (src/BackendChoice.h) and for the CLI's checks before any run starts.

#include <string>

namespace vsim::app {

/// True for "auto", "cpu" and "cuda".
bool isBackendName(const std::string& name);

} // namespace vsim::app
