#pragma once

// Where a GPU SPH step's time goes (bench_sph_cuda, bench_sph_cuda_stenosis --phases): `steps` steps untimed, then
// as many with CudaSph's phases timed (each phase waited for: StepPhases.cuh), as JSON: the untimed milliseconds a
// step, the timed ones (the waits' own cost is the difference) and the milliseconds a step of each phase. A
// profile for where nsys does not run (the device tool's machine), not a speed figure.

#include "vsim/core/Error.h"
#include "vsim/cuda_sph/CudaSph.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <string>

namespace vsim::bench {

inline nlohmann::json gpuStepPhases(cuda::CudaSph& gpu, int steps)
{
    const auto run = [&]() {
        const auto start = std::chrono::steady_clock::now();
        for (int s = 0; s < steps; ++s)
            if (const std::string guard = gpu.step(); !guard.empty())
                throw Error("a guard stopped the profiled run: " + guard);
        return 1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / steps;
    };
    const double untimed = run();
    gpu.timePhases(true);
    const double timed = run();
    gpu.timePhases(false);
    nlohmann::json phases = nlohmann::json::object(), order = nlohmann::json::array();
    for (const auto& [phase, seconds] : gpu.phaseSeconds())
        phases[phase] = 1e3 * seconds / steps, order.push_back(phase);
    return {{"profiled_steps", steps},
            {"particles", gpu.particleCount()},
            {"ms_per_step_untimed", untimed},
            {"ms_per_step_timed", timed},
            {"phase_ms_per_step", phases},
            {"phase_order", order}};
}

} // namespace vsim::bench
