#pragma once

// The GPU backends as a plugin (issue 22): libvascusim-gpu.so, in its own package (vascusim-gpu) because it
// carries NVIDIA's CUDA runtime, which is not a Debian package. The workstation and the CLI load it at run time
// when it is installed and run every solver on the CPU when it is not. The plugin and the executables come from one
// build: the plugin states the VascuSim version and the interface it was built with, and the loader refuses a
// mismatch with a message (GpuPlugin.h).

#include "vsim/sim/fem/ImplicitStepper.h"
#include "vsim/sim/fem/StaticSolver.h"
#include "vsim/sim/smoke/SmokeBackend.h"
#include "vsim/sim/sph/SphStepper.h"

#include <string>

namespace vsim::app {

/// Raised whenever this table, or a type it names, changes.
inline constexpr int kGpuPluginInterface = 2;

/// What the plugin provides, filled by its entry point. Every function is set.
struct GpuPluginApi
{
    int interfaceVersion = kGpuPluginInterface;
    /// vsim::kVersion of the plugin's build.
    const char* applicationVersion = nullptr;
    /// The CUDA runtime inside the plugin, e.g. "13.0".
    std::string (*runtimeVersion)() = nullptr;
    /// The CUDA devices present: 0 without a driver or a device; never throws.
    int (*deviceCount)() = nullptr;
    /// One line for people, e.g. "NVIDIA H200 (sm_90, 139.8 GiB, 132 SMs)" or "no CUDA device".
    std::string (*deviceSummary)() = nullptr;
    /// The wall's co-rotational backward-Euler stepper on the GPU (cuda_fem).
    sim::fem::StepperFactory (*wallStepperFactory)() = nullptr;
    /// The wall's static solve on the GPU (cuda_fem's CudaStaticWall: the quasi-static tearing's equilibria).
    sim::fem::StaticModelFactory (*wallStaticModelFactory)() = nullptr;
    /// The SPH stepper on the GPU (cuda_sph); it throws vsim::Error for a solver it does not support.
    sim::sph::SphStepperFactory (*sphStepperFactory)() = nullptr;
    /// The smoke step's work on the GPU (cuda_smoke).
    sim::smoke::SmokeBackendFactory (*smokeBackendFactory)() = nullptr;
};

/// The plugin's one exported symbol: extern "C" const GpuPluginApi* vascusimGpuPlugin().
inline constexpr const char* kGpuPluginEntry = "vascusimGpuPlugin";
using GpuPluginEntry = const GpuPluginApi* (*)();

} // namespace vsim::app
