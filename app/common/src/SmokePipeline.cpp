#include "vsim/app/SmokePipeline.h"

#include "vsim/app/RunRecord.h"
#include "vsim/core/Error.h"
#include "vsim/core/Localized.h"
#include "vsim/core/StoredText.h"
#include "vsim/sim/common/RunDriver.h"

#include "BackendChoice.h"
#include "GpuPlugin.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>

namespace vsim::app {
namespace {

constexpr double kEvhTunnelRadiusMm = 12.0; // the CO2 tunnel around the vessel (EVH dissects about 2-3 cm wide)

/// The longest segment of the newest centerlines, with its mean radius (mm).
std::pair<std::vector<Eigen::Vector3d>, double> longestSegment(const study::Study& study, std::string& centerlinesId)
{
    centerlinesId = study.newestArtifact(study::ArtifactKind::Skeleton, "centerline");
    if (centerlinesId.empty())
        throw Error("the evh scenario places its tunnel around a vessel: the study has no centerlines (vascusim-cli "
                    "centerlines)");
    const SkeletonGraph skeleton = study.loadSkeleton(centerlinesId);
    const SkeletonGraph::Edge* best = nullptr;
    double bestLength = 0.0;
    for (const SkeletonGraph::Edge& edge : skeleton.edges)
    {
        double length = 0.0;
        for (std::size_t n = 1; n < edge.points.size(); ++n)
            length += (edge.points[n] - edge.points[n - 1]).norm();
        if (length > bestLength)
            best = &edge, bestLength = length;
    }
    if (!best)
        throw Error("the study's centerlines have no segment for the evh tunnel");
    double radius = 0.0;
    for (double r : best->radii)
        radius += r;
    radius = best->radii.empty() ? 2.0 : radius / double(best->radii.size());
    return {best->points, radius};
}

/// The newest liver label (segment-organ --organ liver), or empty.
std::string newestLiver(const study::Study& study)
{
    std::string found;
    for (const study::Artifact& artifact : study.artifacts())
        if (artifact.kind == study::ArtifactKind::Label && !artifact.damaged && artifact.provenance.command == "segment-organ")
        {
            const auto organ = artifact.provenance.parameters.find("organ");
            if (organ != artifact.provenance.parameters.end() && organ->second == "liver")
                found = artifact.id;
        }
    return found;
}

/// The scenario's name in the run's name (a stored text, translated when shown; the option's word otherwise).
std::string scenarioTitle(const std::string& scenario)
{
    if (scenario == "ball-drop")
        return storedText("ball drop");
    if (scenario == "evh")
        return storedText("endoscopic vessel harvesting");
    if (scenario == "liver-ablation")
        return storedText("liver ablation");
    return scenario;
}

} // namespace

SmokeSetup smokeSetup(const std::string& scenario)
{
    const std::vector<std::string> known = sim::smoke::smokeScenarios();
    if (std::find(known.begin(), known.end(), scenario) == known.end())
        throw Error(Pattern{"unknown smoke scenario '%1' (ball-drop, evh, liver-ablation)", {scenario}});
    SmokeSetup setup;
    setup.scenario = scenario;
    setup.parameters = ParameterSet(sim::smoke::smokeParameters(scenario));
    return setup;
}

SmokeRun runSmoke(const study::Study& study, const SmokeSetup& setup, const Progress& progress)
{
    SmokeRun result;
    result.scenario = setup.scenario;
    result.parameters = setup.parameters;
    const int cells = int(setup.parameters.get("grid_cells"));
    progress.report(0.0, localized("vsim::Progress", "smoke scene"));
    sim::smoke::SmokeScene scene;
    if (setup.scenario == "ball-drop")
        scene = sim::smoke::ballDropScene(cells);
    else if (setup.scenario == "evh")
    {
        std::string centerlines;
        const auto [points, radius] = longestSegment(study, centerlines);
        scene = sim::smoke::evhTunnelScene(points, radius, kEvhTunnelRadiusMm, cells);
        result.inputs.push_back(centerlines);
    }
    else
    {
        const std::string liver = newestLiver(study);
        if (liver.empty())
        {
            scene = sim::smoke::liverBoxScene(cells);
            result.warnings.push_back(storedText("no liver label in the study (vascusim-cli segment-organ --organ "
                                                 "liver): the box phantom was used"));
        }
        else
        {
            scene = sim::smoke::liverDomeScene(study.loadLabel(liver), cells);
            result.inputs.push_back(liver);
        }
    }
    result.description = scene.description;
    char grid[128];
    std::snprintf(grid, sizeof grid, "%d x %d x %d cells of %.2f mm", scene.grid.nx, scene.grid.ny, scene.grid.nz,
                  scene.grid.h * 1e3);
    result.grid = grid;
    sim::smoke::SmokeSolver solver(std::move(scene));
    if (chooseCuda(setup.backend, result.device))
    {
        solver.setBackend(gpuPlugin()->smokeBackendFactory());
        result.backend = "cuda";
    }
    sim::RunControl control;
    control.frameEvery = setup.parameters.get("end_time_s") / std::max(1, setup.frames);
    result.run = sim::runSolver(solver, {}, setup.parameters, control, progress.subRange(0.02, 1.0));
    result.obscuration = solver.obscurationCurve();
    return result;
}

std::string smokeDocument(const SmokeRun& run)
{
    nlohmann::json parameters;
    for (const ParameterSpec& spec : run.parameters.specs())
        parameters[spec.key] = run.parameters.get(spec.key);
    nlohmann::json curve = nlohmann::json::array();
    for (const auto& [time, fraction] : run.obscuration)
        curve.push_back({time, fraction});
    return nlohmann::json{{"scenario", run.scenario},
                          {"illustrative", true},
                          {"description", run.description},
                          {"grid", run.grid},
                          {"inputs", run.inputs},
                          {"backend", run.backend == "cuda" ? "cuda (single precision, " + run.device + ")"
                                                            : "cpu (single precision)"},
                          {"run_status", nlohmann::json::parse(runStatusJson(run.run.status))},
                          {"parameters", parameters},
                          {"metrics", run.run.metrics},
                          {"obscuration",
                           {{"definition", "share of the endoscope's pixels whose Beer-Lambert transmittance through the "
                                           "smoke is below the visibility threshold"},
                            {"columns", {"time_s", "obscured_fraction"}},
                            {"rows", curve}}},
                          {"frames", run.run.frames.size()},
                          {"warnings", run.warnings}}
               .dump(2) + "\n";
}

std::string addSmokeRun(study::Study& study, const SmokeRun& run)
{
    study::Provenance provenance{"simulate smoke", {}, run.inputs, "", ""};
    for (const ParameterSpec& spec : run.parameters.specs())
        provenance.parameters[spec.key] = preciseNumberText(run.parameters.get(spec.key));
    provenance.parameters["scenario"] = run.scenario;
    provenance.parameters["backend"] = run.backend;
    if (!run.device.empty())
        provenance.parameters["device"] = run.device;
    std::vector<std::string> warnings = run.warnings;
    if (const std::string status = runStatusWarning(run.run.status); !status.empty())
        warnings.insert(warnings.begin(), status);
    const std::string id = study.addRun(
        run.run, storedText(Pattern{"Surgical smoke (%1, illustrative)", {scenarioTitle(run.scenario)}}), provenance, warnings);
    std::map<std::string, std::string> attributes = runAttributes(run.run.metrics, run.run.status);
    nlohmann::json curve = nlohmann::json::array();
    for (const auto& [time, fraction] : run.obscuration)
        curve.push_back({time, fraction});
    attributes["obscuration_curve"] = curve.dump();
    attributes["scenario"] = run.scenario;
    study.setArtifactAttributes(id, attributes);
    return id;
}

} // namespace vsim::app
