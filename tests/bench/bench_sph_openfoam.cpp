// The blood-flow solver against OpenFOAM (issue 18's cross-check): the sph-stenosis problem (StenosisPipe.h: a 50 %
// diameter cosine stenosis in a 1.6 mm pipe, parabolic inflow of 0.05 m/s mean, Re 24 upstream and 48 in the throat)
// run by our SPH (25 ms, averaged over 15-25 ms once the 10 ms ramp has passed) and by OpenFOAM's simpleFoam on an
// axisymmetric wedge (OpenFoamStenosis.h) at two meshes (the finer one the reference, the coarser one showing
// OpenFOAM's own discretisation error). Both read through the same section definitions (CrossSections.h) and the
// same figures (StenosisFigures.h). Compared, with the tolerances:
//   centerline velocity profile  each section's peak velocity (the mean of its fastest 5 %), from the upstream
//                                compared section to the downstream one: largest difference / OpenFOAM's <= 10 %;
//   peak velocity ratio          throat / 1.6 mm upstream: <= 10 %;
//   pressure drop                1.6 mm upstream - 1.6 mm downstream (section means): <= 15 %;
//   wall shear stress in the throat: the mean |tau_w| over the wall in the throat's section slab: <= 20 %;
//   the fluid kept (a GPU run's file that names its first fluid mass): the ledger's net outflow <= 3 % of it, or the
//                                SPH's figures are not a full pipe's (fluidKept below);
//   beside them, the wall shear stress along the wall (the SPH's rings every 0.05 mm against OpenFOAM's nearest wall
//   face), reported as the largest difference over OpenFOAM's throat value (the stress nearly vanishes where the
//   jet's recirculation reattaches: a local ratio says nothing there).
//
//   bench_sph_openfoam <work folder> [--spacing MM] [--mean-speed M/S --length MM] [--sph-in FILE] [--sph-out FILE]
//                      [--openfoam-only] [--classic-simple] [--transient] [--period MS --amplitude A]
//                      [--coarse-only]
//
// --spacing sets the SPH's particle lattice (0.1 mm by default) and with it the sections' slab thickness (two
// spacings) on both sides. --sph-out writes the SPH's sections and wall rings (JSON) after its run; --sph-in reads
// them instead of running it (the SPH may run on a machine without OpenFOAM: 4 min on 16 cores, about 30 min on 2,
// or on the GPU: bench_sph_cuda_stenosis). --openfoam-only runs the two OpenFOAM meshes alone and prints their
// figures (exit 1 when one does not converge). --classic-simple solves with SIMPLE's relaxation in place of
// SIMPLEC's (OpenFoamStenosis.h). --transient runs pimpleFoam from rest through the SPH's ramp and averages over
// the SPH's window (OpenFoamStenosis.h): the same question as the SPH's, whether or not the flow has settled by
// then; "converged" then says that every pressure correction met its tolerance to the end. A work folder that holds
// the same OpenFOAM cases solved before (another --spacing or --sph-in) is read again ("reused" in the JSON, the
// seconds its solve's). --period and --amplitude make the inflow pulse on both sides (StenosisPipe::pulsatile;
// transient): the figures above are then the averaged cycle's, the TAWSS the mean of the magnitude, and beside them
// the systole's (a tenth of the cycle about the inflow's peak): the peak-systolic velocity ratio (<= 10 %, the
// duplex criterion's counterpart) and the systolic pressure drop (<= 15 %); OpenFOAM's systolic peak ratio in the
// cycle after (it runs one more) shows how periodic its flow has become. --coarse-only solves the first wedge alone, which is then
// the reference (a pulsatile run on the fine wedge takes about 8 times as long). Prints one JSON object; exit 1
// beyond a tolerance, 0 with "SKIP" when simpleFoam is not installed (`scripts/install-deps.sh --bench`).

#include "OpenFoamStenosis.h"
#include "StenosisJson.h"

#include "vsim/core/Error.h"
#include "vsim/sim/sph/StenosisPipe.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

using namespace vsim;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

json figuresJson(const sim::sph::StenosisFigures& f)
{
    return {{"throat_mm", f.throatArcMm}, {"peak_ratio_upstream", f.peakRatio},
            {"peak_ratio_downstream", f.peakRatioDownstream}, {"mean_ratio", f.meanRatio},
            {"area_ratio", f.areaRatio}, {"pressure_drop_pa", f.pressureDropPa}, {"flow_rate_ratio", f.flowRateRatio}};
}

