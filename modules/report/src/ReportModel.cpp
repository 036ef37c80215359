#include "vsim/report/ReportModel.h"

#include "vsim/core/Localized.h"

#include <cmath>
#include <cstdio>

namespace vsim::report {

std::string planningStatement()
{
    return localized("Report", "Results are computed from the patient's images by physical models for planning support "
                               "only. They are not a diagnosis and need clinical judgement.");
}

namespace {

/// What a figure that is not a finite number prints as.
std::string notAvailable()
{
    return localized("Report", "n/a");
}

} // namespace

std::string formatMetric(double value)
{
    if (!std::isfinite(value))
        return notAvailable();
    char text[32];
    const double magnitude = std::abs(value);
    if (magnitude != 0.0 && (magnitude < 1e-3 || magnitude >= 1e6))
        std::snprintf(text, sizeof text, "%.3e", value);
    else
        std::snprintf(text, sizeof text, "%.4g", value);
    return localizedNumber(text);
}

namespace {

/// Decimals that mean something for a unit's figures; -1 where 3 significant digits are printed instead.
int meaningfulDecimals(const std::string& unit)
{
    static const std::pair<const char*, int> kDecimals[] = {
        {"mm", 1}, {"mm^2", 1}, {"ml", 1}, {"kPa", 0}, {"MPa", 2}, {"mmHg", 0}, {"Pa", 0}, {"s", 1}, {"%", 1}};
    for (const auto& [name, decimals] : kDecimals)
        if (unit == name)
            return decimals;
    return -1;
}

std::string fixedDecimals(double value, int decimals)
{
    char text[48];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    const std::string printed = text;
    // A small negative value rounded to zero prints as zero ("-0.0" would read as a sign that means something).
    const bool zero = printed.find_first_not_of("-0.") == std::string::npos;
    return localizedNumber(zero && printed[0] == '-' ? printed.substr(1) : printed);
}

} // namespace

std::string formatMetric(double value, const std::string& unit, int decimals)
{
    if (!std::isfinite(value))
        return notAvailable();
    if (decimals < 0)
        decimals = meaningfulDecimals(unit);
    if (decimals >= 0)
        return fixedDecimals(value, decimals);
    const double magnitude = std::abs(value);
    if (unit.empty() && magnitude < 1e15 && value == std::round(value))
        return fixedDecimals(value, 0); // a count
    if (magnitude != 0.0 && magnitude < 1e-3)
        return formatMetric(value);
    // 3 significant digits without an exponent.
    const int leading = magnitude == 0.0 ? 0 : int(std::floor(std::log10(magnitude)));
    return fixedDecimals(value, std::max(0, 2 - leading));
}

Metric metric(std::string key, std::string label, double value, std::string unit, int decimals)
{
    Metric m{std::move(key), std::move(label), value, std::move(unit), {}};
    m.text = formatMetric(value, m.unit, decimals);
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
