#include "vsim/core/Version.h"
#include "vsim/dicom/PhantomModel.h"

#include <nlohmann/json.hpp>

namespace vsim::dicom {
namespace {

using nlohmann::json;

json vec(const Eigen::Vector3d& v)
{
    return json::array({v.x(), v.y(), v.z()});
}

std::string shapeTypeName(TissueShape::Type type)
{
    return type == TissueShape::Type::EllipticCylinder ? "elliptic-cylinder-z" : "ellipsoid";
}

} // namespace

std::string phantomTruthJson(const PhantomModel& model, const PhantomOptions& options)
{
    const VolumeGeometry geometry = phantomGeometry(options);
    std::vector<int> degree(model.nodes.size(), 0);
    for (const VesselSegment& segment : model.segments)
    {
        ++degree[segment.from];
        ++degree[segment.to];
    }
    json nodes = json::array();
    for (std::size_t n = 0; n < model.nodes.size(); ++n)
        nodes.push_back({{"id", n},
                         {"position_mm", vec(model.nodes[n].position)},
                         {"degree", degree[n]},
                         {"type", degree[n] == 1 ? "end" : "junction"}});
    json segments = json::array();
    for (std::size_t s = 0; s < model.segments.size(); ++s)
    {
        const VesselSegment& segment = model.segments[s];
        json points = json::array();
        for (const auto& point : segment.points)
            points.push_back(vec(point));
        segments.push_back({{"id", s},
                            {"name", segment.name},
                            {"from", segment.from},
                            {"to", segment.to},
                            {"parent", segment.parent},
                            {"generation", segment.generation},
                            {"length_mm", segment.lengthMm()},
                            {"radius_start_mm", segment.radii.front()},
                            {"radius_end_mm", segment.radii.back()},
                            {"centerline_mm", points},
                            {"radii_mm", segment.radii}});
    }
    json tissues = json::array();
    for (const TissueShape& shape : model.tissues)
        tissues.push_back({{"name", shape.name},
                           {"type", shapeTypeName(shape.type)},
                           {"centre_mm", vec(shape.centre)},
                           {"semi_axes_mm", vec(shape.semiAxes)},
                           {"hu", shape.hu},
                           {"label", shape.label}});
    const json document = {
        {"format", "vascusim-phantom-truth"},
        {"format_version", 1},
        {"software_version", kVersion},
        {"kind", phantomKindName(model.kind)},
        {"options",
         {{"size", options.size},
          {"spacing_mm", vec(options.spacing)},
          {"noise_hu", options.noiseHu},
          {"seed", options.seed},
          {"blur_sigma_mm", options.effectiveBlurMm()},
          {"aneurysm_diameter_mm", options.aneurysmDiameterMm},
          {"stenosis_percent", options.stenosisPercent},
          {"second_stenosis_percent", options.secondStenosisPercent},
          {"vessel_diameter_mm", options.vesselDiameterMm},
          {"stenosis_length_mm", options.stenosisLengthMm}}},
        {"geometry",
         {{"dims", geometry.dims},
          {"spacing_mm", vec(geometry.spacing)},
          {"origin_mm", vec(geometry.origin)},
          {"direction_columns", {vec(geometry.direction.col(0)), vec(geometry.direction.col(1)),
                                 vec(geometry.direction.col(2))}},
          {"frame", "LPS"}}},
        {"blood_hu", model.bloodHu},
        {"labels", {{"1", "vessel lumen"}, {"2", "tumour"}, {"3", "bone"}}},
        {"topology", {{"nodes", nodes.size()}, {"segments", segments.size()}}},
        {"nodes", nodes},
        {"segments", segments},
        {"tissues", tissues},
        {"measures", model.measures},
        {"note", "Centerlines, radii and measures describe the analytic model; parts outside the field of view are "
                 "not in the images. Radii are lumen radii perpendicular to the centerline."}};
    return document.dump(2) + "\n";
}

} // namespace vsim::dicom
