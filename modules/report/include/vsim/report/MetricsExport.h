#pragma once

// A report's metrics as CSV and JSON: one row per metric with its section, key, label, value, unit and the text the
// PDF prints, so that other tools read the same numbers the clinician sees.

#include "vsim/report/ReportModel.h"

#include <filesystem>
#include <string>

namespace vsim::report {

/// section,key,label,value,unit,text (RFC 4180 quoting).
std::string metricsCsv(const Report& report);
/// {"format": "vascusim-report-metrics", "version": 1, "patient_anonymized": ..., "metrics": [{...}, ...],
///  "not_run": [...]}.
std::string metricsJson(const Report& report);

/// Writes text to a file; throws vsim::Error when it cannot.
void writeText(const std::string& text, const std::filesystem::path& file);

} // namespace vsim::report
