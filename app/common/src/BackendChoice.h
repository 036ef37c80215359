#pragma once

// Which backend a run asks for (`--backend auto|cpu|cuda`, the GUI's choice), shared by the pipelines whose
// solvers have a GPU backend (wall, blood flow, injection, smoke). Internal to app/common.

#include <functional>
#include <string>

namespace vsim::app {

/// True when the run should go to the GPU: "cuda", or "auto" with a device present; `device` then names it.
/// Throws vsim::Error for an unknown name, and for "cuda" when the GPU plugin (GpuPlugin.h) is not installed or
/// there is no device.
bool chooseCuda(const std::string& requested, std::string& device);
/// The same where the run itself may keep the GPU out: `whyNot` (asked only when the GPU could be chosen: not for
/// "cpu") says why it cannot go there, "" when it can (gpuUnavailableReason() for the plain form).
bool chooseCuda(const std::string& requested, std::string& device, const std::function<std::string()>& whyNot);

} // namespace vsim::app
