#include "vsim/app/GuidedSegmentationRecord.h"

#include "vsim/core/Error.h"
#include "vsim/core/StoredText.h"

#include <cstdlib>
#include <sstream>

namespace vsim::app {
namespace {

std::vector<double> numbers(const std::string& text, std::size_t count)
{
    std::vector<double> values;
    std::stringstream stream(text);
    std::string item;
    while (std::getline(stream, item, ','))
    {
        char* end = nullptr;
        values.push_back(std::strtod(item.c_str(), &end));
        if (end == item.c_str())
            throw Error(Pattern{"'%1' is not %2 numbers separated by commas", {text, std::to_string(count)}});
    }
    if (values.size() != count)
        throw Error(Pattern{"'%1' is not %2 numbers separated by commas", {text, std::to_string(count)}});
    return values;
}

std::string labelName(imaging::SegmentationTarget target)
{
    switch (target)
    {
    case imaging::SegmentationTarget::Aorta: return storedText("Vessel lumen (aorta)");
    case imaging::SegmentationTarget::Hepatic: return storedText("Vessel lumen (hepatic arteries)");
    case imaging::SegmentationTarget::All: return storedText("Vessel lumen (from points)");
    }
    return storedText("Vessel lumen");
}

} // namespace

std::string pointsText(const std::vector<Eigen::Vector3d>& points)
{
    std::string text;
    for (const Eigen::Vector3d& p : points)
        text += (text.empty() ? "" : "; ") + numberText(p.x()) + "," + numberText(p.y()) + "," + numberText(p.z());
    return text;
}

std::vector<Eigen::Vector3d> pointsFromText(const std::string& text)
{
    std::vector<Eigen::Vector3d> points;
    std::stringstream stream(text);
    std::string item;
    while (std::getline(stream, item, ';'))
    {
        if (item.find_first_not_of(' ') == std::string::npos)
            continue;
        const std::vector<double> xyz = numbers(item, 3);
        points.emplace_back(xyz[0], xyz[1], xyz[2]);
    }
    return points;
}

std::string recordGuidedSegmentation(study::Study& study, const imaging::SegmentationResult& result,
                                     const imaging::SegmentationRequest& request, const ParameterSet& parameters,
                                     const std::string& imageId)
{
    study::Provenance provenance;
    provenance.command = "segment";
    provenance.inputs = {imageId};
    provenance.parameters = parameters.valuesAsText();
    provenance.parameters["target"] = imaging::segmentationTargetName(request.target);
    const bool automatic = request.includeMm.empty();
    provenance.parameters["include_points_mm"] =
        pointsText(automatic ? std::vector<Eigen::Vector3d>{result.seedMm} : request.includeMm);
    provenance.parameters["include_point_found_automatically"] = result.seedFound ? "yes" : "no";
    provenance.parameters["exclude_points_mm"] = pointsText(request.excludeMm);
    for (std::size_t n = 0; n < request.stops.size(); ++n) // point (mm), then normal
        provenance.parameters["stop_plane_" + std::to_string(n + 1)] =
            pointsText({request.stops[n].pointMm}) + "," + pointsText({request.stops[n].normal});
    if (request.maxLengthMm)
        provenance.parameters["max_length_mm"] = numberText(*request.maxLengthMm);
    return study.addLabel(result.label, labelName(request.target), provenance, result.warnings);
}

std::optional<imaging::SegmentationRequest> guidedRequestOf(const study::Artifact& label)
{
    const auto& p = label.provenance.parameters;
    if (label.kind != study::ArtifactKind::Label || label.provenance.command != "segment" || !p.count("target"))
        return std::nullopt;
    imaging::SegmentationRequest request;
    request.target = imaging::segmentationTargetFromName(p.at("target"));
    const auto automatic = p.find("include_point_found_automatically");
    if (automatic == p.end() || automatic->second != "yes")
        request.includeMm = pointsFromText(p.at("include_points_mm"));
    if (p.count("exclude_points_mm"))
        request.excludeMm = pointsFromText(p.at("exclude_points_mm"));
    for (std::size_t n = 1; p.count("stop_plane_" + std::to_string(n)); ++n)
    {
        const std::vector<double> v = numbers(p.at("stop_plane_" + std::to_string(n)), 6);
        request.stops.push_back({Eigen::Vector3d(v[0], v[1], v[2]), Eigen::Vector3d(v[3], v[4], v[5])});
    }
    if (p.count("max_length_mm"))
        request.maxLengthMm = std::strtod(p.at("max_length_mm").c_str(), nullptr);
    return request;
}

} // namespace vsim::app
