// The needle injection's document (the CLI's output, the run folder's metrics.json) and its record in the study.

#include "SphPipelineSupport.h"
#include "vsim/app/InjectionPipeline.h"
#include "vsim/app/RunRecord.h"
#include "vsim/core/StoredText.h"
#include "vsim/core/Units.h"
#include "vsim/sim/sph/FluidModel.h"

#include <nlohmann/json.hpp>

namespace vsim::app {
namespace {

nlohmann::json vectorJson(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

/// The mass balance from the solver's ledger (kg): injected - absorbed - the fluid's gain, 0 to rounding (nothing
/// leaves: the open ends pour into the box).
double massBalanceKg(const std::map<std::string, double>& metrics)
{
    auto get = [&](const char* key) { return metrics.count(key) ? metrics.at(key) : 0.0; };
    return get("inflow_kg") - get("outflow_kg") - get("absorbed_kg") - get("fluid_mass_change_kg");
}

} // namespace

std::string injectionDocument(const InjectionRun& injection, const InjectionSetup& setup)
{
    nlohmann::json parameters;
    for (const ParameterSpec& spec : injection.parameters.specs())
        parameters[spec.key] = injection.parameters.get(spec.key);
    nlohmann::json fill = nlohmann::json::array();
    for (const InjectionFill& f : injection.fill)
        fill.push_back({{"time_s", f.timeS},
                        {"in_vessel_ml", f.inVesselMl},
                        {"collected_ml", f.collectedMl},
                        {"front_mm", f.frontMm}});
    const std::map<std::string, double>& m = injection.run.metrics;
    auto metric = [&](const char* key) { return m.count(key) ? m.at(key) : 0.0; };
    sim::sph::FluidModel mixture;
    mixture.restDensity = injection.parameters.get("density_kg_m3");
    const double voidFraction = injection.parameters.get("void_fraction");
    nlohmann::json balance{
        {"definition", "from the solver's ledger: injected through the needle - absorbed by the walls - the fluid's "
                       "gain; 0 to rounding when mass is conserved (kg)"},
        {"injected_kg", metric("inflow_kg")},
        {"absorbed_kg", metric("absorbed_kg")},
        {"fluid_gain_kg", metric("fluid_mass_change_kg")},
        {"residual_kg", massBalanceKg(m)}};
    const double spacingMm = injection.parameters.get("spacing_mm");
    return nlohmann::json{
        {"centerlines", setup.centerlinesId},
        {"scenario", "thesis scenario (a): needle injection into an empty, upright vessel, collected in a box below"},
        {"backend", injection.backend == "cuda" ? "cuda (single precision, " + injection.device + ")"
                                                : std::string("cpu (double precision)")},
        {"run_status", nlohmann::json::parse(runStatusJson(injection.run.status))},
        {"needle", openBoundaryJson(injection.needle)},
        {"needle_bore_mm", setup.needleBoreMm},
        {"generation_rate",
         {{"particles_per_s", setup.particlesPerSecond},
          {"ml_per_min", units::m3PerSToMlPerMin(injection.needle.flowRateM3S)},
          {"definition", "particles of the run's spacing (" + numberText(spacingMm) + " mm)^3 a second"}}},
        {"gauge_pressure_mmhg", units::paToMmHg(injection.parameters.get("reference_pressure_pa"))},
        {"gravity_direction", vectorJson(injection.gravityDirection)},
        {"open_ends", injection.openEnds},
        {"vessel_length_mm", injection.vesselLengthMm},
        {"collection_box",
         {{"frame_columns_patient", {vectorJson(injection.boxFrame.col(0)), vectorJson(injection.boxFrame.col(1)),
                                     vectorJson(injection.boxFrame.col(2))}},
          {"low_mm", vectorJson(injection.boxLowMm)},
          {"high_mm", vectorJson(injection.boxHighMm)},
          {"definition", "interior in gravity's frame (third axis down), open at the top"}}},
        {"fill",
         {{"definition", "at each kept frame: fluid particles x spacing^3 (rest volume) in the box and outside it; "
                         "front: the farthest fluid outside the box along gravity from the needle's plane"},
          {"rows", fill}}},
        {"first_collected_s", injection.firstCollectedS},
        {"mass_balance", balance},
        {"injected_ml", {{"value", 1e6 * metric("inflow_kg") / mixture.mixtureDensity(voidFraction)},
                         {"definition", "the ledger's injected mass / the mixture's rest density"}}},
        {"parameters", parameters},
        {"metrics", m},
        {"frames", injection.run.frames.size()},
        {"precision", injection.backend == "cuda" ? "single (GPU)" : "double (CPU)"},
        {"warnings", injection.warnings}}
               .dump(2) + "\n";
}

std::string addInjectionRun(study::Study& study, const InjectionRun& injection, const InjectionSetup& setup)
{
    study::Provenance provenance{"simulate injection", {}, {setup.centerlinesId}, "", ""};
    for (const ParameterSpec& spec : injection.parameters.specs())
        provenance.parameters[spec.key] = preciseNumberText(injection.parameters.get(spec.key));
    provenance.parameters["needle_bore_mm"] = preciseNumberText(setup.needleBoreMm);
    provenance.parameters["particles_per_s"] = preciseNumberText(setup.particlesPerSecond);
    provenance.parameters["collection_depth_mm"] = preciseNumberText(setup.collectionDepthMm);
    provenance.parameters["collection_margin_mm"] = preciseNumberText(setup.collectionMarginMm);
    provenance.parameters["needle"] = openBoundaryJson(injection.needle).dump();
    provenance.parameters["backend"] = injection.backend;
    if (!injection.device.empty())
        provenance.parameters["device"] = injection.device;
    std::vector<std::string> warnings = injection.warnings;
    const std::string statusWarning = runStatusWarning(injection.run.status);
    if (!statusWarning.empty())
        warnings.insert(warnings.begin(), statusWarning);
    const std::string id = study.addRun(injection.run, storedText("Needle injection (SPH)"), provenance, warnings);
    std::map<std::string, std::string> attributes = runAttributes(injection.run.metrics, injection.run.status);
    attributes["injection_mass_balance_kg"] = preciseNumberText(massBalanceKg(injection.run.metrics));
    attributes["injection_first_collected_s"] = preciseNumberText(injection.firstCollectedS);
    if (!injection.fill.empty())
    {
        attributes["injection_collected_ml"] = preciseNumberText(injection.fill.back().collectedMl);
        attributes["injection_in_vessel_ml"] = preciseNumberText(injection.fill.back().inVesselMl);
        attributes["injection_front_mm"] = preciseNumberText(injection.fill.back().frontMm);
    }
    study.setArtifactAttributes(id, attributes);
    return id;
}

} // namespace vsim::app
