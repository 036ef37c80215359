// The sph-stenosis problem (StenosisPipe.h) on the GPU (cuda/sph, single precision): the same particles, open
// ends, sections and wall points as the CPU's runStenosisPipe, stepped by CudaSph; within the averaging window,
// every `every`-th step the particles come back to the host, where the sections and the wall loads take their
// samples, each weighted by the time since the last (the CPU samples the sections every step and the wall every
// 10th). Writes the JSON that bench_sph_openfoam reads with --sph-in (give it the same --spacing) and prints a
// summary line.
//
//   bench_sph_cuda_stenosis <spacing mm> <out.json> [every] [sound speed m/s] [mean speed m/s] [length mm]
//                           [particle shifting A] [solver parameter=value]... [--checkpoint FILE]
//                           [--stop-after SECONDS] [--period MS --amplitude A] [--phases STEPS]
//
// --checkpoint goes on from FILE when it exists (SphCheckpoint.h: the particles, the time, the mass ledger, the
// averages so far and this bench's own counters) and saves the run's end there; with --stop-after it saves the
// run there once that many seconds have passed and exits 3: run the same command again to go on (a run longer
// than one call of the device tool). The checkpoint holds the GPU's rates of the next kick, which the resumed run
// takes (a checkpoint written before 2026-12-01 has none: the resumed run evaluates them at the saved state;
// SphCheckpoint.h); stderr gives the largest density variation at the save and over the first steps after it.
// When a guard stops the run, the state it read is saved beside it as FILE.guard (to read back, e.g. the
// densities near the particle the guard names; not to go on from).
//
// A mean speed (and length) other than the default's 0.05 m/s (5.6 mm) is StenosisPipe::atFlow's problem (Re 100
// upstream at 0.207 m/s); the sound speed then scales with it unless given (0: scaled), and the Courant number and
// the walls' backstop follow the throat's Re (StenosisPipe.h).
//
// --period and --amplitude make the inflow pulse (StenosisPipe::pulsatile: 1 + A sin(2 pi t / T), averaged over one
// whole cycle once settled, the systole over a tenth of it about the inflow's peak); the JSON then holds the
// systolic sections too ("systolic_sections"), which bench_sph_openfoam --period --amplitude compares.
//
// --phases STEPS profiles instead of running to the end: from the start (or the checkpoint) STEPS steps untimed, then
// STEPS with each phase of the step timed (GpuStepPhases.h); prints that JSON and saves nothing.
//
// Exit 0 with "SKIP" without a device, 1 when a guard stops the run, 3 when --stop-after saved it to go on.

#include "GpuStepPhases.h"
#include "StenosisArguments.h"
#include "StenosisJson.h"

#include "vsim/core/Error.h"
#include "vsim/cuda_common/DeviceInfo.h"
#include "vsim/cuda_sph/CudaSph.h"
#include "vsim/sim/sph/SphCheckpoint.h"
#include "vsim/sim/sph/SphSolver.h"
#include "vsim/sim/sph/StenosisPipe.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace vsim;
using namespace vsim::sim::sph;

namespace {

/// The option `name` and its value taken out of the arguments ("" when absent).
std::string takeOption(std::vector<std::string>& arguments, const std::string& name)
{
    for (std::size_t a = 0; a + 1 < arguments.size(); ++a)
        if (arguments[a] == name)
        {
            const std::string value = arguments[a + 1];
            arguments.erase(arguments.begin() + long(a), arguments.begin() + long(a) + 2);
            return value;
        }
    return {};
}

/// The GPU run now as a checkpoint: the solver's (its fluid mass at the start), the GPU's particles, time, ledger
/// and boundaries' last values, this bench's series and counters.
SphCheckpoint gpuCheckpoint(const SphSolver& solver, const cuda::CudaSph& gpu, long steps, const SectionSeries& sections,
                            const WallLoadSeries& wallLoads, std::map<std::string, double> counters)
{
    SphCheckpoint c = solver.checkpoint();
    c.particles = gpu.download();
    c.rates = gpu.nextRates();
    c.timeS = gpu.timeS(), c.steps = steps, c.ledger = gpu.massLedger();
    for (int id : c.particles.id)
        c.nextId = std::max(c.nextId, id + 1);
    for (std::size_t k = 0; k < c.boundaryFlowRateM3S.size(); ++k)
        c.boundaryFlowRateM3S[k] = gpu.flowRate(k), c.boundaryPressurePa[k] = gpu.pressure(k);
    c.sections = sections.sums(), c.wallLoads = wallLoads.sums();
    c.counters = std::move(counters);
    return c;
}

} // namespace

