#include "WallCommands.h"

#include "CliSupport.h"
#include "CommandLine.h"
#include "vsim/core/Error.h"
#include "vsim/core/OutputSafety.h"
#include "vsim/core/StoredText.h"
#include "vsim/app/RunRecord.h"
#include "vsim/app/SacRecord.h"
#include "vsim/app/WallPipeline.h"
#include "vsim/sim/fem/FemProtocols.h"
#include "vsim/study/MeshFileImport.h"
#include "vsim/study/RunSeries.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <iostream>

namespace vsim::cli {

namespace {

/// Adds a sheet or an imported mesh as a wall (provenance "mesh wall" so that simulate and the GUI find it).
int addOtherWall(study::Study& study, const TetMesh& wall, const std::string& name,
                 const std::map<std::string, std::string>& parameters)
{
    study::Provenance provenance;
    provenance.command = "mesh wall";
    provenance.parameters = parameters;
    const std::string id = study.addTetMesh(wall, name, provenance);
    study.save();
    std::cout << nlohmann::json{{"artifact", id}, {"nodes", wall.points.size()}, {"tets", wall.tets.size()}}.dump(2)
              << "\n";
    return 0;
}

} // namespace

int meshWall(const Arguments& arguments, const Progress& progress)
{
    const std::string kind = arguments.positional.empty() ? std::string() : arguments.positional.front();
    if (kind == "sheet")
    {
        study::Study study = openStudyForWriting(arguments);
        const double width = quantityOption(arguments, "width", "mm", 40.0);
        const double length = quantityOption(arguments, "length", "mm", 40.0);
        const double thickness = quantityOption(arguments, "thickness", "mm", 0.5);
        const double cell = quantityOption(arguments, "cell", "mm", 1.0);
        return addOtherWall(study, app::clothSheet(width, length, thickness, cell), storedText("Cloth sheet"),
                            {{"shape", "sheet"},
                             {"width_mm", numberText(width)},
                             {"length_mm", numberText(length)},
                             {"thickness_mm", numberText(thickness)},
                             {"cell_mm", numberText(cell)}});
    }
    if (kind == "import")
    {
        mesh::WallBoundarySelection selection;
        selection.pressureArray = arguments.option("pressure-array");
        selection.fixedArray = arguments.option("fixed-array");
        selection.fixOpenEnds = arguments.hasOption("fix-open-ends");
        if (arguments.hasOption("lumen-point"))
        {
            const auto xyz = parseTriple<double>(arguments.option("lumen-point"), ',', "lumen-point");
            selection.lumenPointMm = Eigen::Vector3d(xyz[0], xyz[1], xyz[2]);
        }
        if (!selection.pressureArray.empty() && selection.lumenPointMm)
            throw UsageError("give the pressure faces by --pressure-array or by --lumen-point, not both");
        if (!selection.fixedArray.empty() && selection.fixOpenEnds)
            throw UsageError("give the held nodes by --fixed-array or by --fix-open-ends, not both");
        const std::string file = arguments.positional[1];
        const mesh::MarkedWall marked = app::asWall(study::readTetMeshFile(file), selection);
        study::Study study = openStudyForWriting(arguments);
        study::Provenance provenance;
        provenance.command = "mesh wall";
        provenance.parameters = {{"shape", "imported"},
                                 {"source", std::filesystem::path(file).filename().string()},
                                 {"pressure_faces", std::to_string(marked.pressureFaces)},
                                 {"fixed_nodes", std::to_string(marked.fixedNodes)}};
        for (const auto& [key, value] : std::map<std::string, std::string>{
                 {"pressure_array", selection.pressureArray}, {"fixed_array", selection.fixedArray}})
            if (!value.empty())
                provenance.parameters[key] = value;
        if (selection.lumenPointMm)
            provenance.parameters["lumen_point_mm"] = arguments.option("lumen-point");
        if (selection.fixOpenEnds)
            provenance.parameters["fixed"] = "open ends";
        const std::string id = study.addTetMesh(marked.wall, storedText("Imported wall"), provenance, marked.warnings);
        study.save();
        std::cout << nlohmann::json{{"artifact", id},
                                    {"nodes", marked.wall.points.size()},
                                    {"tets", marked.wall.tets.size()},
                                    {"boundary_faces", marked.boundaryFaces},
                                    {"pressure_faces", marked.pressureFaces},
                                    {"open_loops", marked.openLoops},
                                    {"fixed_nodes", marked.fixedNodes},
                                    {"warnings", marked.warnings}}
                         .dump(2)
                  << "\n";
        return 0;
    }
    study::Study study = openStudyForWriting(arguments);
    const std::string centerlinesId = chooseCenterlines(study, arguments.option("centerlines"));
    // Without --label: the lumen the centerlines were traced from, so that the wall's provenance names its input.
    const std::string labelId = arguments.hasOption("label")
                                    ? chooseArtifact(study, arguments.option("label"), study::ArtifactKind::Label, {})
                                    : app::lumenLabelOfCenterlines(study, centerlinesId);
    if (labelId.empty())
        throw Error("the study has no vessel label: run vascusim-cli segment first");
    const double thickness = quantityOption(arguments, "thickness", "mm", 1.5);
    const double targetVertices = quantityOption(arguments, "target-vertices", "", 3000.0);
    std::string sacId;
    if (arguments.hasOption("thrombus"))
    {
        app::newestSacFigures(study, &sacId);
        if (sacId.empty())
            throw Error("--thrombus needs the study's AAA sac: run vascusim-cli sac first");
    }
    const std::optional<LabelVolume> sacLabels =
        sacId.empty() ? std::nullopt : std::optional<LabelVolume>(study.loadLabel(sacId));
    const app::WallMeshBuild build =
        app::buildWallMesh(study.loadLabel(labelId), study.loadSkeleton(centerlinesId), thickness, targetVertices,
                           progress.subRange(0.0, 0.95), sacLabels ? &*sacLabels : nullptr);
    const mesh::WallMesh& wall = build.wall;
    const std::string id = app::addWallMesh(study, build, labelId, centerlinesId, thickness, targetVertices, sacId);
    study.save();
    progress.report(1.0, "saved");
    nlohmann::json ends = nlohmann::json::array();
    for (const auto& nodes : wall.endNodes)
        ends.push_back(nodes.size());
    std::cout << nlohmann::json{{"artifact", id},
                                {"lumen_label", labelId},
                                {"centerlines", centerlinesId},
                                {"nodes", wall.mesh.points.size()},
                                {"tets", wall.mesh.tets.size()},
                                {"thickness_mm", thickness},
                                {"surface_vertices", build.lumenVertices},
                                {"remesh_edge_mm", build.remeshEdgeMm},
                                {"smallest_surface_angle_deg", build.smallestSurfaceAngleDeg},
                                {"elements_under_5_deg", wall.slivers},
                                {"min_dihedral_deg", wall.minDihedralDeg},
                                {"min_dihedral_unsmoothed_deg", wall.minDihedralUnsmoothedDeg},
                                {"nodes_smoothed", wall.nodesSmoothed},
                                {"edge_flips", wall.edgeFlips},
                                {"largest_smoothing_move_mm", wall.largestSmoothingMoveMm},
                                {"worst_element_mm", {wall.worstElementMm.x(), wall.worstElementMm.y(), wall.worstElementMm.z()}},
                                {"mean_min_dihedral_deg", wall.meanMinDihedralDeg},
                                {"inverted_elements", wall.inverted},
                                {"thrombus_from", sacId.empty() ? "none" : sacId},
                                {"thrombus_elements", wall.thrombusElements},
                                {"max_thrombus_mm", wall.maxThrombusMm},
                                {"thrombus_sub_layers", sacId.empty() ? 0 : wall.innerSubLayers},
                                {"thrombus_sub_layers_by_aspect", sacId.empty() ? 0 : wall.innerSubLayersByAspect},
                                {"end_nodes", ends},
                                {"warnings", wall.warnings}}
                     .dump(2)
              << "\n";
    return 0;
}

int simulateFem(const Arguments& arguments, const Progress& progress)
{
    const std::string protocol = arguments.option("protocol");
    if (protocol == "interactive")
        throw Error("the interactive protocol needs the workstation (vascusim): it drags the wall with the mouse");
    if (protocol != "thesis-rupture" && protocol != "physiological")
        throw Error("unknown protocol '" + protocol + "' (thesis-rupture, physiological, interactive)");
    if (arguments.hasOption("out")) // before the run: a refused folder costs no time
        checkOutputFolder(arguments.option("out"), "run");
    study::Study study = openStudyForWriting(arguments);
    const std::string meshId = chooseMadeBy(study, arguments.option("mesh"), study::ArtifactKind::TetMesh, "mesh wall",
                                            "the study has no wall mesh: run vascusim-cli mesh wall first");
    ParameterSet parameters(sim::fem::femParameters());
    applyParameters(arguments, parameters);
    const app::WallBackend backend = app::chooseWallBackend(arguments.option("backend", "auto"), protocol, parameters);
    const std::string centerlinesId =
        protocol == "physiological" ? chooseCenterlines(study, arguments.option("centerlines")) : std::string();
    const sim::fem::FemRunResult run =
        app::runWallProtocol(study, protocol, meshId, centerlinesId, parameters, backend, progress.subRange(0.0, 0.95));
    nlohmann::json metrics(run.metrics);
    nlohmann::json entropy = nlohmann::json::array();
    for (const auto& [pressure, value] : run.entropyCurve)
        entropy.push_back({{"pressure_mpa", pressure * 1e-6}, {"entropy", value}});
    const nlohmann::json document{{"protocol", protocol},
                                  {"mesh", meshId},
                                  {"backend", backend.name},
                                  {"device", backend.device},
                                  {"metrics", metrics},
                                  {"entropy_curve", entropy},
                                  {"stop_reason", run.stopReason},
                                  {"run_status", nlohmann::json::parse(app::runStatusJson(run.status))},
                                  {"step_solves", {{"pcg_iterations", run.stepIterations},
                                                   {"relative_residuals", run.stepResiduals}}},
                                  {"equilibrium_force_residuals", run.equilibriumResiduals},
                                  {"frames", run.frames.size()},
                                  {"frame_times_s", run.frameTimesS},
                                  {"frame_pressures_kpa", [&run] {
                                       std::vector<double> kpa;
                                       for (double pa : run.framePressuresPa)
                                           kpa.push_back(1e-3 * pa);
                                       return kpa;
                                   }()},
                                  {"parameters", sim::fem::femProtocolValues(parameters, protocol)}};

    const app::WallRunIds ids = app::addWallRun(study, run, protocol, meshId, centerlinesId, parameters, backend);
    study.save();
    if (arguments.hasOption("out"))
    {
        claimOutputFolder(arguments.option("out"), "run");
        study::writeRunSeries(arguments.option("out"), sim::fem::runOf(run), document.dump(2));
    }
    progress.report(1.0, "saved");
    nlohmann::json printed = document;
    printed["artifact"] = ids.stress;
    printed["run_artifact"] = ids.run;
    std::cout << printed.dump(2) << "\n";
    return runExitCode(run.status, ids.stress);
}

} // namespace vsim::cli
