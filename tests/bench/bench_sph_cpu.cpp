// The SPH solver's speed on the CPU (issue 18): the 3D dam break (DamBreak.h, SPHERIC 2 without its obstacle) at a
// spacing giving about `particles` particles in all, stepped on the run driver's solver:
//
//   bench_sph_cpu [particles=200000] [steps=10] [repetitions=3]
//
// Prints one JSON object: the particle counts, the spacing, h = 2 spacings, double precision, the threads, and the
// median over `repetitions` of `steps` steps each: seconds per step and particle-steps per second (every particle,
// wall ones included, as DualSPHysics counts them).

#include "vsim/sim/sph/DamBreak.h"
#include "vsim/sim/sph/SphSolver.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace vsim;
using namespace vsim::sim::sph;

int main(int argc, char** argv)
{
    const double wanted = argc > 1 ? std::stod(argv[1]) : 2e5;
    const int steps = argc > 2 ? std::stoi(argv[2]) : 10;
    const int repetitions = argc > 3 ? std::stoi(argv[3]) : 3;
    const DamBreakCase dam = damBreakCase(wanted);
    SimulationInput input;
    input.data["particles"] = dam.particles;
    const ParameterSet parameters = damBreakParameters(dam.spacingMm);
    SphSolver solver;
    solver.initialize(input, parameters);
    std::vector<double> perStep;
    RunStatus status;
    for (int r = 0; r < repetitions; ++r)
    {
        const auto start = std::chrono::steady_clock::now();
        for (int s = 0; s < steps; ++s)
            if (solver.step(status, {}).kind == sim::StepOutcome::Kind::Guard)
            {
                std::fprintf(stderr, "bench_sph_cpu: a guard stopped the dam break\n");
                return 1;
            }
        perStep.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / steps);
    }
    std::sort(perStep.begin(), perStep.end());
    const double median = perStep[perStep.size() / 2];
    std::printf("{\"case\": \"3D dam break (SPHERIC 2, no obstacle)\", \"particles\": %zu, \"wall_particles\": %zu, "
                "\"spacing_mm\": %.3f, \"smoothing_ratio\": 2, \"precision\": \"double\", \"threads\": %d, "
                "\"steps\": %d, \"repetitions\": %d, \"median_seconds_per_step\": %.4f, "
                "\"particle_steps_per_second\": %.4g, \"simulated_time_s\": %.5g}\n",
                dam.particles.size(), dam.wallParticles, dam.spacingMm, omp_get_max_threads(), steps, repetitions, median,
                double(dam.particles.size()) / median, solver.position());
    return 0;
}
