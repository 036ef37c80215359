#pragma once

// A simulation run as the study keeps it: its metrics (numbers) and its run-status record (RunStatus) in the run
// artifact's attributes, written once here for every solver and read back by the report, the GUI and the CLI.

#include "vsim/core/RunStatus.h"
#include "vsim/study/Artifact.h"

#include <map>
#include <string>

namespace vsim::app {

/// The attributes of a run artifact: every metric with 15 digits, and the status record's text fields.
std::map<std::string, std::string> runAttributes(const std::map<std::string, double>& metrics, const RunStatus& status);

/// The run-status record of a run artifact (its attributes as runAttributes() wrote them).
RunStatus runStatusOf(const study::Artifact& run);

/// What a reader must know before reading a run's figures: "" when its solves converged and it reached its target;
/// else "NOT CONVERGED (...)" and / or "STOPPED EARLY (... reached ... of ...)", joined by "; ".
std::string runStatusWarning(const RunStatus& status);

/// The record as a JSON object's text (converged, convergence, stopped_by, stop, reached, target, unit, warning), for
/// the CLI's output and the run folder's metrics.json.
std::string runStatusJson(const RunStatus& status);

} // namespace vsim::app
