#include "vsim/app/StudySummary.h"

#include "vsim/study/Study.h"

#include <nlohmann/json.hpp>

namespace vsim::app {
namespace {

using nlohmann::json;

json imageGeometry(const VolumeGeometry& geometry)
{
    json direction = json::array();
    for (int row = 0; row < 3; ++row)
        direction.push_back({geometry.direction(row, 0), geometry.direction(row, 1), geometry.direction(row, 2)});
    return {{"dims", geometry.dims},
            {"spacing_mm", {geometry.spacing.x(), geometry.spacing.y(), geometry.spacing.z()}},
            {"origin_mm", {geometry.origin.x(), geometry.origin.y(), geometry.origin.z()}},
            {"direction", direction}};
}

} // namespace

std::string studySummaryJson(const study::Study& study)
{
    json artifacts = json::array();
    for (const study::Artifact& artifact : study.artifacts())
    {
        json entry = {{"id", artifact.id},
                      {"kind", study::kindName(artifact.kind)},
                      {"name", artifact.name},
                      {"file", artifact.file},
                      {"bytes", artifact.bytes},
                      {"damaged", artifact.damaged},
                      {"warnings", artifact.warnings},
                      {"attributes", artifact.attributes},
                      {"provenance",
                       {{"command", artifact.provenance.command},
                        {"parameters", artifact.provenance.parameters},
                        {"inputs", artifact.provenance.inputs},
                        {"time", artifact.provenance.time},
                        {"software_version", artifact.provenance.softwareVersion}}}};
        if (artifact.damaged)
            entry["damage"] = artifact.damage;
        else if (artifact.kind == study::ArtifactKind::Image || artifact.kind == study::ArtifactKind::Label)
            entry["geometry"] = imageGeometry(study.volumeGeometry(artifact.id));
        artifacts.push_back(std::move(entry));
    }
    const json summary = {{"name", study.name()},
                          {"bundle", study.bundlePath().string()},
                          {"metadata", study.metadata()},
                          {"open_warnings", study.openWarnings()},
                          {"artifacts", artifacts}};
    return summary.dump(2);
}

} // namespace vsim::app
