// The smoke solver's speed on the CPU (issue 21: 64^3 at 20 steps per second or more on 2 cores): a plume from a
// cautery-like source at the floor of a 1 m box of n^3 cells, open at the top, with buoyancy, vorticity
// confinement and vortex particles (up to 1,100 alive), the projection by MGPCG to a relative residual of 1e-4,
// warm-started. After `warmup` steps (the plume rising), `steps` steps are timed `repetitions` times:
//
//   bench_smoke_cpu [n=64] [steps=20] [repetitions=3] [warmup=40]
//
// Prints one JSON object: the median seconds per step and steps per second, each part's median share, the
// projections' iterations (mean and most) and worst relative residual, the particles alive, the threads.

#include "vsim/sim/smoke/SmokeForces.h"
#include "vsim/sim/smoke/SmokeSimulation.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
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

} // namespace

int main(int argc, char** argv)
{
    const int n = argc > 1 ? std::stoi(argv[1]) : 64;
    const int steps = argc > 2 ? std::stoi(argv[2]) : 20;
    const int repetitions = argc > 3 ? std::stoi(argv[3]) : 3;
    const int warmup = argc > 4 ? std::stoi(argv[4]) : 40;
    DomainBoundaries boundaries{};
    boundaries[5] = DomainBoundary::Open;
    SmokeSettings settings;
    settings.buoyancyAlpha = kGravity / kAirDensity;
    settings.buoyancyBeta = kGravity / kAmbientK;
    settings.confinement = 0.3;
    settings.particleStrength = 0.3;
    settings.particleRadius = 2.0 / n;
    settings.coolingPerS = 0.5;
    SmokeSimulation simulation(SmokeGrid::make(n, n, n, 1.0 / n, boundaries), settings);
    SmokeSource source;
    source.centre = {0.5, 0.5, 0.1};
    source.radius = 0.06;
    source.densityRate = 1e-3;
    source.temperatureK = 80.0;
    source.velocity = {0.0, 0.0, 0.5};
    source.particlesPerSecond = 600.0;
    simulation.addSource(source);
    const double frame = 1.0 / 30.0;
    for (int s = 0; s < warmup; ++s)
        if (!simulation.step(simulation.stableStep(frame)).guard.empty())
            return std::fprintf(stderr, "bench_smoke_cpu: a guard stopped the warm-up\n"), 1;
    std::vector<double> perStep, advection, forces, projection, particles;
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
                return std::fprintf(stderr, "bench_smoke_cpu: %s\n", report.guard.c_str()), 1;
            sums[0] += report.advectionSeconds, sums[1] += report.forceSeconds;
            sums[2] += report.projectionSeconds, sums[3] += report.particleSeconds;
            iterations += report.projection.iterations;
            mostIterations = std::max(mostIterations, report.projection.iterations);
            worstResidual = std::max(worstResidual, report.projection.relativeResidual);
        }
        perStep.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / steps);
        advection.push_back(sums[0] / steps), forces.push_back(sums[1] / steps);
        projection.push_back(sums[2] / steps), particles.push_back(sums[3] / steps);
    }
    const double step = median(perStep);
    std::printf("{\"case\": \"smoke plume, 1 m box, open top\", \"grid\": \"%dx%dx%d\", \"precision\": \"single\", "
                "\"threads\": %d, \"steps\": %d, \"repetitions\": %d, \"median_seconds_per_step\": %.4f, "
                "\"steps_per_second\": %.2f, \"median_seconds\": {\"sources_and_advection\": %.4f, \"forces\": %.4f, "
                "\"projection\": %.4f, \"vortex_particles\": %.4f}, \"mean_iterations\": %.2f, \"most_iterations\": %d, "
                "\"worst_relative_residual\": %.2e, \"tolerance\": %.0e, \"particles\": %zu, \"simulated_time_s\": %.3f}\n",
                n, n, n, omp_get_max_threads(), steps, repetitions, step, 1.0 / step, median(advection), median(forces),
                median(projection), median(particles), iterations / (steps * repetitions), mostIterations, worstResidual,
                settings.tolerance, simulation.particles().size(), simulation.time());
    return 0;
}
