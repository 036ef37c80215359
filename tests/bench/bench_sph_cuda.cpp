// The SPH solver's speed on the GPU (issue 18: >= 3.5e8 particle-steps per second for 1-5 million particles
// on the 3D dam break; DualSPHysics 5.4 measured 3.4-3.6e8 on an H100, single precision): the dam break of
// bench_sph_cpu (DamBreak.h, SPHERIC 2 without its obstacle) at about `particles` particles, set up by the
// CPU solver, then `steps` GPU steps after 20 of warm-up; with `cpuSteps` > 0 the CPU solver (all OpenMP
// threads) steps the same particles that many times beside it, for the same machine's CPU figure; with
// `phaseSteps` > 0 a fresh copy from rest then prints where that many steps' time went (GpuStepPhases.h).
//
//   bench_sph_cuda [particles=1000000] [steps=200] [cpuSteps=0] [phaseSteps=0]
//
// Prints one JSON object: counts, spacing, h = 2 spacings, single precision on the GPU (double on the CPU),
// the device, seconds per step and particle-steps per second (every particle, wall ones included, as
// DualSPHysics counts them), the simulated time and the largest density variation at the end.

#include "GpuStepPhases.h"

#include "vsim/cuda_common/DeviceInfo.h"
#include "vsim/cuda_sph/CudaSph.h"
#include "vsim/sim/sph/DamBreak.h"
#include "vsim/sim/sph/SphSolver.h"

#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>

using namespace vsim;
using namespace vsim::sim::sph;

constexpr double kSoundSpeedFactor = 20.0;

int main(int argc, char** argv)
try
{
    const double wanted = argc > 1 ? std::stod(argv[1]) : 1e6;
    const int steps = argc > 2 ? std::stoi(argv[2]) : 200;
    const int cpuSteps = argc > 3 ? std::stoi(argv[3]) : 0;
    const int phaseSteps = argc > 4 ? std::stoi(argv[4]) : 0;
    if (vsim::cuda::devices().empty())
    {
        std::printf("SKIP: no CUDA device\n");
        return 0;
    }
    const DamBreakCase dam = damBreakCase(wanted);
    SimulationInput input;
    input.data["particles"] = dam.particles;
    // c0 = 20 sqrt(g H), DualSPHysics' CoefSound of 20 (bench_sph_cpu's 10 let the column's first collapse
    // reach the 3 % density guard at 1 million particles, t = 0.038 s); the figure per particle-step does not
    // depend on it.
    ParameterSet parameters = damBreakParameters(dam.spacingMm, kSoundSpeedFactor, 100.0);
    // Tait's tension (fluid_tension 1, kept here: it is the solver's default work) lets the first collapse reach the
    // 3 % guard at t = 0.028 s, inside the profile's steps; a speed figure needs steps, not that check
    // (DamBreakValidation.cpp's validation run sets the same 20 %).
    parameters.set("density_guard", 0.2);
    SphSolver solver;
    solver.initialize(input, parameters);
    cuda::CudaSph gpu(solver);
    const auto run = [&](int count)
    {
        for (int s = 0; s < count; ++s)
            if (const std::string guard = gpu.step(); !guard.empty())
                throw Error("a guard stopped the GPU dam break: " + guard);
    };
    run(20);
    const auto start = std::chrono::steady_clock::now();
    run(steps);
    const double gpuStep =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / steps;
    // The profile starts a fresh copy from rest, so that it times the same stretch of the flow as the timed run.
    nlohmann::json phases;
    if (phaseSteps > 0)
    {
        cuda::CudaSph fresh(solver);
        phases = bench::gpuStepPhases(fresh, phaseSteps);
    }
    double cpuStep = 0.0;
    if (cpuSteps > 0)
    {
        RunStatus status;
        const auto cpuStart = std::chrono::steady_clock::now();
        for (int s = 0; s < cpuSteps; ++s)
            if (solver.step(status, {}).kind == sim::StepOutcome::Kind::Guard)
                throw Error("a guard stopped the CPU dam break");
        cpuStep =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - cpuStart).count() / cpuSteps;
    }
    const double n = double(dam.particles.size());
    std::printf(
        "{\"case\": \"3D dam break (SPHERIC 2, no obstacle)\", \"device\": \"%s\", \"particles\": %zu, "
        "\"wall_particles\": %zu, \"spacing_mm\": %.3f, \"smoothing_ratio\": 2, \"sound_speed_m_s\": %.2f, "
        "\"gpu_precision\": \"single\", "
        "\"gpu_steps\": %d, \"gpu_seconds_per_step\": %.6f, \"gpu_particle_steps_per_second\": %.4g, "
        "\"gpu_simulated_time_s\": %.5g, \"gpu_largest_density_variation\": %.4g, \"gpu_memory_mib\": %.1f, "
        "\"cpu_precision\": \"double\", \"cpu_threads\": %d, \"cpu_steps\": %d, \"cpu_seconds_per_step\": "
        "%.4f, "
        "\"cpu_particle_steps_per_second\": %.4g}\n",
        vsim::cuda::deviceSummary().c_str(), dam.particles.size(), dam.wallParticles, dam.spacingMm,
        kSoundSpeedFactor * std::sqrt(9.81 * kDamBreakWaterHeightM), steps, gpuStep, n / gpuStep, gpu.timeS(),
        gpu.largestDensityVariation(), double(gpu.deviceBytes()) / 1048576.0, omp_get_max_threads(), cpuSteps,
        cpuStep, cpuStep > 0.0 ? n / cpuStep : 0.0);
    if (phaseSteps > 0)
        std::printf("%s\n", phases.dump().c_str());
    return 0;
}
catch (const std::exception& error)
{
    std::fprintf(stderr, "bench_sph_cuda: %s\n", error.what());
    return 1;
}
