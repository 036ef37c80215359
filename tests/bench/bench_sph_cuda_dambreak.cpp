// SPHERIC benchmark 2 on the GPU (issue 18's sph-dambreak; the check itself is sim/sph's DamBreakValidation.h,
// shared with `vascusim-cli validate sph-dambreak`): the dam break with the experiment's obstacle at about
// `particles` particles, single precision, run to `endS` (at most the experiment's record, 1.02 s), the four probes
// read every 20 ms of simulated time against MARIN's measurements (Kleefsman et al. 2005).
//
//   bench_sph_cuda_dambreak [particles=1000000] [endS=1.02] [soundSpeedFactor=20] [map] [solver parameter=value]...
//
// With `map`, stderr also gets the water's depth (cm, the probes' reading) on a 5 cm grid over the tank's first
// 1.2 m (around the obstacle and behind it) every 0.1 s from 0.4 s on: where the water is when a probe differs.
//
// Prints one JSON object: the set-up, the run (steps, seconds, particle-steps per second, the largest density
// variation at the samples), per probe the heights of both at every sample, the RMS difference (m) and the arrival
// time of the front (the first time the height passes 20 mm; H1-H3) of both. Exit 0 within the tolerance of
// DamBreakValidation.h, 1 otherwise, 2 on bad arguments or a guard (the figures up to it are printed, marked).

#include "vsim/cuda_common/DeviceInfo.h"
#include "vsim/cuda_sph/CudaSph.h"
#include "vsim/sim/sph/DamBreakProbes.h"
#include "vsim/sim/sph/DamBreakValidation.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

using namespace vsim;
using namespace vsim::sim::sph;

namespace {

std::string list(const std::vector<double>& values, const char* format)
{
    std::string out;
    char buffer[32];
    for (double v : values)
        std::snprintf(buffer, sizeof buffer, format, v), out += (out.empty() ? "" : ", ") + std::string(buffer);
    return "[" + out + "]";
}

/// The depth map of the bench's `map` (stderr): rows y from 0 to 1 m, columns x from 0 to 1.2 m, 5 cm apart.
void printDepthMap(const ParticleState& particles, const QuarticKernel& kernel, double timeS)
{
    const int sample = int(std::lround(timeS / kDamBreakSampleS));
    if (sample < 20 || sample % 5 != 0)
        return;
    const double spacingM = kernel.smoothingLength() / 2.0;
    std::fprintf(stderr, "depth map (cm) at t = %.2f s, x 0 .. 1.2 m left to right, y 0 .. 1 m top to bottom:\n",
                 timeS);
    for (int j = 0; j <= 20; ++j)
    {
        for (int i = 0; i <= 24; ++i)
            std::fprintf(stderr, "%3.0f", 100.0 * waterHeightM(particles, kernel, spacingM, 0.05 * i, 0.05 * j));
        std::fprintf(stderr, "\n");
    }
}

} // namespace

int main(int argc, char** argv)
try
{
    if (vsim::cuda::devices().empty())
    {
        std::printf("SKIP: no CUDA device\n");
        return 0;
    }
    DamBreakCheckOptions options;
    options.particles = argc > 1 ? std::stod(argv[1]) : 1e6;
    options.untilS = argc > 2 ? std::min(std::stod(argv[2]), damBreakExperiment().lastTimeS()) : 0.0;
    options.soundSpeedFactor = argc > 3 ? std::stod(argv[3]) : 20.0;
    for (int a = 4; a < argc; ++a)
        if (std::string(argv[a]) == "map")
            options.onSample = printDepthMap;
        else
            options.settings.push_back(argv[a]);
    const auto started = std::chrono::steady_clock::now();
    const DamBreakCheck check = runDamBreakCheck(options, cuda::cudaSphStepperFactory());
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    if (!check.guard.empty())
        std::fprintf(stderr, "bench_sph_cuda_dambreak: a guard stopped the run at %.4f s: %s\n", check.endS,
                     check.guard.c_str());

    std::string probes;
    const char* names[4] = {"H1", "H2", "H3", "H4"};
    for (std::size_t p = 0; p < 4; ++p)
    {
        const DamBreakProbeSeries& series = check.probes[p];
        char head[320];
        std::snprintf(head, sizeof head,
                      "%s\"%s\": {\"x_m\": %.3f, \"rms_difference_m\": %.4f, \"arrival_s\": %.3f, "
                      "\"measured_arrival_s\": %.3f, ",
                      p ? ", " : "", names[p], kDamBreakProbeXM[p], series.rmsDifferenceM, series.arrivalS,
                      series.measuredArrivalS);
        probes += head + std::string("\"simulated_m\": ") + list(series.simulatedM, "%.4f") +
                  ", \"measured_m\": " + list(series.measuredM, "%.4f") + "}";
    }
    const ParameterSet& parameters = check.parameters;
    std::printf("{\"case\": \"SPHERIC 2 dam break with obstacle (Kleefsman et al. 2005)\", \"device\": \"%s\", "
                "\"stepped_on_gpu\": %s, \"particles\": %zu, \"wall_particles\": %zu, \"spacing_mm\": %.3f, "
                "\"smoothing_ratio\": %.1f, \"sound_speed_m_s\": %.2f, \"wall_repulsion\": %.3f, "
                "\"density_guard\": %.2f, \"cfl\": %.3f, \"delta_sph\": %.3f, \"fluid_tension\": %.0f, "
                "\"gpu_precision\": \"single\", \"end_s\": %.4f, \"steps\": %ld, \"seconds\": %.1f, "
                "\"stepping_seconds\": %.1f, \"particle_steps_per_second\": %.4g, "
                "\"largest_density_variation_at_samples\": %.4g, \"rms_tolerance_m\": %.4f, "
                "\"arrival_tolerance_s\": %.3f, \"stopped_by_guard\": %s, \"within_tolerance\": %s, "
                "\"times_s\": %s, \"probes\": {%s}}\n",
                vsim::cuda::deviceSummary().c_str(), check.steppedElsewhere ? "true" : "false", check.particles,
                check.wallParticles, check.spacingMm, parameters.get("smoothing_ratio"),
                parameters.get("sound_speed_m_s"), parameters.get("wall_repulsion"), parameters.get("density_guard"),
                parameters.get("cfl"), parameters.get("delta_sph"), parameters.get("fluid_tension"), check.endS,
                check.steps, seconds, check.steppingSeconds,
                double(check.particles) * double(check.steps) / check.steppingSeconds,
                check.largestDensityVariation, kDamBreakRmsToleranceM, kDamBreakArrivalToleranceS,
                check.guard.empty() ? "false" : "true", check.withinTolerance() ? "true" : "false",
                list(check.timesS, "%.4f").c_str(), probes.c_str());
    return !check.guard.empty() ? 2 : check.withinTolerance() ? 0 : 1;
}
catch (const std::exception& error)
{
    std::fprintf(stderr, "bench_sph_cuda_dambreak: %s\n", error.what());
    return 2;
}
