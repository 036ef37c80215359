#include "vsim/report/MetricsExport.h"

#include "vsim/core/Error.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>
#include <sstream>

namespace vsim::report {
namespace {

std::string csvField(const std::string& value)
{
    if (value.find_first_of(",\"\n") == std::string::npos)
        return value;
    std::string quoted = "\"";
    for (char c : value)
        quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

std::string fullPrecision(double value)
{
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

} // namespace

std::string metricsCsv(const Report& report)
{
    std::ostringstream csv;
    csv << "section,key,label,value,unit,text\n";
    for (const auto& [section, m] : report.metrics())
        csv << csvField(section) << "," << csvField(m.key) << "," << csvField(m.label) << "," << fullPrecision(m.value)
            << "," << csvField(m.unit) << "," << csvField(m.text) << "\n";
    return csv.str();
}

std::string metricsJson(const Report& report)
{
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    for (const auto& [section, m] : report.metrics())
        rows.push_back({{"section", section}, {"key", m.key}, {"label", m.label}, {"value", m.value},
                        {"unit", m.unit}, {"text", m.text}});
    const nlohmann::ordered_json document = {{"format", "vascusim-report-metrics"},
                                             {"version", 1},
                                             {"software", report.header.softwareVersion},
                                             {"report_date", report.header.reportDate},
                                             {"patient_anonymized", report.header.anonymized},
                                             {"metrics", rows},
                                             {"not_run", report.notRun}};
    return document.dump(2) + "\n";
}

void writeText(const std::string& text, const std::filesystem::path& file)
{
    std::ofstream out(file, std::ios::trunc);
    if (!(out << text) || !out.flush())
        throw Error("cannot write the file", {{"file", file.string()}});
}

} // namespace vsim::report
