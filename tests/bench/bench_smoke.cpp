// The smoke solver's speed (issue 21: on the CPU 64^3 at 20 steps per second or more on 2 cores; on the GPU a
// 256^3 step in 10 ms or less): a plume from a cautery-like source at the floor of a 1 m box of n^3 cells, open
// at the top, with buoyancy, vorticity confinement and vortex particles (up to 1,100 alive), the projection by
// MGPCG to a relative residual of 1e-4, warm-started. After `warmup` steps (the plume rising), `steps` steps are
// timed `repetitions` times:
//
//   bench_smoke_cpu [n=64] [steps=20] [repetitions=3] [warmup=40]
//   bench_smoke_cuda [n=256] [steps=20] [repetitions=3] [warmup=40]     (the same source on the CUDA backend)
//
// Prints one JSON object: the median seconds per step and steps per second, each part's median share, the
// projections' iterations (mean, most, and each timed projection's) and relative residuals (worst, and each), the
// particles alive, the threads or the device. On the GPU also the bytes the step's kernels must move at the
// least (SmokeTraffic below: each kernel reading and writing its arrays once) over the median step time, against
// the device's copy bandwidth measured in the same run: how far the step is from the memory-bandwidth bound.

#include "SmokePlume.h"

#ifdef VSIM_BENCH_SMOKE_CUDA
#include "vsim/cuda_common/DeviceInfo.h"
#include "vsim/cuda_smoke/CudaSmokeBackend.h"

#include <cuda_runtime.h>
#endif

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <cstdio>
#include <string>
#include <vector>

using namespace vsim::sim::smoke;

