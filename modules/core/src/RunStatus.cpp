#include "vsim/core/RunStatus.h"

#include "vsim/core/Localized.h"
#include "vsim/core/StoredText.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vsim {
namespace {

std::string shortNumber(double value, const char* format = "%.1e")
{
    char text[32];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

/// One decimal ("12.5", "60000.0"), small values by their significant digits ("0.002", "1.78e-05": a blood-flow
/// run's milliseconds).
std::string fixed(double value) { return shortNumber(value, value == 0.0 || std::abs(value) >= 0.1 ? "%.1f" : "%.3g"); }

} // namespace

std::string stoppedByName(RunStatus::StoppedBy stoppedBy)
{
    switch (stoppedBy)
    {
    case RunStatus::StoppedBy::End: return "end";
    case RunStatus::StoppedBy::EndCondition: return "end condition";
    case RunStatus::StoppedBy::Guard: return "guard";
    case RunStatus::StoppedBy::Cancel: return "cancel";
    }
    return "end";
}

void RunStatus::recordSolve(int solveIterations, double residual, double solveTolerance, int cap)
{
    ++solves;
    iterations += solveIterations;
    iterationCap = std::max(iterationCap, cap);
    tolerance = std::max(tolerance, solveTolerance);
    finalResidual = residual;
    worstResidual = std::max(worstResidual, residual);
    if (!(residual <= solveTolerance)) // NaN counts as not converged
    {
        ++unconvergedSolves;
        if (cap > 0 && solveIterations >= cap)
            ++solvesAtCap;
    }
}

std::string RunStatus::convergenceText(bool forPeople) const
{
    const LocalizedWhen localized{forPeople};
    const std::string force = forceResidual < 0.0
                                  ? std::string()
                                  : withArguments(localized("vsim::RunStatus", "force residual %1 (tolerance %2)"),
                                                  {localized.number(shortNumber(forceResidual)),
                                                   localized.number(shortNumber(forceTolerance))});
    if (converged())
        return force.empty() ? localized("vsim::RunStatus", "converged")
                             : withArguments(localized("vsim::RunStatus", "converged, %1"), {force});
    std::string details;
    if (unconvergedSolves > 0)
    {
        details = withArguments(localized("vsim::RunStatus", "%1 of %2 solves ended above their tolerance"),
                                {std::to_string(unconvergedSolves), std::to_string(solves)});
        if (iterationCap > 0 && solvesAtCap > 0 && solvesAtCap == unconvergedSolves)
            details +=
                withArguments(localized("vsim::RunStatus", " at the %1-iteration cap"), {std::to_string(iterationCap)});
        else if (iterationCap > 0 && solvesAtCap > 0)
            details += withArguments(localized("vsim::RunStatus", ", %1 of them at the %2-iteration cap"),
                                     {std::to_string(solvesAtCap), std::to_string(iterationCap)});
        details += withArguments(localized("vsim::RunStatus", ", worst relative residual %1 (tolerance %2)"),
                                 {localized.number(shortNumber(worstResidual)),
                                  localized.number(shortNumber(tolerance))});
        if (!force.empty())
            details += "; ";
    }
    return withArguments(localized("vsim::RunStatus", "not converged: %1"), {details + force});
}

std::string RunStatus::stopText(bool forPeople) const
{
    const LocalizedWhen localized{forPeople};
    if (stoppedBy == StoppedBy::End)
        return {};
    std::string text = stoppedBy == StoppedBy::Cancel  ? localized("vsim::RunStatus", "cancelled")
                       : stoppedBy == StoppedBy::Guard ? localized("vsim::RunStatus", "stopped by a guard")
                                                       : localized("vsim::RunStatus", "stopped by its end condition");
    if (!reachedQuantity.empty())
    {
        const std::string quantity = reachedQuantity == "pressure" ? localized("vsim::RunStatus", "pressure")
                                     : reachedQuantity == "time"   ? localized("vsim::RunStatus", "time")
                                                                   : reachedQuantity;
        text += withArguments(localized("vsim::RunStatus", " at %1 %2 of %3 %4"),
                              {quantity, localized.number(fixed(reached)), localized.number(fixed(target)),
                               reachedUnit});
    }
    if (!stopMessage.empty())
        text += ": " + (forPeople ? storedTextForPeople(stopMessage) : stopMessage);
    return text;
}

std::string RunStatus::warningText(bool forPeople) const
{
    const LocalizedWhen localized{forPeople};
    std::string warning;
    if (!converged())
    {
        // The details without the "not converged: " that convergenceText() starts with.
        const std::string text = convergenceText(forPeople);
        const std::string lead = withArguments(localized("vsim::RunStatus", "not converged: %1"), {""});
        warning = withArguments(localized("vsim::RunStatus", "NOT CONVERGED (%1)"),
                                {text.compare(0, lead.size(), lead) == 0 ? text.substr(lead.size()) : text});
    }
    if (!complete())
        warning += (warning.empty() ? "" : "; ") +
                   withArguments(localized("vsim::RunStatus", "STOPPED EARLY (%1)"), {stopText(forPeople)});
    return warning;
}

std::map<std::string, double> RunStatus::metrics() const
{
    std::map<std::string, double> values{{"run_converged", converged() ? 1.0 : 0.0},
                                         {"run_complete", complete() ? 1.0 : 0.0},
                                         {"run_solves", double(solves)},
                                         {"run_unconverged_solves", double(unconvergedSolves)},
                                         {"run_solves_at_cap", double(solvesAtCap)},
                                         {"run_mean_iterations", solves ? double(iterations) / double(solves) : 0.0},
                                         {"run_iteration_cap", double(iterationCap)},
                                         {"run_tolerance", tolerance},
                                         {"run_final_residual", finalResidual},
                                         {"run_worst_residual", worstResidual}};
    if (forceResidual >= 0.0)
        values["run_force_residual"] = forceResidual, values["run_force_tolerance"] = forceTolerance;
    if (!reachedQuantity.empty())
    {
        values["run_reached_" + reachedQuantity + "_" + reachedUnit] = reached;
        values["run_target_" + reachedQuantity + "_" + reachedUnit] = target;
    }
    return values;
}

std::map<std::string, std::string> RunStatus::attributes() const
{
    return {{"run_stopped_by", stoppedByName(stoppedBy)},
            {"run_stop_message", stopMessage},
            {"run_reached_quantity", reachedQuantity},
            {"run_reached_unit", reachedUnit},
            {"run_convergence", convergenceText()}};
}

RunStatus RunStatus::fromRecords(const std::map<std::string, double>& metrics,
                                 const std::map<std::string, std::string>& attributes)
{
    auto number = [&](const std::string& key, double fallback) {
        const auto found = metrics.find(key);
        return found == metrics.end() ? fallback : found->second;
    };
    auto text = [&](const std::string& key) {
        const auto found = attributes.find(key);
        return found == attributes.end() ? std::string() : found->second;
    };
    RunStatus status;
    status.solves = long(number("run_solves", 0));
    status.unconvergedSolves = long(number("run_unconverged_solves", 0));
    status.solvesAtCap = long(number("run_solves_at_cap", 0)); // unknown in older studies: the cap is not claimed
    status.iterations = long(number("run_mean_iterations", 0) * double(status.solves) + 0.5);
    status.iterationCap = int(number("run_iteration_cap", 0));
    status.tolerance = number("run_tolerance", 0);
    status.finalResidual = number("run_final_residual", 0);
    status.worstResidual = number("run_worst_residual", 0);
    status.forceResidual = number("run_force_residual", -1);
    status.forceTolerance = number("run_force_tolerance", 0);
    for (RunStatus::StoppedBy by : {StoppedBy::End, StoppedBy::EndCondition, StoppedBy::Guard, StoppedBy::Cancel})
        if (stoppedByName(by) == text("run_stopped_by"))
            status.stoppedBy = by;
    status.stopMessage = text("run_stop_message");
    status.reachedQuantity = text("run_reached_quantity");
    status.reachedUnit = text("run_reached_unit");
    if (!status.reachedQuantity.empty())
    {
        const std::string suffix = status.reachedQuantity + "_" + status.reachedUnit;
        status.reached = number("run_reached_" + suffix, 0);
        status.target = number("run_target_" + suffix, 0);
    }
    return status;
}

} // namespace vsim
