#pragma once

// What a clinical report says, apart from how it is laid out: a header (patient, study, software, the planning
// support statement), sections of paragraphs, metric tables (every value with its unit), tables, vector plots and
// pictures, and the analyses that were not run. Built by the application from a study (app::buildStudyReport);
// written as PDF (PdfReport.h), as DICOM Encapsulated PDF (EncapsulatedPdf.h) and as metrics (MetricsExport.h).

#include <QImage>

#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace vsim::report {

/// Said on every report, in the reader's language: the results support planning and do not replace clinical
/// judgement.
std::string planningStatement();

struct ReportHeader
{
    std::string title = "VascuSim planning report";       ///< app::buildStudyReport gives it in the reader's language
    std::string patientName, patientId, patientBirthDate; ///< empty when anonymized
    std::string studyDate, studyDescription, seriesDescription, institution;
    std::string softwareVersion; ///< "VascuSim 0.2.0"
    std::string reportDate;      ///< ISO 8601 UTC
    bool anonymized = false;
};

/// One figure with its unit. `text` is the number as printed (formatMetric) and exported.
struct Metric
{
    std::string key;   ///< as in the run's metrics, e.g. "peak_von_mises_kpa"
    std::string label; ///< for people, e.g. "Peak wall stress (von Mises)"
    double value = 0.0;
    std::string unit;  ///< "kPa", "%", "" for a count
    std::string text;  ///< formatMetric(value)
};

/// The number as reports and exports print it: 4 significant digits, no exponent between 1e-3 and 1e6.
std::string formatMetric(double value);
/// The number rounded to the precision that means something for its unit (mm 0.1, kPa 1, MPa 0.01, mmHg 1,
/// s 0.1, % 0.1; counts as integers; other units 3 significant digits); `decimals` >= 0 overrides (e.g. 0 for a
/// diameter in the clinical summary, which guidelines report to 1 mm).
std::string formatMetric(double value, const std::string& unit, int decimals = -1);
/// A metric with its text filled in by formatMetric(value, unit, decimals).
Metric metric(std::string key, std::string label, double value, std::string unit, int decimals = -1);

struct Paragraph
{
    std::string text;
};

struct MetricTable
{
    std::string caption;
    std::vector<Metric> rows;
};

struct Table
{
    std::string caption;
    std::vector<std::string> columns; ///< headers, units in brackets: "Flow [ml/min]"
    std::vector<std::vector<std::string>> rows;
};

struct PlotSeries
{
    std::string name;
    std::vector<std::pair<double, double>> points; ///< (x, y) in the axes' units
};

/// A horizontal line across a plot, e.g. a repair threshold.
struct ReferenceLine
{
    std::string label;
    double y = 0.0;
};

/// A line plot, drawn as vectors.
struct Plot
{
    std::string caption;
    std::string xLabel, yLabel; ///< with units: "Distance along the centerline [mm]"
    std::vector<PlotSeries> series;
    std::vector<ReferenceLine> references;
};

/// A picture (a 3D snapshot rendered offscreen at print resolution).
struct Figure
{
    std::string caption;
    QImage image;
};

using Block = std::variant<Paragraph, MetricTable, Table, Plot, Figure>;

struct Section
{
    std::string id;    ///< "aaa", "stenosis", "chemoembolization", "smoke", "runs"
    std::string title;
    std::vector<Block> blocks;
};

struct Report
{
    ReportHeader header;
    std::vector<Section> sections;
    std::vector<std::string> notRun; ///< analyses the study holds no run of, said as such in the report
    std::vector<std::string> sources; ///< the study artifacts reported (the report's provenance inputs)

    /// Every metric of every section's metric tables, with the section's id.
    std::vector<std::pair<std::string, Metric>> metrics() const;
};

} // namespace vsim::report
