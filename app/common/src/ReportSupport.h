#pragma once

// Helpers of the study report (StudyReport.cpp and its sections): run artifacts and their metrics, metric rows
// with units, parameter tables from the declarations, offscreen snapshots that degrade to a note.

#include "vsim/app/StudyReport.h"
#include "vsim/core/Localized.h"
#include "vsim/core/Parameters.h"
#include "vsim/imaging/VesselMeasurements.h"
#include "vsim/report/ReportModel.h"
#include "vsim/study/Study.h"

#include <QImage>

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace vsim::app::detail {

/// The text recorded under `key` (metadata, attributes, provenance parameters), or `fallback`.
std::string textOr(const std::map<std::string, std::string>& values, const std::string& key,
                   const std::string& fallback = {});

/// `value` with `decimals` digits after the decimal mark ("%.*f", in the reader's mark: localizedNumber()).
std::string fixed(double value, int decimals);

/// The newest undamaged artifact made by `command` (e.g. "simulate fem") whose provenance parameter `key` is
/// `value` when key is given, of `kind` when given (a run's derived artifacts share its command); nullptr when there
/// is none.
const study::Artifact* newestRun(const study::Study& study, const std::string& command, const std::string& key = {},
                                 const std::string& value = {}, std::optional<study::ArtifactKind> kind = std::nullopt);

/// A metric of a run (its attributes) as a report row; `scale` converts it (100 for a fraction in %). Empty when
/// the run has no such metric.
std::optional<report::Metric> runMetric(const study::Artifact& run, const std::string& key, const std::string& label,
                                        const std::string& unit, double scale = 1.0);

/// Adds runMetric() rows that exist to `table`.
struct MetricRow
{
    const char* key;
    std::string label; ///< in the reader's language
    const char* unit;
    double scale = 1.0;
    int decimals = -1; ///< -1: the unit's (report::formatMetric)
};
void addMetrics(report::MetricTable& table, const study::Artifact& run, const std::vector<MetricRow>& rows);

/// Marks a run's figures: the table's caption gains " - NOT CONVERGED" / " - STOPPED EARLY", and the paragraph
/// returned (when there is something to say) gives the residuals and the pressure or time reached against the target.
std::optional<report::Paragraph> markRunStatus(report::MetricTable& table, const study::Artifact& run);

/// The run's parameters as a table: the values of `specs` (those the run used) by their labels, with units a
/// clinician reads (a blood pressure in mmHg with kPa beside it); what the run recorded beyond `declaredSpecs`
/// (the tip, the tumour) by people's names. Declared parameters the run did not use are left out.
report::Table parameterTable(const study::Artifact& run, const std::vector<ParameterSpec>& specs,
                             const std::vector<ParameterSpec>& declaredSpecs, const std::string& caption);

/// The cross-sections of a study's centerlines in the label they came from, measured once per centerlines artifact
/// however many sections ask (a full-size tree takes about half a second).
class VesselSections
{
public:
    explicit VesselSections(const study::Study& study) : m_study(study) {}
    /// The measurements of `centerlinesId`; nullptr when the centerlines have no label to measure in.
    const imaging::VesselMeasurements* of(const std::string& centerlinesId, const Progress& progress);

private:
    const study::Study& m_study;
    std::map<std::string, std::optional<imaging::VesselMeasurements>> m_measured;
};

/// The equivalent diameter along a segment's centerline (its sections away from junctions).
report::Plot diameterPlot(const imaging::SegmentMeasurements& segment, const std::string& caption);

/// A picture for the report (rendered through options.renderSnapshot when set), or a paragraph saying why there is
/// none (no display for the offscreen renderer, or the renderer's error).
report::Block snapshotOrNote(const std::string& caption, const ReportOptions& options,
                             const std::function<QImage()>& render);

} // namespace vsim::app::detail
