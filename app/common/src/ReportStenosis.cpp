#include "ReportSections.h"

#include "ReportSupport.h"
#include "vsim/app/BloodFlowPipeline.h"
#include "vsim/app/RunRecord.h"
#include "vsim/core/Error.h"
#include "vsim/core/Units.h"
#include "vsim/viz/Snapshot.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace vsim::app::detail {
namespace {

constexpr double kReportedStenosisPercent = 40.0; // a narrowing from which the stenosis section is written

/// The run's time-averaged sections along the centerline: peak and mean velocity (m/s), mean pressure (mmHg).
std::vector<report::Plot> alongCenterlinePlots(const study::Artifact& flow)
{
    const std::vector<SectionAlongCenterline> along = sectionsAlongCenterline(flow);
    if (along.empty())
        return {};
    const std::string distance = localized("Report", "Distance along the centerline from the inlet [mm]");
    report::Plot velocity{
        localized("Report", "Velocity along the centerline (cross-sections of the same run, time-averaged)"),
        distance,
        localized("Report", "Velocity [m/s]"),
        {},
        {}};
    report::PlotSeries peak{localized("Report", "peak (fastest 5 % of the section)"), {}},
        mean{localized("Report", "mean (flow rate / area)"), {}};
    report::Plot pressure{localized("Report", "Mean pressure along the centerline (gauge; the same sections)"),
                          distance,
                          localized("Report", "Pressure [mmHg]"),
                          {},
                          {}};
    report::PlotSeries level{localized("Report", "section mean"), {}};
    for (const SectionAlongCenterline& s : along)
    {
        peak.points.emplace_back(s.arcMm, s.peakVelocityMS);
        mean.points.emplace_back(s.arcMm, s.meanVelocityMS);
        level.points.emplace_back(s.arcMm, units::paToMmHg(s.meanPressurePa));
    }
    velocity.series = {peak, mean};
    pressure.series = {level};
    return {velocity, pressure};
}

/// The "Wall loads (SPH)" surface made from `run` (the newest), or nullptr.
const study::Artifact* wallLoadsOf(const study::Study& study, const std::string& run)
{
    const study::Artifact* found = nullptr;
    for (const study::Artifact& a : study.artifacts())
        if (a.kind == study::ArtifactKind::Surface && a.provenance.command == "simulate sph" &&
            std::count(a.provenance.inputs.begin(), a.provenance.inputs.end(), run))
            found = &a;
    return found;
}

/// The lumen surface coloured by TAWSS from 0 to its largest value, which is called out.
QImage wallShearPicture(const study::Study& study, const study::Artifact& surfaceArtifact, QSize pixels)
{
    const TriangleMesh surface = study.loadSurface(surfaceArtifact.id);
    const auto field = surface.pointFields.find("tawss_pa");
    if (field == surface.pointFields.end())
        throw Error("the wall-load surface has no TAWSS");
    const std::vector<double>& tawss = field->second;
    std::size_t largest = tawss.size();
    for (std::size_t v = 0; v < tawss.size(); ++v)
        if (std::isfinite(tawss[v]) && (largest == tawss.size() || tawss[v] > tawss[largest]))
            largest = v;
    if (largest == tawss.size())
        throw Error("no vertex of the wall-load surface was sampled");
    const double high = std::max(tawss[largest], 1e-6);
    const viz::Callout callout{surface.points[largest],
                               withArguments(localized("Report", "largest TAWSS %1 Pa"), {fixed(high, 2)})};
    return viz::snapshotSurface(surface, "tawss_pa", {localized("Report", "TAWSS [Pa]"), 0.0, high}, pixels, {callout});
}

} // namespace