/// The two OpenFOAM meshes: 40 cells per mm along (224 on the default 5.6 mm) by 32 across, and twice that (the
/// reference); or the first alone (--coarse-only: the reference then).
std::vector<bench::OpenFoamMesh> openFoamMeshes(const sim::sph::StenosisPipe& pipe, bool classicSimple, bool transient,
                                                bool coarseOnly)
{
    const int axial = int(std::lround(40.0 * pipe.lengthMm));
    if (coarseOnly)
        return {{axial, 32, 0.4, 5.0, classicSimple, transient}};
    return {{axial, 32, 0.4, 5.0, classicSimple, transient}, {2 * axial, 64, 0.4, 5.0, classicSimple, transient}};
}

json openFoamJson(const bench::OpenFoamStenosisFlow& f)
{
    json out = {{"cells", f.cells}, {"iterations", f.iterations}, {"converged", f.converged},
                {"pressure_residual", f.pressureResidual}, {"seconds", f.seconds}, {"reused", f.reused},
                {"inlet_flow_rate_m3s", f.inletFlowRateM3S}, {"figures", figuresJson(f.figures)},
                {"throat_wss_pa", f.throatWallShearPa}};
    if (!f.systolicSections.empty())
        out["systolic_figures"] = figuresJson(f.systolicFigures),
        out["next_cycle_systolic_figures"] = figuresJson(f.nextSystolicFigures);
    return out;
}

double parsedNumber(const char* text, const std::string& option)
{
    char* end = nullptr;
    const double value = std::strtod(text, &end);
    if (*end != '\0')
        throw Error(option + " takes a number, not '" + std::string(text) + "'");
    return value;
}

json check(double ours, double reference, double tolerance)
{
    const double difference = std::abs(ours - reference) / std::abs(reference);
    return {{"sph", ours}, {"openfoam", reference}, {"relative_difference", difference}, {"tolerance", tolerance},
            {"passed", difference <= tolerance}};
}

/// Whether the SPH run's pipe still holds its fluid: a pipe full of fluid within the density guard (3 %) holds its
/// first mass within 3 %, so a larger net outflow (the ledger's, kg) means particles that no longer fill the pipe at
/// their carried density (the pulsatile Re 200 run's wake thinned to 0.5-0.7 rho0 by summation while its continuity
/// density read rho0: RESULTS.md, 2026-12-04), and its figures are not a flow's.
json fluidKept(const json& run)
{
    const double initial = run.at("initial_fluid_kg").get<double>();
    const double netOut = run.at("outflow_kg").get<double>() - run.at("inflow_kg").get<double>();
    const double fraction = netOut / initial;
    return {{"initial_fluid_kg", initial}, {"net_outflow_kg", netOut}, {"net_outflow_fraction", fraction},
            {"tolerance", 0.03}, {"passed", std::abs(fraction) <= 0.03}};
}

} // namespace