namespace {

double median(std::vector<double> values)
{
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

#ifdef VSIM_BENCH_SMOKE_CUDA
/// The bytes one step's kernels move at the least, in units of N = the cells (one float per cell is 4 N): each
/// kernel reading and writing its arrays once (cuda/smoke's kernels, the transport's `substeps` over the three
/// axes, `iterations` conjugate-gradient iterations). An estimate of the compulsory traffic, not a count of the
/// caches' misses.
double leastBytesPerCell(int substeps, int iterations)
{
    // A level's V-cycle per cell of that level: the first pass from x = 0 (b and the codes read, x written: 9),
    // 4 s - 1 more half passes (by colour: the other colour's x, this colour's b and codes read, its x written:
    // 6.5), the residual's restriction (b, x, the codes; an eighth written: 9.5) and the prolongation (x read and
    // written, the codes, an eighth read: 9.5); s = PoissonMultigrid::smoothingSweeps (2 on the finest level, 6 on
    // the coarser ones, which together hold a seventh of the finest's cells).
    const auto level = [](int sweeps) { return 9 + (4 * sweeps - 1) * 6.5 + 9.5 + 9.5; };
    const double vcycle = level(2) + level(6) / 7.0;
    const double advection = 24 + 48 + 16 + 29.0 * substeps;             // copies, 3 lattices, start, sweeps (clamped in the last)
    const double forces = 8 + 17 + 95;                                    // cooling, buoyancy, vorticity and confinement
    // The right side with the warm start 34 (psi and its predecessor read and written), |b| 4, the true residual
    // twice (13, |r| 4), the first V-cycle, p = z 8, r . z 8, the velocity's correction 39, the largest divergence
    // left 13, the faces' largest speeds 12.
    const double projectionSetUp = 34 + 4 + 2 * 17 + vcycle + 8 + 8 + 39 + 13 + 12;
    // Each iteration: q = A p with p . q 9, psi and r updated with |r| 24; all but the last also a V-cycle,
    // r . z 8 and p = z + beta p 12.
    const double perIteration = 9 + 24, perContinuation = vcycle + 8 + 12;
    const double guards = 20;                                             // the not-finite count over five fields
    return advection + forces + projectionSetUp + iterations * perIteration + std::max(0, iterations - 1) * perContinuation +
           guards;
}

/// The device's copy bandwidth (bytes/s, read plus write) over a 1 GiB device-to-device copy, the best of 5.
double copyBandwidth()
{
    const std::size_t bytes = std::size_t(1) << 30;
    void *a = nullptr, *b = nullptr;
    cudaMalloc(&a, bytes), cudaMalloc(&b, bytes);
    cudaMemcpy(b, a, bytes, cudaMemcpyDeviceToDevice);
    cudaDeviceSynchronize();
    double best = 0.0;
    for (int r = 0; r < 5; ++r)
    {
        const auto start = std::chrono::steady_clock::now();
        cudaMemcpy(b, a, bytes, cudaMemcpyDeviceToDevice);
        cudaDeviceSynchronize();
        best = std::max(best, 2.0 * bytes / std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    cudaFree(a), cudaFree(b);
    return best;
}
#endif

} // namespace

#ifdef VSIM_BENCH_SMOKE_CUDA
constexpr const char* kName = "bench_smoke_cuda";
constexpr int kDefaultCells = 256;
#else
constexpr const char* kName = "bench_smoke_cpu";
constexpr int kDefaultCells = 64;
#endif

int main(int argc, char** argv)
{
#ifdef VSIM_BENCH_SMOKE_CUDA
    if (vsim::cuda::devices().empty())
        return std::printf("SKIP: no CUDA device\n"), 0;
    const double bandwidth = copyBandwidth();
#endif
    const int n = argc > 1 ? std::stoi(argv[1]) : kDefaultCells;
    const int steps = argc > 2 ? std::stoi(argv[2]) : 20;
    const int repetitions = argc > 3 ? std::stoi(argv[3]) : 3;
    const int warmup = argc > 4 ? std::stoi(argv[4]) : 40;
#ifdef VSIM_BENCH_SMOKE_CUDA
    std::unique_ptr<SmokeBackend> backend = vsim::cuda::cudaSmokeBackendFactory()(vsim::test::plumeGrid(n));
#else
    std::unique_ptr<SmokeBackend> backend;
#endif
    const std::unique_ptr<SmokeSimulation> owned = vsim::test::plumeSimulation(n, std::move(backend));
    SmokeSimulation& simulation = *owned;
    const SmokeSettings settings = vsim::test::plumeSettings(n);
    const double frame = 1.0 / 30.0;
    for (int s = 0; s < warmup; ++s)
        if (!simulation.step(simulation.stableStep(frame)).guard.empty())
            return std::fprintf(stderr, "%s: a guard stopped the warm-up\n", kName), 1;
    std::vector<double> perStep, advection, forces, projection, particles, leastBytes;
    std::string each; // every timed projection's iterations and relative residual
    int mostIterations = 0;
    double iterations = 0.0, worstResidual = 0.0;
    for (int r = 0; r < repetitions; ++r)
    {
        double sums[4] = {0, 0, 0, 0};
        const auto start = std::chrono::steady_clock::now();
        for (int s = 0; s < steps; ++s)
        {
            const SmokeStepReport report = simulation.step(simulation.stableStep(frame));
            if (!report.guard.empty())
                return std::fprintf(stderr, "%s: %s\n", kName, report.guard.c_str()), 1;
            sums[0] += report.advectionSeconds, sums[1] += report.forceSeconds;
            sums[2] += report.projectionSeconds, sums[3] += report.particleSeconds;
            iterations += report.projection.iterations;
            mostIterations = std::max(mostIterations, report.projection.iterations);
            worstResidual = std::max(worstResidual, report.projection.relativeResidual);
            char entry[48];
            std::snprintf(entry, sizeof entry, "%s[%d, %.2e]", each.empty() ? "" : ", ", report.projection.iterations,
                          report.projection.relativeResidual);
            each += entry;
#ifdef VSIM_BENCH_SMOKE_CUDA
            // The transport's sub-steps: at most half a cell each, along each axis (the largest speed stands for
            // each axis's: an upper bound on the sub-steps, so the traffic is overestimated by at most that).
            const int substeps = 3 * std::max(1, int(std::ceil(report.cfl / 0.5)));
            leastBytes.push_back(leastBytesPerCell(substeps, report.projection.iterations) * double(n) * n * n);
#endif
        }
        perStep.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / steps);
        advection.push_back(sums[0] / steps), forces.push_back(sums[1] / steps);
        projection.push_back(sums[2] / steps), particles.push_back(sums[3] / steps);
    }
    const double step = median(perStep);
#ifdef VSIM_BENCH_SMOKE_CUDA
    const double bytes = median(leastBytes);
    std::printf("{\"backend\": \"cuda\", \"device\": \"%s\", \"copy_bandwidth_gb_s\": %.0f, "
                "\"least_bytes_per_step_gb\": %.2f, \"achieved_gb_s\": %.0f, \"bandwidth_bound_seconds\": %.4f, "
                "\"times_the_bound\": %.2f, ",
                vsim::cuda::deviceSummary().c_str(), bandwidth / 1e9, bytes / 1e9, bytes / step / 1e9, bytes / bandwidth,
                step / (bytes / bandwidth));
#else
    std::printf("{\"backend\": \"cpu\", ");
#endif
    std::printf("\"case\": \"smoke plume, 1 m box, open top\", \"grid\": \"%dx%dx%d\", \"precision\": \"single\", "
                "\"threads\": %d, \"steps\": %d, \"repetitions\": %d, \"median_seconds_per_step\": %.4f, "
                "\"steps_per_second\": %.2f, \"median_seconds\": {\"sources_and_advection\": %.4f, \"forces\": %.4f, "
                "\"projection\": %.4f, \"vortex_particles\": %.4f}, \"mean_iterations\": %.2f, \"most_iterations\": %d, "
                "\"worst_relative_residual\": %.2e, \"tolerance\": %.0e, \"particles\": %zu, \"simulated_time_s\": %.3f, \"each_projection_iterations_and_residual\": [%s]}\n",
                n, n, n, omp_get_max_threads(), steps, repetitions, step, 1.0 / step, median(advection), median(forces),
                median(projection), median(particles), iterations / (steps * repetitions), mostIterations, worstResidual,
                settings.tolerance, simulation.particles().size(), simulation.time(), each.c_str());
    return 0;
}