std::optional<report::Section> stenosisSection(const study::Study& study, VesselSections& sections,
                                               const ReportOptions& options, const Progress& progress)
{
    const imaging::VesselMeasurements* measured =
        sections.of(study.newestArtifact(study::ArtifactKind::Skeleton, "centerline"), progress);
    if (!measured || measured->worstStenosisSegment < 0)
        return std::nullopt;
    const imaging::SegmentMeasurements& worst = measured->segments[std::size_t(measured->worstStenosisSegment)];
    if (worst.diameterStenosisPercent < kReportedStenosisPercent)
        return std::nullopt;
    report::Section section{"stenosis", localized("Report", "Stenosis / blockage"), {}};
    report::MetricTable geometry{
        localized("Report", "The narrowest segment (cross-sections perpendicular to the centerline)"), {}};
    geometry.rows = {
        report::metric("diameter_stenosis_percent", localized("Report", "Diameter stenosis"),
                       worst.diameterStenosisPercent, "%"),
        report::metric("area_stenosis_percent", localized("Report", "Area stenosis"), worst.areaStenosisPercent, "%"),
        report::metric("reference_diameter_mm", localized("Report", "Reference diameter (median)"),
                       worst.referenceDiameterMm, "mm"),
        report::metric("minimal_diameter_mm", localized("Report", "Minimal diameter"), worst.minimalDiameterMm, "mm"),
        report::metric("segment_length_mm", localized("Report", "Segment length"), worst.lengthMm, "mm")};
    section.blocks.push_back(geometry);
    report::Plot plot = diameterPlot(worst, localized("Report", "Diameter along the narrowest segment"));
    plot.references = {{localized("Report", "reference diameter"), worst.referenceDiameterMm}};
    section.blocks.push_back(plot);
    const study::Artifact* flow = newestRun(study, "simulate sph", {}, {}, study::ArtifactKind::Run);
    if (!flow || !flow->attributes.count("stenosis_peak_velocity_ratio"))
    {
        section.blocks.push_back(report::Paragraph{
            flow ? localized("Report",
                             "Blockage velocity ratios and the pressure drop come from a blood-flow run (Flow > "
                             "Blood Flow, vascusim-cli simulate sph); the study's run has no settled flow to "
                             "measure them (see its warnings).")
                 : localized("Report",
                             "Blockage velocity ratios and the pressure drop come from a blood-flow run (Flow > "
                             "Blood Flow, vascusim-cli simulate sph); this study has none.")});
        return section;
    }
    const std::string compared = textOr(flow->attributes, "stenosis_compared_at_mm", "?");
    const std::string outlets = textOr(flow->provenance.parameters, "outlet_pressure_pa", "0");
    report::MetricTable figures{
        withArguments(localized("Report", "Blood flow (SPH run %1): the throat against the sections %2 mm upstream and "
                                          "downstream along the centerline, time-averaged over the settled flow; "
                                          "pressures gauge, the outlets at %3 mmHg"),
                      {flow->id, numberText(std::atof(compared.c_str())),
                       numberText(units::paToMmHg(std::atof(outlets.c_str())))}),
        {}};
    addMetrics(
        figures, *flow,
        {{"stenosis_peak_velocity_ratio",
          localized("Report", "Peak velocity ratio, throat / upstream (PSV ratio's counterpart)"), ""},
         {"stenosis_peak_velocity_ratio_downstream", localized("Report", "Peak velocity ratio, throat / downstream"),
          ""},
         {"stenosis_mean_velocity_ratio", localized("Report", "Mean velocity ratio, throat / upstream (a mass check)"),
          ""},
         {"stenosis_area_ratio", localized("Report", "Flow area ratio, upstream / throat (from the particles)"), ""},
         {"stenosis_throat_peak_velocity_m_s", localized("Report", "Throat peak velocity (fastest 5 % of the section)"),
          "m/s"},
         {"stenosis_pressure_drop_mmhg", localized("Report", "Pressure drop, upstream - downstream (section means)"),
          "mmHg"},
         {"stenosis_pressure_ratio", localized("Report", "Distal / proximal pressure (gauge)"), ""},
         {"stenosis_flow_rate_ratio", localized("Report", "Flow rate throat / upstream (1 when settled)"), ""}});
    section.blocks.push_back(figures);
    if (flow->attributes.count("wall_largest_tawss_pa"))
    {
        report::MetricTable wall{localized("Report",
                                           "Wall loads on the lumen surface (the same run and window; tau_w: the "
                                           "walls' friction on the particles next to them)"),
                                 {}};
        addMetrics(
            wall, *flow,
            {{"wall_largest_tawss_pa", localized("Report", "Largest time-averaged wall shear stress (TAWSS)"), "Pa",
              1.0, 2},
             {"wall_mean_tawss_pa", localized("Report", "Mean TAWSS over the surface"), "Pa", 1.0, 2},
             {"wall_largest_osi", localized("Report", "Largest oscillatory shear index (0: steady)"), "", 1.0, 2},
             {"wall_highest_pressure_pa", localized("Report", "Highest wall pressure (gauge)"), "Pa"},
             {"wall_lowest_pressure_pa", localized("Report", "Lowest wall pressure (gauge)"), "Pa"}});
        section.blocks.push_back(wall);
    }
    for (report::Plot& plot : alongCenterlinePlots(*flow))
        section.blocks.push_back(std::move(plot));
    if (const study::Artifact* loads = wallLoadsOf(study, flow->id))
    {
        const auto& parameters = loads->provenance.parameters;
        const double from = std::atof(textOr(parameters, "averaged_from_s", "0").c_str()),
                     over = std::atof(textOr(parameters, "averaged_over_s", "0").c_str());
        const std::string caption = withArguments(
            localized("Report",
                      "Time-averaged wall shear stress (TAWSS, Pa) on the lumen surface, averaged over %1-%2 ms "
                      "of the same run, seen from the front; grey: no value (past an open end, or within a "
                      "kernel support of it)"),
            {fixed(1e3 * from, 1), fixed(1e3 * (from + over), 1)});
        section.blocks.push_back(snapshotOrNote(caption, options, [&] {
            return wallShearPicture(study, *loads, QSize(options.snapshotPixels, options.snapshotPixels * 3 / 4));
        }));
    }
    if (const std::string warning = runStatusOf(*flow).warningText(true); !warning.empty())
        section.blocks.push_back(report::Paragraph{
            withArguments(localized("Report", "These blood-flow figures come from a run that is %1."), {warning})});
    return section;
}

} // namespace vsim::app::detail
