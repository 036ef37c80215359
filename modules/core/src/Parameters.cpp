#include "vsim/core/Parameters.h"

#include "vsim/core/Error.h"

#include <charconv>
#include <cmath>
#include <sstream>

namespace vsim {
namespace {

std::string formatNumber(double value)
{
    std::ostringstream text;
    text.precision(12);
    text << value;
    return text.str();
}

std::string describeRange(const ParameterSpec& spec)
{
    return "[" + formatNumber(spec.minimum) + ", " + formatNumber(spec.maximum) + "]" +
           (spec.unit.empty() ? "" : " " + spec.unit);
}

std::string trim(const std::string& text)
{
    const auto first = text.find_first_not_of(" \t");
    if (first == std::string::npos)
        return {};
    const auto last = text.find_last_not_of(" \t");
    return text.substr(first, last - first + 1);
}

} // namespace

ParameterSet::ParameterSet(std::vector<ParameterSpec> specs) : m_specs(std::move(specs))
{
    for (const ParameterSpec& spec : m_specs)
    {
        if (m_values.count(spec.key))
            throw Error("parameter declared twice", {{"key", spec.key}});
        if (!(spec.minimum <= spec.defaultValue && spec.defaultValue <= spec.maximum))
            throw Error("parameter default outside its declared range",
                        {{"key", spec.key}, {"default", formatNumber(spec.defaultValue)}, {"range", describeRange(spec)}});
        m_values[spec.key] = spec.defaultValue;
    }
}

const ParameterSpec& ParameterSet::spec(const std::string& key) const
{
    for (const ParameterSpec& spec : m_specs)
        if (spec.key == key)
            return spec;
    std::string known;
    for (const ParameterSpec& spec : m_specs)
        known += (known.empty() ? "" : ", ") + spec.key;
    throw Error(Pattern{"unknown parameter '%1'", {key}}, {{"key", key}, {"known parameters", known}});
}

void ParameterSet::set(const std::string& key, double value)
{
    const ParameterSpec& declared = spec(key);
    const Error::Context context{{"key", key}, {"value", formatNumber(value)}, {"range", describeRange(declared)}};
    if (!std::isfinite(value))
        throw Error(Pattern{"parameter '%1' is not a finite number", {key}}, context);
    if (value < declared.minimum || value > declared.maximum)
        throw Error(Pattern{"parameter '%1' = %2 is outside its range %3",
                            {key, formatNumber(value), describeRange(declared)}},
                    context);
    if (declared.kind == ParameterSpec::Kind::Integer && value != std::round(value))
        throw Error(Pattern{"parameter '%1' must be a whole number, got %2", {key, formatNumber(value)}}, context);
    m_values[key] = value;
}

void ParameterSet::setFromText(const std::string& assignment)
{
    const auto equals = assignment.find('=');
    if (equals == std::string::npos)
        throw Error(Pattern{"expected key=value, got '%1'", {assignment}}, {{"text", assignment}});
    const std::string key = trim(assignment.substr(0, equals));
    const std::string valueText = trim(assignment.substr(equals + 1));
    double value = 0.0;
    const auto [end, status] = std::from_chars(valueText.data(), valueText.data() + valueText.size(), value);
    if (status != std::errc() || end != valueText.data() + valueText.size() || valueText.empty())
        throw Error(Pattern{"parameter '%1' needs a number, got '%2'",
                            {key, valueText}}, {{"key", key}, {"value", valueText}});
    set(key, value);
}

double ParameterSet::get(const std::string& key) const
{
    const auto found = m_values.find(key);
    if (found == m_values.end())
        spec(key); // throws with the list of known keys
    return found->second;
}

std::map<std::string, std::string> ParameterSet::valuesAsText() const
{
    std::map<std::string, std::string> text;
    for (const auto& [key, value] : m_values)
        text[key] = numberText(value);
    return text;
}

std::string numberText(double value)
{
    std::ostringstream text;
    text << value;
    return text.str();
}

std::string preciseNumberText(double value)
{
    std::ostringstream text;
    text.precision(15);
    text << value;
    return text.str();
}

} // namespace vsim