int main(int argc, char** argv)
try
{
    std::vector<std::string> arguments(argv, argv + argc);
    const std::string checkpointFile = takeOption(arguments, "--checkpoint");
    const std::string stopAfterText = takeOption(arguments, "--stop-after");
    const double stopAfterS = stopAfterText.empty() ? INFINITY : std::stod(stopAfterText);
    const std::string periodText = takeOption(arguments, "--period"), amplitudeText = takeOption(arguments, "--amplitude");
    const std::string phasesText = takeOption(arguments, "--phases");
    if (periodText.empty() != amplitudeText.empty())
        throw Error("--period MS and --amplitude A go together (a pulsatile inflow)");
    if (!stopAfterText.empty() && checkpointFile.empty())
        throw Error("--stop-after needs --checkpoint FILE to save the run in");
    std::vector<char*> kept;
    for (std::string& argument : arguments)
        kept.push_back(argument.data());
    argc = int(kept.size()), argv = kept.data();
    if (argc < 3)
    {
        std::fprintf(stderr, "usage: bench_sph_cuda_stenosis <spacing mm> <out.json> [every] [sound speed m/s] "
                             "[mean speed m/s] [length mm] [particle shifting A] [solver parameter=value]... "
                             "[--checkpoint FILE] [--stop-after SECONDS] [--period MS --amplitude A] "
                             "[--phases STEPS]\n");
        return 2;
    }
    if (vsim::cuda::devices().empty())
    {
        std::printf("SKIP: no CUDA device\n");
        return 0;
    }
    StenosisPipe pipe;
    pipe.spacingMm = std::stod(argv[1]);
    const std::string out = argv[2];
    const int every = argc > 3 ? std::stoi(argv[3]) : 10;
    if (argc > 5)
        pipe = pipe.atFlow(std::stod(argv[5]), argc > 6 ? std::stod(argv[6]) : pipe.lengthMm);
    if (!periodText.empty())
        pipe = pipe.pulsatile(1e-3 * std::stod(periodText), std::stod(amplitudeText));
    if (argc > 4 && std::stod(argv[4]) > 0.0)
        pipe.soundSpeedMS = std::stod(argv[4]);
    if (argc > 7)
        pipe.particleShifting = std::stod(argv[7]);
    bench::takeSmoothingRatio(pipe, 8, argc, argv);
    const auto start = std::chrono::steady_clock::now();
    SphSolver solver;
    configureStenosisPipe(pipe, solver, 1, 1); // sampled here every `every` steps, weighted by the time between
    SimulationInput input;
    input.data["particles"] = stenosisPipeParticles(pipe);
    ParameterSet parameters = stenosisPipeParameters(pipe);
    for (int a = 8; a < argc; ++a) // the solver's parameters (sphParameters), e.g. delta_sph=0
        parameters.setFromText(argv[a]);
    std::map<std::string, double> counters; // this bench's, carried through a checkpoint
    if (!checkpointFile.empty() && std::filesystem::exists(checkpointFile))
    {
        auto saved = std::make_shared<SphCheckpoint>(readSphCheckpoint(checkpointFile));
        counters = saved->counters;
        solver.setStartState(saved);
        std::fprintf(stderr, "going on from %s at t = %.3f ms, step %ld (density variation then %.4g)\n",
                     checkpointFile.c_str(), 1e3 * saved->timeS, saved->steps, counters["density_variation_at_save"]);
    }
    solver.initialize(input, parameters);
    SectionSeries sections = solver.sections();
    WallLoadSeries wallLoads = solver.wallLoads();
    NeighbourGrid grid(solver.kernel().support());
    cuda::CudaSph gpu(solver);
    if (!phasesText.empty())
    {
        std::printf("%s\n", bench::gpuStepPhases(gpu, std::stoi(phasesText)).dump().c_str());
        return 0;
    }
    const double endS = parameters.get("end_time_s");
    long steps = long(solver.metrics().at("steps"));
    double pending = counters["pending_s"], largestVariation = counters["largest_density_variation"],
           largestAtS = counters["largest_density_variation_at_s"], stepping = counters["stepping_seconds"],
           sampling = counters["sampling_seconds"];
    counters["steps_at_start"] = double(steps);
    const double earlierSeconds = counters["seconds"];
    const long earlierCalls = long(counters["calls"]);
    // Saves the run (the final state too, so that the settled flow can be read again: WallShear.h's estimators).
    auto save = [&](const std::string& file) {
        const double seconds =
            earlierSeconds + std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        writeSphCheckpoint(gpuCheckpoint(solver, gpu, steps, sections, wallLoads,
                                         {{"pending_s", pending},
                                          {"largest_density_variation", largestVariation},
                                          {"largest_density_variation_at_s", largestAtS},
                                          {"stepping_seconds", stepping},
                                          {"sampling_seconds", sampling},
                                          {"seconds", seconds},
                                          {"calls", double(earlierCalls + 1)},
                                          {"density_variation_at_save", gpu.largestDensityVariation()}}),
                           file);
    };
    while (gpu.timeS() < endS)
    {
        if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > stopAfterS)
        {
            save(checkpointFile);
            std::printf("{\"case\": \"sph-stenosis on the GPU\", \"saved_at_s\": %.6g, \"end_time_s\": %.6g, "
                        "\"steps\": %ld, \"checkpoint\": \"%s\", \"largest_density_variation\": %.4g, "
                        "\"next\": \"run the same command again to go on\"}\n",
                        gpu.timeS(), endS, steps, checkpointFile.c_str(), largestVariation);
            return 3;
        }
        const auto stepStart = std::chrono::steady_clock::now();
        if (const std::string guard = gpu.step(); !guard.empty())
        {
            if (!checkpointFile.empty()) // the state the guard read: to read back, not to go on from
                try
                {
                    save(checkpointFile + ".guard");
                    std::fprintf(stderr, "the state at the guard's stop saved to %s.guard\n",
                                 checkpointFile.c_str());
                }
                catch (const std::exception& error) // the guard's own message matters more
                {
                    std::fprintf(stderr, "the state at the guard's stop was not saved: %s\n",
                                 error.what());
                }
            throw Error("a guard stopped the GPU stenosis run: " + guard);
        }
        ++steps;
        pending += gpu.lastStepS();
        if (gpu.largestDensityVariation() > largestVariation)
            largestVariation = gpu.largestDensityVariation(), largestAtS = gpu.timeS();
        if (steps - long(counters["steps_at_start"]) <= 3 && counters.count("density_variation_at_save"))
            std::fprintf(stderr, "step %ld after going on: density variation %.4g\n", steps,
                         gpu.largestDensityVariation());
        if (steps % 5000 == 0) // progress on stderr: how far a run that a time limit stops came
            std::fprintf(stderr, "t = %.3f ms of %.3f, %ld steps, largest density variation so far %.3g\n",
                         1e3 * gpu.timeS(), 1e3 * endS, steps, largestVariation);
        const auto stepEnd = std::chrono::steady_clock::now();
        stepping += std::chrono::duration<double>(stepEnd - stepStart).count();
        if (gpu.timeS() < pipe.averageFromS) // nothing is sampled before the window: no download either
        {
            pending = 0.0;
            continue;
        }
        if (steps % every != 0)
            continue;
        const ParticleState particles = gpu.download();
        grid.build(particles.position);
        sections.sample(particles, solver.fluid(), gpu.timeS(), pending);
        wallLoads.sample(particles, grid, solver.kernel(), solver.fluid(), 1e-3 * pipe.spacingMm, gpu.timeS(), pending);
        pending = 0.0;
        sampling += std::chrono::duration<double>(std::chrono::steady_clock::now() - stepEnd).count();
    }
    if (!checkpointFile.empty())
        save(checkpointFile);
    const double seconds =
        earlierSeconds + std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::map<std::string, double> metrics = {{"steps", double(steps)}, {"particles", double(gpu.particleCount())},
                                             {"largest_density_variation", largestVariation}};
    const StenosisPipeFlow flow = stenosisPipeFlow(pipe, sections, wallLoads, metrics);
    const nlohmann::json wall = {{"arc_mm", flow.wallArcMm}, {"tawss_pa", flow.wallShearPa},
                                 {"pressure_pa", flow.wallPressurePa}, {"throat_tawss_pa", flow.throatWallShearPa}};
    const double inflow = double(gpu.massLedger().totalInflow());
    nlohmann::json report = {
        {"sections", bench::sectionsJson(flow.arcMm, flow.flows)}, {"wall", wall}, {"seconds", seconds},
        {"stepping_seconds", stepping}, {"sampling_seconds", sampling}, {"steps", steps},
        {"particles", gpu.particleCount()}, {"largest_density_variation", largestVariation},
        {"largest_density_variation_at_s", largestAtS}, {"precision", "single (GPU)"},
        {"device", vsim::cuda::deviceSummary()}, {"spacing_mm", pipe.spacingMm}, {"sound_speed_m_s", pipe.soundSpeedMS},
        {"sampled_every_steps", every}, {"inflow_kg", inflow}, {"mean_speed_m_s", pipe.meanSpeedMS},
        {"length_mm", pipe.lengthMm}, {"averaged_s", {pipe.averageFromS, pipe.endTimeS}},
        {"particle_shifting", parameters.get("particle_shifting")}, {"cfl", parameters.get("cfl")},
        {"wall_repulsion", parameters.get("wall_repulsion")}, {"shift_correction", parameters.get("shift_correction")},
        {"fpm", parameters.get("fpm")}, {"density_summation", parameters.get("density_summation")},
        {"density_relaxation_s", parameters.get("density_relaxation_s")},
        {"smoothing_ratio", parameters.get("smoothing_ratio")},
        {"outflow_kg", double(gpu.massLedger().totalOutflow())}, {"calls", earlierCalls + 1},
        {"initial_fluid_kg", double(solver.checkpoint().initialFluidMassKg)}};
    if (!pipe.systole.empty())
    {
        report["period_s"] = pipe.inflowWaveform.period(), report["amplitude"] = std::stod(amplitudeText);
        report["womersley"] = pipe.womersleyNumber(), report["systole_s"] = {pipe.systole.fromS, pipe.systole.toS};
        report["systolic_sections"] = bench::sectionsJson(flow.arcMm, flow.systolicFlows);
        std::fprintf(stderr, "systolic peak velocity ratio %.4f, pressure drop %.3f Pa (Womersley %.2f)\n",
                     flow.systolicFigures.peakRatio, flow.systolicFigures.pressureDropPa, pipe.womersleyNumber());
    }
    std::ofstream(out) << report.dump(1) << '\n';
    std::printf("{\"case\": \"sph-stenosis on the GPU\", \"spacing_mm\": %.3f, \"sound_speed_m_s\": %.1f, "
                "\"particles\": %zu, \"steps\": %ld, "
                "\"seconds\": %.1f, \"stepping_seconds\": %.1f, \"particle_steps_per_second\": %.4g, "
                "\"peak_ratio\": %.4f, \"pressure_drop_pa\": %.3f, \"mean_ratio\": %.4f, \"area_ratio\": %.4f, "
                "\"flow_rate_ratio\": %.4f, \"throat_tawss_pa\": %.3f, \"largest_density_variation\": %.4g, "
                "\"at_s\": %.4f}\n",
                pipe.spacingMm, pipe.soundSpeedMS, gpu.particleCount(), steps, seconds, stepping,
                double(gpu.particleCount()) * double(steps) / stepping, flow.figures.peakRatio,
                flow.figures.pressureDropPa, flow.figures.meanRatio, flow.figures.areaRatio,
                flow.figures.flowRateRatio, flow.throatWallShearPa, largestVariation, largestAtS);
    return 0;
}
catch (const std::exception& error)
{
    std::fprintf(stderr, "bench_sph_cuda_stenosis: %s\n", error.what());
    return 1;
}
