// The AAA sac as a study artifact (SacRecord.h).

#include "vsim/app/SacRecord.h"

#include <cstdlib>
#include <iomanip>
#include <sstream>

namespace vsim::app {
namespace {

constexpr const char* kSacCommand = "sac";

std::string text(double value)
{
    std::ostringstream out;
    out << std::setprecision(6) << value;
    return out.str();
}

} // namespace

std::string recordAneurysmSac(study::Study& study, const imaging::AneurysmSac& sac, const std::string& imageId,
                              const std::string& lumenId, double wallThicknessMm)
{
    study::Provenance provenance;
    provenance.command = kSacCommand;
    provenance.inputs = {imageId, lumenId};
    provenance.parameters = {{"wall_thickness_mm", text(wallThicknessMm)}};
    for (const auto& [key, value] : sac.figures)
        provenance.parameters[key] = text(value);
    return study.addLabel(sac.labels, "AAA sac (lumen 1, thrombus 4, wall 5)", provenance, sac.warnings);
}

std::map<std::string, double> newestSacFigures(const study::Study& study, std::string* sacId)
{
    const std::string id = study.newestArtifact(study::ArtifactKind::Label, kSacCommand);
    if (sacId)
        *sacId = id;
    std::map<std::string, double> figures;
    if (id.empty())
        return figures;
    for (const auto& [key, value] : study.artifact(id).provenance.parameters)
    {
        char* end = nullptr;
        const double number = std::strtod(value.c_str(), &end);
        if (!value.empty() && *end == '\0')
            figures[key] = number;
    }
    return figures;
}

std::string newestLumenLabel(const study::Study& study)
{
    std::string newest;
    for (const study::Artifact& artifact : study.artifacts())
        if (artifact.kind == study::ArtifactKind::Label && !artifact.damaged && artifact.provenance.command != kSacCommand)
            newest = artifact.id;
    return newest;
}

} // namespace vsim::app
