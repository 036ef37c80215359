#include "vsim/app/WallPipeline.h"

#include "BackendChoice.h"
#include "GpuPlugin.h"
#include "ReportSupport.h"
#include "vsim/app/FlowWallPressure.h"
#include "vsim/app/RunRecord.h"
#include "vsim/app/SacRecord.h"
#include "vsim/core/Error.h"
#include "vsim/core/Localized.h"
#include "vsim/core/StoredText.h"
#include "vsim/mesh/SurfaceRemeshing.h"
#include "vsim/mesh/WallBoundary.h"
#include "vsim/mesh/VesselSurface.h"
#include "vsim/sim/fem/FemProtocols.h"
#include "vsim/sim/fem/StructuredMeshes.h"


#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <tuple>

namespace vsim::app {
std::vector<ParameterSpec> wallMeshParameters()
{
    const std::string group = "Wall mesh";
    return {
        {"thickness_mm", "Wall thickness", "mm", 1.5, 0.1, 10, group,
         "Offset of the lumen surface (one element layer); an assumption, CT does not resolve the wall: 1.5 mm, the "
         "uniform AAA wall of Raghavan et al. 2000 (J Vasc Surg 31:760)."},
        {"target_vertices", "Vertex budget", "", 3000, 200, 200000, group,
         "Sets the largest edge (thin vessels get 0.8 of their radius); thesis meshes: 1,427-2,251 vertices.",
         ParameterSpec::Kind::Integer},
        {"thrombus_layer", "Thrombus layer", "", 0, 0, 1, group,
         "1: the AAA sac's intraluminal thrombus as its own element layer between the lumen and the wall (needs the "
         "sac: Vessels > AAA Sac; run with the Raghavan-Vorp wall model). The CLI's mesh wall --thrombus.",
         ParameterSpec::Kind::Integer},
    };
}

TriangleMesh frameSurface(const TetMesh& frame, const std::string& cellField)
{
    const auto values = frame.cellFields.find(cellField);
    if (values == frame.cellFields.end())
        throw Error(Pattern{"the frame has no cell field '%1'", {cellField}});
    TriangleMesh surface;
    surface.points = frame.points;
    std::vector<std::size_t> owners;
    surface.triangles = boundaryFaces(frame.tets, &owners);
    std::vector<double> sum(frame.points.size(), 0.0), count(frame.points.size(), 0.0);
    for (std::size_t f = 0; f < surface.triangles.size(); ++f)
        for (int node : surface.triangles[f])
            sum[std::size_t(node)] += values->second[owners[f]], count[std::size_t(node)] += 1.0;
    std::vector<double> field(frame.points.size(), 0.0);
    for (std::size_t n = 0; n < field.size(); ++n)
        if (count[n] > 0.0)
            field[n] = sum[n] / count[n];
    surface.pointFields[cellField] = field;
    return surface;
}

TetMesh clothSheet(double widthMm, double lengthMm, double thicknessMm, double cellMm)
{
    if (!(widthMm > 0 && lengthMm > 0 && thicknessMm >= 0.05 && cellMm > 0))
        throw Error("a sheet needs a positive size, a cell size and at least 0.05 mm thickness");
    const std::array<int, 3> cells{std::max(1, int(std::lround(lengthMm / cellMm))),
                                   std::max(1, int(std::lround(widthMm / cellMm))), 1};
    const sim::fem::StructuredTetMesh box = sim::fem::boxTetMesh(Eigen::Vector3d(lengthMm, widthMm, thicknessMm), cells);
    TetMesh sheet;
    sheet.points = box.points;
    sheet.tets = box.tets;
    std::vector<double> layer, ends;
    for (const Eigen::Vector3d& p : box.points)
    {
        layer.push_back(p.z() > 0.5 * thicknessMm ? 1.0 : 0.0);
        ends.push_back(p.x() < 1e-9 ? 1.0 : p.x() > lengthMm - 1e-9 ? 2.0 : 0.0);
    }
    sheet.pointFields["wall_layer"] = layer;
    sheet.pointFields["end_set"] = ends;
    return sheet;
}

mesh::MarkedWall asWall(TetMesh mesh, const mesh::WallBoundarySelection& selection)
{
    const bool selected = !selection.pressureArray.empty() || selection.lumenPointMm || !selection.fixedArray.empty() ||
                          selection.fixOpenEnds;
    if (!selected && mesh.pointFields.count("wall_layer") && mesh.pointFields.count("end_set"))
    {
        mesh::MarkedWall kept; // a VascuSim wall: its own fields say where the pressure acts and what is held
        const auto& ends = mesh.pointFields.at("end_set");
        kept.fixedNodes = std::size_t(std::count_if(ends.begin(), ends.end(), [](double e) { return e > 0.0; }));
        kept.wall = std::move(mesh);
        return kept;
    }
    return mesh::markWallBoundary(std::move(mesh), selection);
}

WallMeshBuild buildWallMesh(const LabelVolume& label, const SkeletonGraph& centerlines, double thicknessMm,
                            double targetVertices, const Progress& progress, const LabelVolume* sacLabels)
{
    ParameterSet surfaceParameters(mesh::surfaceParameters());
    surfaceParameters.set("target_vertices", targetVertices);
    progress.report(0.0, localized("vsim::Progress", "lumen surface"));
    const mesh::VesselSurface decimated = mesh::extractVesselSurface(label, 1, surfaceParameters, progress.subRange(0.0, 0.7));
    WallMeshBuild build;
    // Decimation keeps the shape but leaves slivers; remeshing evens the triangles (SurfaceRemeshing.h).
    build.remeshEdgeMm = mesh::edgeForVertexBudget(decimated.surface.area(), targetVertices);
    progress.report(0.7, localized("vsim::Progress", "remeshing"));
    const TriangleMesh lumen =
        mesh::remeshIsotropic(decimated.surface, mesh::vesselSizing(centerlines, 0.8, build.remeshEdgeMm));
    progress.throwIfCancelled();
    progress.report(0.9, localized("vsim::Progress", "wall"));
    build.lumenVertices = lumen.points.size();
    build.smallestSurfaceAngleDeg = mesh::minTriangleAngle(lumen);
    build.wall = mesh::buildWallMesh(lumen, mesh::vesselEnds(centerlines), thicknessMm,
                                     sacLabels ? sacOuterWallDistance(*sacLabels) : mesh::OuterWallDistance{});
    progress.report(1.0, localized("vsim::Progress", "wall"));
    return build;
}

std::string addWallMesh(study::Study& study, const WallMeshBuild& build, const std::string& labelId,
                        const std::string& centerlinesId, double thicknessMm, double targetVertices,
                        const std::string& sacId)
{
    study::Provenance provenance;
    provenance.command = "mesh wall";
    provenance.inputs = {labelId, centerlinesId};
    provenance.parameters = {{"thickness_mm", numberText(thicknessMm)},
                             {"target_vertices", numberText(targetVertices)},
                             {"remesh_edge_mm", numberText(build.remeshEdgeMm)},
                             {"thrombus_from", sacId.empty() ? "none" : sacId}};
    if (!sacId.empty())
        provenance.inputs.push_back(sacId);
    const std::string id = study.addTetMesh(build.wall.mesh, storedText("Vessel wall"), provenance, build.wall.warnings);
    study.setArtifactAttributes(id, {{"min_dihedral_deg", numberText(build.wall.minDihedralDeg)},
                                     {"min_dihedral_unsmoothed_deg", numberText(build.wall.minDihedralUnsmoothedDeg)},
                                     {"nodes_smoothed", std::to_string(build.wall.nodesSmoothed)},
                                     {"edge_flips", std::to_string(build.wall.edgeFlips)},
                                     {"mean_min_dihedral_deg", numberText(build.wall.meanMinDihedralDeg)},
                                     {"elements_under_5_deg", std::to_string(build.wall.slivers)},
                                     {"inverted_elements", std::to_string(build.wall.inverted)},
                                     {"ends", std::to_string(build.wall.endNodes.size())},
                                     {"thrombus_elements", std::to_string(build.wall.thrombusElements)},
                                     {"max_thrombus_mm", numberText(build.wall.maxThrombusMm)},
                                     {"thrombus_sub_layers", std::to_string(build.wall.innerSubLayers)},
                                     {"thrombus_sub_layers_by_aspect", std::to_string(build.wall.innerSubLayersByAspect)}});
    return id;
}

std::vector<viz::Callout> sacPeakCallouts(const study::Artifact& run)
{
    std::vector<viz::Callout> callouts;
    for (const auto& [prefix, name, unit] : {std::tuple<std::string, std::string, std::string>{"sac_pws", "PWS", " kPa"},
                                             {"sac_pwri", "PWRI", ""}})
    {
        const auto metric = [&](const std::string& key) { return detail::runMetric(run, prefix + key, "", "", 1.0); };
        const auto x = metric("_x_mm"), y = metric("_y_mm"), z = metric("_z_mm"),
                   value = metric(unit.empty() ? "_nodal_max" : "_nodal_max_kpa"), hours = metric("_clock_h");
        if (!x || !y || !z || !value)
            continue;
        const bool behind = hours && hours->value > 3.0 && hours->value < 9.0; // the far side seen from the front
        callouts.push_back({Eigen::Vector3d(x->value, y->value, z->value),
                            name + " " + value->text + unit + (hours ? ", " + hours->text + " h" : "") +
                                (behind ? localized("Report", " (posterior)") : std::string())});
    }
    return callouts;
}

namespace {

/// A wall protocol's name inside an artifact's name: a stored text, so that the workstation shows it translated.
std::string protocolName(const std::string& protocol)
{
    if (protocol == "physiological")
        return storedText("physiological");
    if (protocol == "thesis-rupture")
        return storedText("thesis-rupture");
    if (protocol == "interactive")
        return storedText("interactive");
    return protocol;
}

/// Why this wall run cannot go to the GPU: no plugin or device, or a model the GPU stepper does not have; "" if it can.
std::string wallGpuUnavailable(const std::string& protocol, const ParameterSet& parameters)
{
    if (std::string reason = gpuUnavailableReason(); !reason.empty())
        return reason;
    if (sim::fem::femUsesQuadraticWall(protocol, parameters))
        return "the quadratic hyperelastic wall (wall_model 1) runs on the CPU: its GPU solver is not built yet";
    if (sim::fem::femUsesQuasiStaticTearing(protocol, parameters) && parameters.get("modified_newton") < 0.5)
        return "quasi-static tearing's full Newton iteration (modified_newton 0) runs on the CPU; the GPU runs the "
               "modified one (modified_newton 1)";
    if (sim::fem::femMaterial(parameters).model != sim::fem::ElasticMaterial::Model::CorotationalLinear)
        return "the CUDA backend runs the co-rotational linear model only";
    return {};
}

} // namespace

WallBackend chooseWallBackend(const std::string& requested, const std::string& protocol, const ParameterSet& parameters)
{
    std::string device;
    if (!chooseCuda(requested, device, [&] { return wallGpuUnavailable(protocol, parameters); }))
        return {};
    return {"cuda", device, gpuPlugin()->wallStepperFactory(), gpuPlugin()->wallStaticModelFactory()};
}

sim::fem::FemRunResult runWallProtocol(const study::Study& study, const std::string& protocol, const std::string& wallId,
                                       const std::string& centerlinesId, const ParameterSet& parameters,
                                       const WallBackend& backend, const Progress& progress)
{
    TetMesh wall = study.loadTetMesh(wallId);
    const auto started = std::chrono::steady_clock::now();
    sim::fem::FemRunResult run;
    if (protocol == "thesis-rupture")
        run = sim::fem::runThesisRupture(wall, parameters, progress, backend.stepper, backend.staticModel);
    else if (protocol == "physiological")
    {
        const SkeletonGraph centerlines = study.loadSkeleton(centerlinesId);
        const std::optional<sim::fem::SacRegion> sac = newestSacRegion(study, centerlines);
        std::optional<FlowWallPressure> flow;
        if (parameters.get("flow_wall_pressure") > 0.5)
            flow = addFlowWallPressure(study, wall);
        run = sim::fem::runPhysiological(wall, centerlines, parameters, progress, backend.stepper, sac ? &*sac : nullptr);
        if (flow)
        {
            run.record.provenance.inputs[kFlowWallLoadsInput] = flow->wallLoadsId;
            run.metrics["flow_pressure_lumen_points"] = double(flow->lumenPoints);
            run.metrics["flow_pressure_covered_share"] = double(flow->coveredPoints) / double(flow->lumenPoints);
            run.metrics["flow_pressure_min_pa"] = flow->smallestPa;
            run.metrics["flow_pressure_max_pa"] = flow->largestPa;
        }
    }
    else
        throw Error(Pattern{"unknown protocol '%1' (thesis-rupture, physiological, interactive)", {protocol}});
    run.metrics["wall_clock_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return run;
}

WallRunIds addWallRun(study::Study& study, const sim::fem::FemRunResult& run, const std::string& protocol,
                      const std::string& wallId, const std::string& centerlinesId, const ParameterSet& parameters,
                      const WallBackend& backend)
{
    study::Provenance provenance;
    provenance.command = "simulate fem";
    provenance.inputs = {wallId};
    if (!centerlinesId.empty())
        provenance.inputs.push_back(centerlinesId);
    provenance.parameters = sim::fem::femProtocolValues(parameters, protocol); // what the report's table lists
    provenance.parameters["protocol"] = protocol;
    provenance.parameters["backend"] = backend.name;
    if (!backend.device.empty())
        provenance.parameters["device"] = backend.device;
    std::vector<std::string> warnings;
    if (!run.stopReason.empty())
        warnings.push_back(storedText(Pattern{"stopped early: %1", {run.stopReason}}));
    if (const std::string status = runStatusWarning(run.status); !status.empty())
        warnings.push_back(status);
    SolverRun record = sim::fem::runOf(run);
    record.provenance.parameters = provenance.parameters;
    record.provenance.inputs = {{"wall", wallId}};
    if (!centerlinesId.empty())
        record.provenance.inputs["centerlines"] = centerlinesId;
    if (const auto flow = run.record.provenance.inputs.find(kFlowWallLoadsInput);
        flow != run.record.provenance.inputs.end()) // the blood flow's wall pressure it carried
    {
        provenance.inputs.push_back(flow->second), record.provenance.inputs[flow->first] = flow->second;
        if (const auto covered = run.metrics.find("flow_pressure_covered_share");
            covered != run.metrics.end() && covered->second < kFlowPressureCoveredWarning)
            warnings.push_back(storedText(Pattern{
                "the blood flow's wall pressure reached %1 % of the lumen; the rest carries the uniform pressure",
                {numberText(std::round(1000.0 * covered->second) / 10.0)}}));
    }
    WallRunIds ids;
    ids.run = study.addRun(record, storedText(Pattern{"Wall run (%1)", {protocolName(protocol)}}), provenance, warnings);
    ids.stress = study.addTetMesh(run.frames.back(), storedText(Pattern{"Wall stress (%1)", {protocolName(protocol)}}),
                                  provenance, warnings);
    std::map<std::string, std::string> attributes = runAttributes(run.metrics, run.status);
    attributes["run_artifact"] = ids.run;
    study.setArtifactAttributes(ids.stress, attributes);
    return ids;
}

} // namespace vsim::app
