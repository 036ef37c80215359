// The AAA sac as a study artifact (SacRecord.h).

#include "vsim/app/SacRecord.h"
#include "vsim/core/StoredText.h"

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
    return study.addLabel(sac.labels, storedText("AAA sac (lumen 1, thrombus 4, wall 5)"), provenance, sac.warnings);
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
    // The sac's geometry along an element's radius from the nearest centerline point: the outer-wall chord
    // through that point (both ways to the first voxel outside the labels) and the thrombus crossed outwards,
    // in steps of a quarter of the smallest voxel side.
    const auto graph = std::make_shared<SkeletonGraph>(centerlines);
    region.local = [labels, graph](const Eigen::Vector3d& p) {
        const sim::fem::CenterlinePlace place = sim::fem::nearestCenterlinePlace(*graph, p);
        Eigen::Vector3d radial = p - place.pointMm;
        radial -= radial.dot(place.direction) * place.direction;
        sim::fem::LocalSac local;
        if (radial.norm() < 1e-6)
            return local;
        radial.normalize();
        const double step = 0.25 * labels->geometry().spacing.minCoeff();
        const auto valueAt = [&](const Eigen::Vector3d& q) {
            const Eigen::Vector3d index = labels->geometry().patientToIndex(q);
            const int i = int(std::lround(index.x())), j = int(std::lround(index.y())), k = int(std::lround(index.z()));
            return labels->geometry().contains(i, j, k) ? labels->at(i, j, k) : std::uint8_t(0);
        };
        for (const double sign : {1.0, -1.0})
            for (double r = 0.0; r < 100.0; r += step)
            {
                const std::uint8_t value = valueAt(place.pointMm + sign * r * radial);
                if (value != 1 && value != 4 && value != 5)
                {
                    local.outerDiameterMm += r;
                    break;
                }
                if (sign > 0.0 && value == 4)
                    local.thrombusMm += step;
            }
        return local;
    };
    if (const auto neck = figures.find("neck_diameter_mm"); neck != figures.end())
        region.neckDiameterMm = neck->second;
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

std::function<double(const Eigen::Vector3d&, const Eigen::Vector3d&)> sacOuterWallDistance(const LabelVolume& sacLabels)
{
    const auto labels = std::make_shared<LabelVolume>(sacLabels);
    return [labels](const Eigen::Vector3d& point, const Eigen::Vector3d& normal) {
        const double step = 0.25 * labels->geometry().spacing.minCoeff();
        const Eigen::Vector3d direction = normal.normalized();
        bool crossed = false;
        for (double r = 0.0; r < 40.0; r += step)
        {
            const Eigen::Vector3d index = labels->geometry().patientToIndex(point + r * direction);
            const int i = int(std::lround(index.x())), j = int(std::lround(index.y())), k = int(std::lround(index.z()));
            const std::uint8_t value = labels->geometry().contains(i, j, k) ? labels->at(i, j, k) : std::uint8_t(0);
            if (value == 4 || value == 5)
                crossed = true;
            else if (value != 1 && (crossed || r > 5.0))
                return crossed ? r : -1.0;
        }
        return -1.0;
    };
}

std::string newestLumenLabel(const study::Study& study)
{
    std::string newest;
    for (const study::Artifact& artifact : study.artifacts())
        if (artifact.kind == study::ArtifactKind::Label && !artifact.damaged && artifact.provenance.command != kSacCommand &&
            artifact.provenance.command != "segment-organ")
            newest = artifact.id;
    return newest;
}

std::string lumenLabelOfCenterlines(const study::Study& study, const std::string& centerlinesId)
{
    std::vector<std::string> pending{centerlinesId};
    for (std::size_t n = 0; n < pending.size() && n < 8; ++n)
    {
        if (!study.hasArtifact(pending[n]))
            continue;
        for (const std::string& input : study.artifact(pending[n]).provenance.inputs)
        {
            if (!study.hasArtifact(input))
                continue;
            const study::Artifact& artifact = study.artifact(input);
            if (artifact.kind == study::ArtifactKind::Label && !artifact.damaged && artifact.provenance.command != kSacCommand)
                return artifact.id;
            if (artifact.kind == study::ArtifactKind::Skeleton)
                pending.push_back(artifact.id);
        }
    }
    return newestLumenLabel(study);
}

} // namespace vsim::app
