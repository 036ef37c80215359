#include "ReportSupport.h"

#include "vsim/app/NetworkPipeline.h"
#include "vsim/app/RunRecord.h"
#include "vsim/core/Error.h"
#include "vsim/core/Localized.h"
#include "vsim/core/Units.h"
#include "vsim/viz/Snapshot.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>

namespace vsim::app::detail {

std::string textOr(const std::map<std::string, std::string>& values, const std::string& key,
                   const std::string& fallback)
{
    const auto found = values.find(key);
    return found == values.end() ? fallback : found->second;
}

std::string fixed(double value, int decimals)
{
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return localizedNumber(text);
}

const study::Artifact* newestRun(const study::Study& study, const std::string& command, const std::string& key,
                                 const std::string& value, std::optional<study::ArtifactKind> kind)
{
    const study::Artifact* newest = nullptr;
    for (const study::Artifact& artifact : study.artifacts()) // in the order they were added
    {
        if (artifact.damaged || artifact.provenance.command != command || (kind && artifact.kind != *kind))
            continue;
        const auto& parameters = artifact.provenance.parameters;
        if (!key.empty() && (!parameters.count(key) || textOr(parameters, key) != value))
            continue;
        newest = &artifact;
    }
    return newest;
}

std::optional<report::Metric> runMetric(const study::Artifact& run, const std::string& key, const std::string& label,
                                        const std::string& unit, double scale)
{
    const std::string text = textOr(run.attributes, key);
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || end == text.c_str())
        return std::nullopt;
    return report::metric(key, label, value * scale, unit);
}

void addMetrics(report::MetricTable& table, const study::Artifact& run, const std::vector<MetricRow>& rows)
{
    for (const MetricRow& row : rows)
        if (auto m = runMetric(run, row.key, row.label, row.unit, row.scale))
        {
            if (row.decimals >= 0)
                *m = report::metric(m->key, m->label, m->value, m->unit, row.decimals);
            table.rows.push_back(*m);
        }
}

std::optional<report::Paragraph> markRunStatus(report::MetricTable& table, const study::Artifact& run)
{
    const RunStatus status = runStatusOf(run);
    if (status.converged() && status.complete())
        return std::nullopt;
    if (!status.converged())
        table.caption += localized("Report", " - NOT CONVERGED");
    if (!status.complete())
        table.caption += localized("Report", " - STOPPED EARLY");
    return report::Paragraph{
        withArguments(localized("Report", "Read these figures with care: %1."), {status.warningText(true)})};
}

namespace {

/// How a parameter's value reads: 4 significant digits and its unit; a blood pressure in mmHg with kPa beside it.
std::string parameterValueText(const std::string& recorded, const std::string& unit)
{
    char* end = nullptr;
    const double value = std::strtod(recorded.c_str(), &end);
    if (recorded.empty() || *end != '\0')
        return recorded;
    char text[64];
    std::snprintf(text, sizeof text, "%.4g", value);
    std::string shown = localizedNumber(text) + (unit.empty() ? "" : " " + unit);
    if (unit == "mmHg")
        shown += " (" + report::formatMetric(units::mmHgToPa(value) * 1e-3, "kPa", 1) + " kPa)";
    return shown;
}

/// People's names for what a run records beside its declared parameters (its source); the solver, backend and
/// device are in the run's summary table, not here.
std::optional<std::string> sourceLabel(const std::string& key)
{
    const std::map<std::string, std::string> kLabels = {
        // looked up now: the language may have changed
        {"tip", localized("Report", "Catheter tip (node, or x,y,z in mm)")},
        {"tumour_mm", localized("Report", "Tumour sphere (x, y, z, radius; mm)")},
        {"tumour_label", localized("Report", "Tumour label")},
        {"network_file", localized("Report", "Network file")},
        {"control_points", localized("Report", "Control points")},
        {"scenario", localized("Report", "Scenario")}};
    if (key == "protocol" || key == "backend" || key == "device")
        return std::nullopt;
    const auto found = kLabels.find(key);
    if (found != kLabels.end())
        return found->second;
    std::string words = key; // a key nobody named yet: in words, never raw
    std::replace(words.begin(), words.end(), '_', ' ');
    if (!words.empty())
        words[0] = char(std::toupper(static_cast<unsigned char>(words[0])));
    return words;
}

} // namespace

report::Table parameterTable(const study::Artifact& run, const std::vector<ParameterSpec>& specs,
                             const std::vector<ParameterSpec>& declaredSpecs, const std::string& caption)
{
    report::Table table;
    table.caption = caption;
    table.columns = {localized("Report", "Parameter"), localized("Report", "Value")};
    const auto& recorded = run.provenance.parameters;
    for (const ParameterSpec& spec : specs)
        if (const auto found = recorded.find(spec.key); found != recorded.end())
            table.rows.push_back(
                {localizedText("vsim::Parameters", spec.label), parameterValueText(found->second, spec.unit)});
    std::map<std::string, ParameterSpec> declared;
    for (const ParameterSpec& spec : declaredSpecs)
        declared.emplace(spec.key, spec);
    for (const auto& [key, value] : recorded)
        if (!declared.count(key)) // declared keys the run did not use (another protocol's) are left out
            if (const auto label = sourceLabel(key))
                table.rows.push_back({*label, value});
    return table;
}

const imaging::VesselMeasurements* VesselSections::of(const std::string& centerlinesId, const Progress& progress)
{
    auto found = m_measured.find(centerlinesId);
    if (found == m_measured.end())
    {
        std::optional<imaging::VesselMeasurements> measured;
        const std::string labelId = centerlinesId.empty() ? std::string() : labelOfCenterlines(m_study, centerlinesId);
        if (!labelId.empty())
            measured = imaging::measureVessels(m_study.loadLabel(labelId), m_study.loadSkeleton(centerlinesId),
                                               ParameterSet(imaging::measurementParameters()), progress);
        found = m_measured.emplace(centerlinesId, std::move(measured)).first;
    }
    return found->second ? &*found->second : nullptr;
}

report::Plot diameterPlot(const imaging::SegmentMeasurements& segment, const std::string& caption)
{
    report::Plot plot;
    plot.caption = caption;
    plot.xLabel = localized("Report", "Distance along the centerline [mm]");
    plot.yLabel = localized("Report", "Equivalent diameter [mm]");
    report::PlotSeries series{localized("Report", "diameter"), {}};
    for (const imaging::CrossSection& section : segment.sections)
        if (!section.nearJunction && section.equivalentDiameterMm > 0.0)
            series.points.emplace_back(section.arcLengthMm, section.equivalentDiameterMm);
    plot.series.push_back(series);
    return plot;
}

report::Block snapshotOrNote(const std::string& caption, const ReportOptions& options,
                             const std::function<QImage()>& render)
{
    if (!viz::canRenderSnapshots())
        return report::Paragraph{withArguments(
            localized("Report", "%1: not rendered (3D snapshots need a display; run under xvfb-run)."), {caption})};
    try
    {
        return report::Figure{caption, options.renderSnapshot ? options.renderSnapshot(render) : render()};
    }
    catch (const Error& error)
    {
        return report::Paragraph{withArguments(localized("Report", "%1: not rendered (%2)."), {caption, error.what()})};
    }
}

} // namespace vsim::app::detail
