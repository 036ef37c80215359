#include "vsim/app/WorkflowState.h"

#include "vsim/study/Study.h"

#include <algorithm>
#include <set>

namespace vsim::app {
namespace {

using study::Artifact;

/// Position of an artifact in the study's list (artifacts are appended as they are made), -1 if absent.
long positionOf(const study::Study& study, const std::string& id)
{
    const auto& artifacts = study.artifacts();
    for (std::size_t i = 0; i < artifacts.size(); ++i)
        if (artifacts[i].id == id)
            return long(i);
    return -1;
}

/// Whether `artifact` is an edit of `id` (a brush edit of a label), which replaces it. Other artifacts made from
/// it (a sac label from the lumen, centerlines) do not.
bool isEditOf(const Artifact& artifact, const std::string& id)
{
    static const std::set<std::string> kEditCommands = {"edit-label"};
    return kEditCommands.count(artifact.provenance.command) &&
           std::find(artifact.provenance.inputs.begin(), artifact.provenance.inputs.end(), id) != artifact.provenance.inputs.end();
}

/// `id` and everything it was made from, transitively (artifacts of the study only).
void collectLineage(const study::Study& study, const std::string& id, std::set<std::string>& lineage)
{
    if (!study.hasArtifact(id) || !lineage.insert(id).second)
        return;
    for (const std::string& input : study.artifact(id).provenance.inputs)
        collectLineage(study, input, lineage);
}

/// The newer artifact that supersedes `id`, ignoring those in `lineage` (an edit of a label does not make itself
/// stale); "" if none.
std::string supersededOutside(const study::Study& study, const std::string& id, const std::set<std::string>& lineage)
{
    const long position = positionOf(study, id);
    if (position < 0)
        return {};
    const Artifact& artifact = study.artifacts()[std::size_t(position)];
    const auto& artifacts = study.artifacts();
    for (std::size_t i = artifacts.size(); i-- > std::size_t(position + 1);)
    {
        const Artifact& newer = artifacts[i];
        if (newer.damaged || newer.kind != artifact.kind || lineage.count(newer.id))
            continue;
        if (newer.provenance.command == artifact.provenance.command || isEditOf(newer, id))
            return newer.id;
    }
    return {};
}

} // namespace

const std::vector<std::string>& stepCommands(WorkflowStep step)
{
    static const std::vector<std::string> commands[] = {
        {"import dicom", "import volume"},
        {"segment", "edit-label"},
        {"centerline"},
        {"mesh wall"},
        {"simulate fem"},
        {"simulate sph"},
        {"simulate network"},
        {"simulate smoke"},
        {"report"},
    };
    return commands[std::size_t(step)];
}

std::string supersededBy(const study::Study& study, const std::string& id)
{
    return supersededOutside(study, id, {});
}

StepStatus stepStatus(const study::Study& study, WorkflowStep step)
{
    StepStatus status;
    const std::vector<std::string>& commands = stepCommands(step);
    const auto& artifacts = study.artifacts();
    const auto isResult = [&](const Artifact& artifact) {
        if (step == WorkflowStep::Import) // any image: a study made elsewhere may not say how
            return artifact.kind == study::ArtifactKind::Image;
        return std::count(commands.begin(), commands.end(), artifact.provenance.command) > 0;
    };
    for (std::size_t i = artifacts.size(); i-- > 0;)
        if (!artifacts[i].damaged && isResult(artifacts[i]))
        {
            status.artifactId = artifacts[i].id;
            break;
        }
    if (status.artifactId.empty())
        return status;
    std::set<std::string> lineage;
    collectLineage(study, status.artifactId, lineage);
    for (const std::string& input : lineage)
    {
        if (input == status.artifactId)
            continue;
        if (const std::string by = supersededOutside(study, input, lineage); !by.empty())
        {
            status.state = StepState::Stale;
            status.supersededInput = input;
            status.supersededBy = by;
            return status;
        }
    }
    status.state = StepState::Done;
    return status;
}

} // namespace vsim::app
