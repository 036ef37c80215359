// The AAA sac as a study artifact (SacRecord.h).

#include "vsim/app/SacRecord.h"

#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <memory>
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

std::optional<sim::fem::SacRegion> newestSacRegion(const study::Study& study, const SkeletonGraph& centerlines)
{
    std::string id;
    const std::map<std::string, double> figures = newestSacFigures(study, &id);
    if (id.empty() || !figures.count("sac_top_z_mm") || !figures.count("sac_bottom_z_mm"))
        return std::nullopt;
    const auto labels = std::make_shared<LabelVolume>(study.loadLabel(id));
    const double top = figures.at("sac_top_z_mm"), bottom = figures.at("sac_bottom_z_mm");
    sim::fem::SacRegion region;
    region.contains = [labels, top, bottom](const Eigen::Vector3d& p) {
        if (p.z() > std::max(top, bottom) || p.z() < std::min(top, bottom))
            return false;
        const Eigen::Vector3d index = labels->geometry().patientToIndex(p);
        const int i = int(std::lround(index.x())), j = int(std::lround(index.y())), k = int(std::lround(index.z()));
        if (!labels->geometry().contains(i, j, k))
            return false;
        const std::uint8_t value = labels->at(i, j, k);
        return value == 1 || value == 4 || value == 5;
    };
    const auto renal = figures.find("lowest_renal_z_mm");
    const double referenceZ = renal != figures.end() ? renal->second : std::max(top, bottom);
    double widest = -1.0;
    for (const auto& edge : centerlines.edges)
        for (std::size_t n = 0; n < edge.points.size(); ++n)
            if (std::abs(edge.points[n].z() - referenceZ) <= 3.0 && edge.radii[n] > widest)
                widest = edge.radii[n], region.referenceMm = edge.points[n];
    if (widest < 0.0)
        return std::nullopt; // the centerlines do not reach the sac's level
    return region;
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