int main(int argc, char** argv)
{
    // The work folder first: an option in its place (--help) is refused, not made a folder.
    if (argc < 2 || argv[1][0] == '-')
    {
        std::fprintf(stderr,
                     "usage: bench_sph_openfoam <work folder> [--spacing MM] [--mean-speed M/S --length MM] "
                     "[--sph-in FILE] [--sph-out FILE] [--openfoam-only] [--classic-simple] [--transient] "
                     "[--period MS --amplitude A]\n");
        return 2;
    }
    const fs::path work = argv[1];
    std::string sphIn, sphOut;
    bool openFoamOnly = false, classicSimple = false, transient = false, coarseOnly = false;
    sim::sph::StenosisPipe pipe;
    double meanSpeed = 0.0, length = 0.0; // 0: the default problem's
    double periodMs = 0.0, amplitude = -1.0; // a pulsatile inflow's (none by default)
    for (int a = 2; a < argc; ++a)
    {
        const std::string option = argv[a];
        if ((option == "--sph-in" || option == "--sph-out") && a + 1 < argc)
            (option == "--sph-in" ? sphIn : sphOut) = argv[++a];
        else if (option == "--openfoam-only")
            openFoamOnly = true;
        else if (option == "--classic-simple")
            classicSimple = true;
        else if (option == "--coarse-only")
            coarseOnly = true;
        else if (option == "--transient")
            transient = true;
        else if (option == "--spacing" && a + 1 < argc)
        {
            char* end = nullptr;
            pipe.spacingMm = std::strtod(argv[++a], &end);
            if (*end != '\0' || !(pipe.spacingMm > 0.0 && pipe.spacingMm <= 0.2))
            {
                std::fprintf(stderr, "bench_sph_openfoam: --spacing takes mm in (0, 0.2], not '%s'\n", argv[a]);
                return 2;
            }
        }
        else if ((option == "--mean-speed" || option == "--length" || option == "--period" ||
                  option == "--amplitude") && a + 1 < argc)
        {
            try
            {
                const double value = parsedNumber(argv[++a], option);
                (option == "--mean-speed" ? meanSpeed : option == "--length" ? length
                                                      : option == "--period" ? periodMs : amplitude) = value;
            }
            catch (const Error& error)
            {
                std::fprintf(stderr, "bench_sph_openfoam: %s\n", error.what());
                return 2;
            }
        }
        else
        {
            std::fprintf(stderr, "bench_sph_openfoam: unknown option '%s' (--spacing MM, --mean-speed M/S, --length MM, "
                                 "--sph-in FILE, --sph-out FILE, --openfoam-only, --classic-simple, --transient, "
                                 "--period MS, --amplitude A, --coarse-only)\n",
                         option.c_str());
            return 2;
        }
    }
    if (meanSpeed > 0.0 || length > 0.0)
        pipe = pipe.atFlow(meanSpeed > 0.0 ? meanSpeed : pipe.meanSpeedMS, length > 0.0 ? length : pipe.lengthMm);
    if ((periodMs > 0.0) != (amplitude >= 0.0))
    {
        std::fprintf(stderr, "bench_sph_openfoam: --period MS and --amplitude A go together (a pulsatile inflow)\n");
        return 2;
    }
    const bool pulsatile = periodMs > 0.0;
    if (pulsatile)
    {
        try
        {
            pipe = pipe.pulsatile(1e-3 * periodMs, amplitude);
        }
        catch (const Error& error)
        {
            std::fprintf(stderr, "bench_sph_openfoam: %s\n", error.what());
            return 2;
        }
        transient = true; // pimpleFoam through the cycles
    }
    const bool haveOpenFoam = std::system("command -v simpleFoam > /dev/null 2>&1") == 0;
    if (!haveOpenFoam && sphOut.empty())
    {
        std::printf("{\"bench\": \"sph_openfoam\", \"skipped\": \"SKIP: simpleFoam not found (Debian package openfoam: "
                    "scripts/install-deps.sh --bench)\"}\n");
        return 0;
    }
    try
    {
        json report = {{"bench", "sph_openfoam"},
                       {"openfoam_solver",
                        transient ? "pimpleFoam from rest, averaged over the SPH's window" : "simpleFoam (steady)"}};
        if (pulsatile)
            report["pulsatile"] = {{"period_s", pipe.inflowWaveform.period()}, {"amplitude", amplitude},
                                   {"womersley", pipe.womersleyNumber()},
                                   {"averaged_s", {pipe.averageFromS, pipe.endTimeS}},
                                   {"systole_s", {pipe.systole.fromS, pipe.systole.toS}}};
        std::vector<sim::sph::SectionFlow> sph, sphSystole;
        json sphWall;
        const std::vector<double> arcs = pipe.sectionArcsMm();
        if (openFoamOnly) // the reference alone (its SPH counterpart runs on the GPU: bench_sph_cuda_stenosis)
        {
            report["mean_speed_m_s"] = pipe.meanSpeedMS, report["length_mm"] = pipe.lengthMm;
            report["throat_reynolds"] = pipe.throatReynolds();
            report["openfoam"] = json::array();
            bool converged = true;
            const std::vector<bench::OpenFoamMesh> meshes = openFoamMeshes(pipe, classicSimple, transient, coarseOnly);
            for (std::size_t m = 0; m < meshes.size(); ++m)
            {
                const auto f = bench::runOpenFoamStenosis(pipe, meshes[m], work / ("openfoam-" + std::to_string(m + 1)));
                report["openfoam"].push_back(openFoamJson(f));
                converged = converged && f.converged;
            }
            std::printf("%s\n", report.dump().c_str());
            return converged ? 0 : 1;
        }
        if (!sphIn.empty())
        {
            std::ifstream in(sphIn);
            if (!in)
                throw Error("cannot read " + sphIn);
            const json stored = json::parse(in);
            const double storedSpacing = stored.value("spacing_mm", 0.1); // files before --spacing: 0.1 mm
            if (std::abs(storedSpacing - pipe.spacingMm) > 1e-9)
                throw Error(sphIn + " holds an SPH run at " + std::to_string(storedSpacing) +
                            " mm: give the same --spacing (the sections' slabs are two spacings thick)");
            if (std::abs(stored.value("mean_speed_m_s", 0.05) - pipe.meanSpeedMS) > 1e-12 ||
                std::abs(stored.value("length_mm", 5.6) - pipe.lengthMm) > 1e-9)
                throw Error(sphIn + " holds another problem: give its --mean-speed and --length");
            if (std::abs(stored.value("period_s", 0.0) - pipe.inflowWaveform.period()) > 1e-12 ||
                (pulsatile && std::abs(stored.value("amplitude", -1.0) - amplitude) > 1e-12))
                throw Error(sphIn + " holds another inflow: give its --period and --amplitude (or none for a steady one)");
            sph = bench::sectionsFrom(stored.at("sections"));
            if (pulsatile)
                sphSystole = bench::sectionsFrom(stored.at("systolic_sections"));
            sphWall = stored.at("wall");
            report["sph"] = stored;
            report["sph"]["from"] = sphIn;
            if (stored.contains("initial_fluid_kg")) // GPU runs since 2026-12-04
                report["fluid_kept"] = fluidKept(stored);
        }
        else
        {
            const auto start = std::chrono::steady_clock::now();
            const sim::sph::StenosisPipeFlow flow = sim::sph::runStenosisPipe(pipe);
            const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            sph = flow.flows, sphSystole = flow.systolicFlows;
            sphWall = {{"arc_mm", flow.wallArcMm}, {"tawss_pa", flow.wallShearPa}, {"pressure_pa", flow.wallPressurePa},
                       {"throat_tawss_pa", flow.throatWallShearPa}};
            report["sph"] = {{"sections", bench::sectionsJson(flow.arcMm, flow.flows)}, {"wall", sphWall}, {"seconds", seconds},
                             {"steps", flow.metrics.at("steps")}, {"particles", flow.metrics.at("particles")},
                             {"largest_density_variation", flow.metrics.at("largest_density_variation")},
                             {"precision", "double"}, {"spacing_mm", pipe.spacingMm},
                             {"mean_speed_m_s", pipe.meanSpeedMS}, {"length_mm", pipe.lengthMm},
                             {"inflow_kg", flow.metrics.at("inflow_kg")}, {"outflow_kg", flow.metrics.at("outflow_kg")},
                             {"initial_fluid_kg",
                              flow.metrics.at("fluid_mass_kg") - flow.metrics.at("fluid_mass_change_kg")}};
            if (pulsatile)
                report["sph"]["period_s"] = pipe.inflowWaveform.period(), report["sph"]["amplitude"] = amplitude,
                report["sph"]["systolic_sections"] = bench::sectionsJson(flow.arcMm, flow.systolicFlows);
            if (!sphOut.empty())
                std::ofstream(sphOut) << report["sph"].dump(1) << '\n';
            report["fluid_kept"] = fluidKept(report["sph"]);
        }
        const sim::sph::StenosisFigures sphFigures = sim::sph::stenosisFigures(arcs, sph, pipe.compareMm);
        report["sph"]["figures"] = figuresJson(sphFigures);
        report["sph"].erase("sections");
        report["sph"].erase("systolic_sections");
        report["sph"].erase("wall");
        report["sph"]["throat_tawss_pa"] = sphWall.at("throat_tawss_pa");
        if (!haveOpenFoam)
        {
            std::printf("%s\n", report.dump().c_str());
            return 0;
        }

        const std::vector<bench::OpenFoamMesh> meshes = openFoamMeshes(pipe, classicSimple, transient, coarseOnly);
        std::vector<bench::OpenFoamStenosisFlow> foam;
        json foamRuns = json::array();
        for (std::size_t m = 0; m < meshes.size(); ++m)
        {
            foam.push_back(bench::runOpenFoamStenosis(pipe, meshes[m], work / ("openfoam-" + std::to_string(m + 1))));
            foamRuns.push_back(openFoamJson(foam.back()));
        }
        report["openfoam"] = foamRuns;
        report["flow_rate_m3s"] = pipe.flowRateM3S();
        const bench::OpenFoamStenosisFlow& reference = foam.back();

        // The profile: each section's peak from the upstream compared section to the downstream one.
        const sim::sph::StenosisFigures& rf = reference.figures;
        double worst = 0.0, worstAt = 0.0;
        json profile = json::array();
        for (std::size_t k = rf.upstream; k <= rf.downstream; ++k)
        {
            const double ours = sph[k].peakVelocityMS, theirs = reference.sections[k].peakVelocityMS;
            const double difference = std::abs(ours - theirs) / theirs;
            profile.push_back({{"x_mm", arcs[k]}, {"sph_ms", ours}, {"openfoam_ms", theirs}});
            if (difference > worst)
                worst = difference, worstAt = arcs[k];
        }
        report["centerline_profile"] = {{"sections", profile}, {"largest_relative_difference", worst},
                                        {"at_mm", worstAt}, {"tolerance", 0.10}, {"passed", worst <= 0.10}};
        report["peak_ratio"] = check(sphFigures.peakRatio, rf.peakRatio, 0.10);
        report["pressure_drop"] = check(sphFigures.pressureDropPa, rf.pressureDropPa, 0.15);
        report["throat_wss"] = check(sphWall.at("throat_tawss_pa"), reference.throatWallShearPa, 0.20);
        bool systolePassed = true;
        if (pulsatile) // the peak-systolic figures (the duplex peak-systolic velocity ratio's counterpart)
        {
            const sim::sph::StenosisFigures sphSystolic = sim::sph::stenosisFigures(arcs, sphSystole, pipe.compareMm);
            report["systolic_peak_ratio"] = check(sphSystolic.peakRatio, reference.systolicFigures.peakRatio, 0.10);
            report["systolic_pressure_drop"] =
                check(sphSystolic.pressureDropPa, reference.systolicFigures.pressureDropPa, 0.15);
            report["systolic_peak_velocity_throat"] = {{"sph", sphSystole[sphSystolic.throat].peakVelocityMS},
                                                       {"openfoam", reference.systolicSections[rf.throat].peakVelocityMS}};
            report["openfoam_next_cycle_systolic_peak_ratio"] = reference.nextSystolicFigures.peakRatio;
            systolePassed = report["systolic_peak_ratio"]["passed"] && report["systolic_pressure_drop"]["passed"];
        }
        // Along the wall: each SPH ring against OpenFOAM's nearest wall face, between the compared sections.
        double worstWall = 0.0, worstWallAt = 0.0;
        json wallProfile = json::array();
        const std::vector<double> ringArc = sphWall.at("arc_mm"), ringShear = sphWall.at("tawss_pa");
        for (std::size_t r = 0; r < ringArc.size(); ++r)
        {
            if (ringArc[r] < arcs[rf.upstream] - 1e-9 || ringArc[r] > arcs[rf.downstream] + 1e-9)
                continue;
            std::size_t nearest = 0;
            for (std::size_t f = 1; f < reference.wallArcMm.size(); ++f)
                if (std::abs(reference.wallArcMm[f] - ringArc[r]) < std::abs(reference.wallArcMm[nearest] - ringArc[r]))
                    nearest = f;
            const double theirs = reference.wallShearPa[nearest];
            const double difference = std::abs(ringShear[r] - theirs) / reference.throatWallShearPa;
            wallProfile.push_back({{"x_mm", ringArc[r]}, {"sph_pa", ringShear[r]}, {"openfoam_pa", theirs}});
            if (difference > worstWall)
                worstWall = difference, worstWallAt = ringArc[r];
        }
        report["wall_shear_profile"] = {{"rings", wallProfile}, {"largest_difference_over_throat_value", worstWall},
                                        {"at_mm", worstWallAt}};
        const bool fluidKeptPassed = !report.contains("fluid_kept") || report["fluid_kept"]["passed"].get<bool>();
        const bool passed = fluidKeptPassed && report["centerline_profile"]["passed"] && report["peak_ratio"]["passed"] &&
                            report["pressure_drop"]["passed"] && report["throat_wss"]["passed"] && systolePassed &&
                            std::all_of(foam.begin(), foam.end(), [](const auto& f) { return f.converged; });
        report["passed"] = passed;
        std::printf("%s\n", report.dump().c_str());
        return passed ? 0 : 1;
    }
    catch (const std::exception& error)
    {
        std::fprintf(stderr, "bench_sph_openfoam: %s\n", error.what());
        return 1;
    }
}
