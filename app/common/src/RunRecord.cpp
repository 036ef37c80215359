#include "vsim/app/RunRecord.h"

#include "vsim/core/Parameters.h"

#include <nlohmann/json.hpp>

#include <cstdlib>

namespace vsim::app {

std::map<std::string, std::string> runAttributes(const std::map<std::string, double>& metrics, const RunStatus& status)
{
    std::map<std::string, std::string> attributes = status.attributes();
    for (const auto& [key, value] : metrics)
        attributes[key] = preciseNumberText(value);
    for (const auto& [key, value] : status.metrics())
        attributes[key] = preciseNumberText(value);
    return attributes;
}

RunStatus runStatusOf(const study::Artifact& run)
{
    std::map<std::string, double> numbers;
    for (const auto& [key, text] : run.attributes)
    {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (!text.empty() && end != text.c_str() && *end == '\0')
            numbers[key] = value;
    }
    return RunStatus::fromRecords(numbers, run.attributes);
}

std::string runStatusWarning(const RunStatus& status)
{
    return status.warningText();
}

std::string runStatusJson(const RunStatus& status)
{
    return nlohmann::json{{"converged", status.converged()},
                          {"convergence", status.convergenceText()},
                          {"stopped_by", stoppedByName(status.stoppedBy)},
                          {"stop", status.stopText()},
                          {"reached", status.reached},
                          {"target", status.target},
                          {"unit", status.reachedUnit},
                          {"warning", runStatusWarning(status)}}
        .dump();
}

} // namespace vsim::app
