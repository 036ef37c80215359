// The blood-flow run's document (the CLI's output, the run folder's metrics.json) and its record in the study.

#include "SphPipelineSupport.h"
#include "vsim/app/BloodFlowPipeline.h"
#include "vsim/app/RunRecord.h"
#include "vsim/core/StoredText.h"
#include "vsim/core/Units.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <tuple>

namespace vsim::app {
namespace {

/// The stenosis figures with their definitions (StenosisFigures.h), as the document and the attributes name them.
std::vector<std::tuple<std::string, double, std::string>> stenosisRows(const BloodFlowRun& flow)
{
    const sim::sph::StenosisFigures& s = *flow.stenosis;
    const sim::sph::SectionFlow &t = flow.sections[s.throat], &u = flow.sections[s.upstream], &d = flow.sections[s.downstream];
    return {{"throat_position_mm", s.throatArcMm, "along the centerline from the inlet's plane"},
            {"compared_at_mm", s.distanceMm, "upstream and downstream of the throat, along the centerline"},
            {"area_ratio", s.areaRatio, "flow area upstream / in the throat (from the particles)"},
            {"peak_velocity_ratio", s.peakRatio, "peak velocity in the throat / upstream (duplex PSV ratio's counterpart)"},
            {"peak_velocity_ratio_downstream", s.peakRatioDownstream, "peak velocity in the throat / downstream"},
            {"mean_velocity_ratio", s.meanRatio, "mean velocity in the throat / upstream (a mass check: the area ratio)"},
            {"mean_velocity_ratio_downstream", s.meanRatioDownstream, "mean velocity in the throat / downstream"},
            {"throat_peak_velocity_m_s", t.peakVelocityMS, "mean of the fastest 5 % of the throat's particles, time-averaged"},
            {"upstream_peak_velocity_m_s", u.peakVelocityMS, "as the throat's"},
            {"throat_mean_velocity_m_s", t.meanVelocityMS, "flow rate / area"},
            {"pressure_drop_pa", s.pressureDropPa, "section-mean pressure upstream - downstream"},
            {"pressure_drop_mmhg", units::paToMmHg(s.pressureDropPa), "as pressure_drop_pa"},
            {"pressure_ratio", s.pressureRatio,
             "distal / proximal section-mean gauge pressure (the outlets at their given pressure)"},
            {"upstream_pressure_pa", u.meanPressurePa, "section mean"},
            {"downstream_pressure_pa", d.meanPressurePa, "section mean"},
            {"flow_rate_ratio", s.flowRateRatio, "throat / upstream flow rate: 1 for a settled, conserved flow"}};
}

/// The wall loads' summary (sim/sph/WallShear.h): where the time-averaged wall shear stress, the OSI and the wall
/// pressure peak on the lumen surface; nothing when no vertex was sampled.
struct WallLoadSummary
{
    std::size_t vertices = 0, sampled = 0, peakShear = 0, peakOsi = 0, highPressure = 0, lowPressure = 0;
    double meanShearPa = 0.0;
};

std::optional<WallLoadSummary> summariseWallLoads(const TriangleMesh& surface)
{
    if (!surface.pointFields.count("tawss_pa"))
        return std::nullopt;
    const std::vector<double>&tawss = surface.pointFields.at("tawss_pa"), &osi = surface.pointFields.at("osi"),
                            &pressure = surface.pointFields.at("wall_pressure_pa");
    WallLoadSummary w;
    w.vertices = tawss.size();
    for (std::size_t v = 0; v < tawss.size(); ++v)
    {
        if (!std::isfinite(tawss[v]))
            continue;
        if (w.sampled++ == 0)
            w.peakShear = w.peakOsi = w.highPressure = w.lowPressure = v;
        w.meanShearPa += tawss[v];
        w.peakShear = tawss[v] > tawss[w.peakShear] ? v : w.peakShear;
        w.peakOsi = osi[v] > osi[w.peakOsi] ? v : w.peakOsi;
        w.highPressure = pressure[v] > pressure[w.highPressure] ? v : w.highPressure;
        w.lowPressure = pressure[v] < pressure[w.lowPressure] ? v : w.lowPressure;
    }
    if (w.sampled == 0)
        return std::nullopt;
    w.meanShearPa /= double(w.sampled);
    return w;
}

/// The summary's figures (value, the vertex it is at or none, definition), as the document and the attributes name
/// them (key prefix "wall_").
std::vector<std::tuple<std::string, double, std::optional<std::size_t>, std::string>> wallLoadRows(const TriangleMesh& surface,
                                                                                                 const WallLoadSummary& w)
{
    const auto& f = surface.pointFields;
    return {{"largest_tawss_pa", f.at("tawss_pa")[w.peakShear], w.peakShear,
             "largest time-averaged wall shear stress (mean |tau_w|) on the lumen surface"},
            {"mean_tawss_pa", w.meanShearPa, std::nullopt, "the vertices' mean time-averaged wall shear stress"},
            {"largest_osi", f.at("osi")[w.peakOsi], w.peakOsi, "largest oscillatory shear index (1 - |mean tau_w| / TAWSS) / 2"},
            {"highest_pressure_pa", f.at("wall_pressure_pa")[w.highPressure], w.highPressure,
             "highest time-averaged wall pressure, gauge (the outlets at their given pressure)"},
            {"lowest_pressure_pa", f.at("wall_pressure_pa")[w.lowPressure], w.lowPressure,
             "lowest time-averaged wall pressure, gauge (the outlets at their given pressure)"}};
}

nlohmann::json wallLoadsJson(const TriangleMesh& surface)
{
    const std::optional<WallLoadSummary> w = summariseWallLoads(surface);
    if (!w)
        return nullptr;
    nlohmann::json json{{"definition", "on the lumen surface's vertices, time-averaged with the sections; tau_w the "
                                       "friction the wall particles put on the fluid particles in a column a kernel "
                                       "support deep (Morris' no-slip viscous term), over the column's cross-section"},
                        {"vertices", w->vertices},
                        {"sampled_vertices", w->sampled}};
    for (const auto& [key, value, vertex, definition] : wallLoadRows(surface, *w))
    {
        json[key] = {{"value", value}, {"definition", definition}};
        if (vertex)
        {
            const Eigen::Vector3d& p = surface.points[*vertex];
            json[key]["at_mm"] = {p.x(), p.y(), p.z()};
        }
    }
    return json;
}

} // namespace

std::string bloodFlowDocument(const BloodFlowRun& flow, const BloodFlowSetup& setup)
{
    nlohmann::json boundaries = nlohmann::json::array();
    for (const auto& b : flow.boundaries)
        boundaries.push_back(openBoundaryJson(b));
    nlohmann::json parameters;
    for (const ParameterSpec& spec : flow.parameters.specs())
        parameters[spec.key] = flow.parameters.get(spec.key);
    nlohmann::json sections = nlohmann::json::array();
    for (std::size_t k = 0; k < flow.sections.size(); ++k)
    {
        const sim::sph::SectionFlow& s = flow.sections[k];
        const Eigen::Vector3d& c = flow.sectionCentresMm[k];
        sections.push_back({{"arc_mm", flow.sectionArcMm[k]},
                            {"centre_mm", {c.x(), c.y(), c.z()}},
                            {"area_mm2", 1e6 * s.areaM2},
                            {"flow_rate_ml_s", 1e6 * s.flowRateM3S},
                            {"mean_velocity_m_s", s.meanVelocityMS},
                            {"peak_velocity_m_s", s.peakVelocityMS},
                            {"largest_peak_velocity_m_s", k < flow.sectionLargestPeaks.size() ? flow.sectionLargestPeaks[k] : 0.0},
                            {"mean_pressure_pa", s.meanPressurePa}});
    }
    nlohmann::json stenosis = nullptr;
    if (flow.stenosis)
    {
        stenosis = nlohmann::json::object();
        for (const auto& [key, value, definition] : stenosisRows(flow))
            stenosis[key] = {{"value", value}, {"definition", definition}};
    }
    return nlohmann::json{{"centerlines", setup.centerlinesId},
                          {"backend", flow.backend == "cuda" ? "cuda (single precision, " + flow.device + ")"
                                                             : std::string("cpu (double precision)")},
                          {"run_status", nlohmann::json::parse(runStatusJson(flow.run.status))},
                          {"boundaries", boundaries},
                          {"parameters", parameters},
                          {"ramp_s", flow.rampS},
                          {"settling_s", flow.settlingS},
                          {"averaged", {{"from_s", flow.averagedFromS}, {"over_s", flow.averagedS}}},
                          {"metrics", flow.run.metrics},
                          {"stenosis", stenosis},
                          {"sections", sections},
                          {"wall_loads", wallLoadsJson(flow.wallSurface)},
                          {"frames", flow.run.frames.size()},
                          {"precision", flow.backend == "cuda" ? "single (GPU)" : "double (CPU)"},
                          {"warnings", flow.warnings}}
               .dump(2) + "\n";
}

BloodFlowArtifacts addBloodFlowRun(study::Study& study, const BloodFlowRun& flow, const BloodFlowSetup& setup,
                            const std::vector<std::string>& inputs)
{
    study::Provenance provenance{"simulate sph", {}, inputs, "", ""};
    for (const ParameterSpec& spec : flow.parameters.specs())
        provenance.parameters[spec.key] = preciseNumberText(flow.parameters.get(spec.key));
    provenance.parameters["ramp_s"] = preciseNumberText(flow.rampS);
    provenance.parameters["settling_s"] = preciseNumberText(flow.settlingS);
    provenance.parameters["outlet_pressure_pa"] = preciseNumberText(setup.outletPressurePa);
    provenance.parameters["compare_mm"] = preciseNumberText(setup.compareMm);
    provenance.parameters["backend"] = flow.backend;
    if (!flow.device.empty())
        provenance.parameters["device"] = flow.device;
    for (const auto& b : flow.boundaries)
        provenance.parameters["boundary " + b.name] = openBoundaryJson(b).dump();
    std::vector<std::string> warnings = flow.warnings;
    const std::string statusWarning = runStatusWarning(flow.run.status);
    if (!statusWarning.empty())
        warnings.insert(warnings.begin(), statusWarning);
    const std::string id = study.addRun(flow.run, storedText("Blood flow (SPH)"), provenance, warnings);
    std::map<std::string, std::string> attributes = runAttributes(flow.run.metrics, flow.run.status);
    if (flow.stenosis)
        for (const auto& [key, value, definition] : stenosisRows(flow))
            attributes["stenosis_" + key] = preciseNumberText(value);
    if (const std::optional<WallLoadSummary> w = summariseWallLoads(flow.wallSurface))
        for (const auto& [key, value, vertex, definition] : wallLoadRows(flow.wallSurface, *w))
            attributes["wall_" + key] = preciseNumberText(value);
    nlohmann::json sections = nlohmann::json::array(); // compact: the GUI's plots along the centerline read it back
    for (std::size_t k = 0; flow.averagedS > 0.0 && k < flow.sections.size() && k < flow.sectionArcMm.size(); ++k)
        sections.push_back({flow.sectionArcMm[k], flow.sections[k].peakVelocityMS, flow.sections[k].meanVelocityMS,
                            flow.sections[k].meanPressurePa});
    if (!sections.empty()) // none when the run ended before its averaging window
        attributes["sections_along_centerline"] =
        nlohmann::json{{"columns", {"arc_mm", "peak_velocity_m_s", "mean_velocity_m_s", "mean_pressure_pa"}},
                       {"averaged_from_s", flow.averagedFromS},
                       {"averaged_over_s", flow.averagedS},
                       {"rows", sections}}
            .dump();
    study.setArtifactAttributes(id, attributes);
    BloodFlowArtifacts added{id, ""};
    const auto tawss = flow.wallSurface.pointFields.find("tawss_pa");
    if (tawss != flow.wallSurface.pointFields.end() &&
        std::any_of(tawss->second.begin(), tawss->second.end(), [](double v) { return std::isfinite(v); }))
    {
        study::Provenance derived{"simulate sph", {}, {id}, "", ""};
        derived.parameters["fields"] =
            "tawss_pa, osi, wall_pressure_pa (NaN past an open end's plane and within a kernel support inside it)";
        derived.parameters["averaged_from_s"] = preciseNumberText(flow.averagedFromS); // the time window
        derived.parameters["averaged_over_s"] = preciseNumberText(flow.averagedS);
        added.wallLoads = study.addSurface(flow.wallSurface, storedText("Wall loads (SPH)"), derived, warnings);
    }
    return added;
}

std::vector<SectionAlongCenterline> sectionsAlongCenterline(const study::Artifact& run)
{
    const auto text = run.attributes.find("sections_along_centerline");
    if (text == run.attributes.end())
        return {};
    const nlohmann::json json = nlohmann::json::parse(text->second, nullptr, false);
    std::vector<SectionAlongCenterline> sections;
    if (json.is_discarded() || !json.contains("rows"))
        return sections;
    for (const auto& row : json.at("rows"))
        if (row.is_array() && row.size() == 4 &&
            std::all_of(row.begin(), row.end(), [](const nlohmann::json& v) { return v.is_number(); }))
            sections.push_back({row[0].get<double>(), row[1].get<double>(), row[2].get<double>(), row[3].get<double>()});
    return sections;
}

} // namespace vsim::app
