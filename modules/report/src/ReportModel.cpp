#include "vsim/report/ReportModel.h"

#include <cmath>
#include <cstdio>

namespace vsim::report {

std::string formatMetric(double value)
{
    if (!std::isfinite(value))
        return "n/a";
    char text[32];
    const double magnitude = std::abs(value);
    if (magnitude != 0.0 && (magnitude < 1e-3 || magnitude >= 1e6))
        std::snprintf(text, sizeof text, "%.3e", value);
    else
        std::snprintf(text, sizeof text, "%.4g", value);
    return text;
}

Metric metric(std::string key, std::string label, double value, std::string unit)
{
    Metric m{std::move(key), std::move(label), value, std::move(unit), {}};
    m.text = formatMetric(value);
    return m;
}

std::vector<std::pair<std::string, Metric>> Report::metrics() const
{
    std::vector<std::pair<std::string, Metric>> all;
    for (const Section& section : sections)
        for (const Block& block : section.blocks)
            if (const auto* table = std::get_if<MetricTable>(&block))
                for (const Metric& m : table->rows)
                    all.emplace_back(section.id, m);
    return all;
}

} // namespace vsim::report
