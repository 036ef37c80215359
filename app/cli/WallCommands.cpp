#include "WallCommands.h"

#include "CliSupport.h"
#include "vsim/core/Error.h"
#include "vsim/mesh/SurfaceRemeshing.h"
#include "vsim/mesh/VesselSurface.h"
#include "vsim/mesh/WallMesh.h"
#include "vsim/sim/fem/FemProtocols.h"
#include "vsim/study/RunSeries.h"

#include <nlohmann/json.hpp>

#include <iostream>

namespace vsim::cli {

int meshWall(const Arguments& arguments, const Progress& progress)
{
    const std::string bundle = arguments.option("study");
    if (bundle.empty() || arguments.positional != std::vector<std::string>{"wall"})
        throw Error("usage: vascusim-cli mesh wall --study <study.vsim> [--label ID] [--centerlines ID] "
                    "[--thickness mm] [--target-vertices N]");
    study::Study study = study::Study::open(bundle);
    const std::string centerlinesId = chooseCenterlines(study, arguments.option("centerlines"));
    const std::string labelId = chooseArtifact(study, arguments.option("label"), study::ArtifactKind::Label,
                                               "the study has no vessel label: run vascusim-cli segment first");
    const double thickness = std::stod(arguments.option("thickness", "1.5"));
    ParameterSet surfaceParameters(mesh::surfaceParameters());
    surfaceParameters.set("target_vertices", std::stod(arguments.option("target-vertices", "3000")));
    progress.report(0.0, "lumen surface");
    const mesh::VesselSurface decimated =
        mesh::extractVesselSurface(study.loadLabel(labelId), 1, surfaceParameters, progress.subRange(0.0, 0.7));
    // Decimation keeps the shape but leaves slivers; remeshing evens the triangles: edges of the budget's length,
    // shorter in thin vessels (0.8 of the local radius) so that they keep several edges around.
    const SkeletonGraph centerlines = study.loadSkeleton(centerlinesId);
    const double edge = mesh::edgeForVertexBudget(decimated.surface.area(), surfaceParameters.get("target_vertices"));
    progress.report(0.7, "remeshing");
    const TriangleMesh lumen = mesh::remeshIsotropic(decimated.surface, mesh::vesselSizing(centerlines, 0.8, edge));
    const mesh::WallMesh wall = mesh::buildWallMesh(lumen, mesh::vesselEnds(centerlines), thickness);
    study::Provenance provenance;
    provenance.command = "mesh wall";
    provenance.inputs = {labelId, centerlinesId};
    provenance.parameters = provenanceParameters(surfaceParameters);
    provenance.parameters["thickness_mm"] = formatNumber(thickness);
    provenance.parameters["remesh_edge_mm"] = formatNumber(edge);
    const std::string id = study.addTetMesh(wall.mesh, "Vessel wall", provenance, wall.warnings);
    study.setArtifactAttributes(id, {{"min_dihedral_deg", formatNumber(wall.minDihedralDeg)},
                                     {"mean_min_dihedral_deg", formatNumber(wall.meanMinDihedralDeg)},
                                     {"inverted_elements", std::to_string(wall.inverted)},
                                     {"elements_under_5_deg", std::to_string(wall.slivers)},
                                     {"ends", std::to_string(wall.endNodes.size())}});
    study.save();
    progress.report(1.0, "saved");
    nlohmann::json ends = nlohmann::json::array();
    for (const auto& nodes : wall.endNodes)
        ends.push_back(nodes.size());
    std::cout << nlohmann::json{{"artifact", id},
                                {"nodes", wall.mesh.points.size()},
                                {"tets", wall.mesh.tets.size()},
                                {"thickness_mm", thickness},
                                {"surface_vertices", lumen.points.size()},
                                {"remesh_edge_mm", edge},
                                {"smallest_surface_angle_deg", mesh::minTriangleAngle(lumen)},
                                {"elements_under_5_deg", wall.slivers},
                                {"min_dihedral_deg", wall.minDihedralDeg},
                                {"worst_element_mm", {wall.worstElementMm.x(), wall.worstElementMm.y(), wall.worstElementMm.z()}},
                                {"mean_min_dihedral_deg", wall.meanMinDihedralDeg},
                                {"inverted_elements", wall.inverted},
                                {"end_nodes", ends},
                                {"warnings", wall.warnings}}
                     .dump(2)
              << "\n";
    return 0;
}

int simulateFem(const Arguments& arguments, const Progress& progress)
{
    const std::string bundle = arguments.option("study"), protocol = arguments.option("protocol");
    if (bundle.empty() || arguments.positional != std::vector<std::string>{"fem"} || protocol.empty())
        throw Error("usage: vascusim-cli simulate fem --study <study.vsim> --protocol thesis-rupture|physiological "
                    "[--mesh ID] [--centerlines ID] [--backend auto|cpu] [--param key=value] [--out DIR]");
    const std::string backend = arguments.option("backend", "auto");
    if (backend == "cuda")
        throw Error("simulate fem runs on the CPU in this version (the CUDA backend is benchmarked and checked "
                    "against it by tst_gpu_fem); use --backend cpu or auto");
    if (backend != "auto" && backend != "cpu")
        throw Error("unknown backend '" + backend + "' (auto, cpu)");
    if (protocol == "interactive")
        throw Error("the interactive protocol needs the workstation (vascusim): it drags the wall with the mouse");
    if (protocol != "thesis-rupture" && protocol != "physiological")
        throw Error("unknown protocol '" + protocol + "' (thesis-rupture, physiological, interactive)");
    study::Study study = study::Study::open(bundle);
    const std::string meshId = chooseMadeBy(study, arguments.option("mesh"), study::ArtifactKind::TetMesh, "mesh wall",
                                            "the study has no wall mesh: run vascusim-cli mesh wall first");
    ParameterSet parameters(sim::fem::femParameters());
    applyParameters(arguments, parameters);
    const TetMesh wall = study.loadTetMesh(meshId);
    std::string centerlinesId;
    sim::fem::FemRunResult run;
    if (protocol == "thesis-rupture")
        run = sim::fem::runThesisRupture(wall, parameters, progress.subRange(0.0, 0.95));
    else
    {
        centerlinesId = chooseCenterlines(study, arguments.option("centerlines"));
        run = sim::fem::runPhysiological(wall, study.loadSkeleton(centerlinesId), parameters, progress.subRange(0.0, 0.95));
    }
    nlohmann::json metrics(run.metrics);
    nlohmann::json entropy = nlohmann::json::array();
    for (const auto& [pressure, value] : run.entropyCurve)
        entropy.push_back({{"pressure_mpa", pressure * 1e-6}, {"entropy", value}});
    const nlohmann::json document{{"protocol", protocol},
                                  {"mesh", meshId},
                                  {"backend", "cpu"},
                                  {"metrics", metrics},
                                  {"entropy_curve", entropy},
                                  {"stop_reason", run.stopReason},
                                  {"frames", run.frames.size()},
                                  {"parameters", provenanceParameters(parameters)}};

    study::Provenance provenance;
    provenance.command = "simulate fem";
    provenance.inputs = {meshId};
    if (!centerlinesId.empty())
        provenance.inputs.push_back(centerlinesId);
    provenance.parameters = provenanceParameters(parameters);
    provenance.parameters["protocol"] = protocol;
    provenance.parameters["backend"] = "cpu";
    std::vector<std::string> warnings = run.warnings;
    if (!run.stopReason.empty())
        warnings.push_back("stopped early: " + run.stopReason);
    const std::string id = study.addTetMesh(run.frames.back(), "Wall stress (" + protocol + ")", provenance, warnings);
    std::map<std::string, std::string> attributes;
    for (const auto& [key, value] : run.metrics)
        attributes[key] = formatNumber(value);
    study.setArtifactAttributes(id, attributes);
    study.save();
    if (arguments.hasOption("out"))
        study::writeRunSeries(arguments.option("out"), run.frames, run.frameTimesS, document.dump(2));
    progress.report(1.0, "saved");
    nlohmann::json printed = document;
    printed["artifact"] = id;
    std::cout << printed.dump(2) << "\n";
    return 0;
}

} // namespace vsim::cli
