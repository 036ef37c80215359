#pragma once

// The workflow as a checklist: for each step, whether the study holds its result, and whether that result is still
// current. A result is stale when one of its inputs, or an input of those (transitively), has been superseded since:
// a newer artifact of the same kind made by the same step exists, or a newer artifact edits it (a brush edit of a
// label, "edit-label", taking it as input); an edit does not make the artifacts made from it stale. Artifacts
// merely made from it (a sac label from the lumen) do not replace it.

#include <string>
#include <vector>

namespace vsim::study {
class Study;
}

namespace vsim::app {

/// The steps of the workstation's workflow, in order (ARCHITECTURE.md; PACS adds its own the same way).
enum class WorkflowStep
{
    Import,      ///< a CT image (any image artifact, whatever made it)
    Segment,     ///< the vessel label
    Centerlines, ///< skeleton and centerlines
    WallMesh,    ///< the wall mesh
    WallStress,  ///< the wall-stress run
    Flow,        ///< the blood-flow (SPH) run
    Drug,        ///< the drug-delivery run
    Smoke,       ///< a surgical-smoke run (illustrative)
    Report,      ///< the PDF report
};

inline constexpr WorkflowStep kWorkflowSteps[] = {WorkflowStep::Import,   WorkflowStep::Segment,    WorkflowStep::Centerlines,
                                                  WorkflowStep::WallMesh, WorkflowStep::WallStress, WorkflowStep::Flow,
                                                  WorkflowStep::Drug,     WorkflowStep::Smoke,      WorkflowStep::Report};

enum class StepState
{
    NotRun, ///< the study holds no result of the step
    Done,   ///< its newest result is current
    Stale,  ///< its newest result was made from an input that has changed since
};

struct StepStatus
{
    StepState state = StepState::NotRun;
    std::string artifactId; ///< the step's newest result; empty when not run
    /// Stale: the superseded input and what superseded it (artifact ids), for the tooltip.
    std::string supersededInput, supersededBy;
};

/// The provenance commands whose results count as the step's ("segment", "edit-label", ... for Segment).
const std::vector<std::string>& stepCommands(WorkflowStep step);
/// The step's state in `study`.
StepStatus stepStatus(const study::Study& study, WorkflowStep step);
/// The id of the artifact that supersedes `id` (see the header), or "" while it is current.
std::string supersededBy(const study::Study& study, const std::string& id);

} // namespace vsim::app
