#include "ArtifactFiles.h"

#include "BundleFiles.h"
#include "RunFiles.h"
#include "VtkXmlFiles.h"
#include "vsim/core/Error.h"
#include "vsim/interop/NrrdFile.h"
#include "vsim/interop/VtkMesh.h"
#include "vsim/study/NetworkFile.h"

#include <nlohmann/json.hpp>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <fstream>

namespace vsim::study {
namespace {

using nlohmann::json;

json vectorToJson(const Eigen::Vector3d& vector)
{
    return json::array({vector.x(), vector.y(), vector.z()});
}

json skeletonToJson(const SkeletonGraph& skeleton)
{
    json nodes = json::array();
    for (const auto& node : skeleton.nodes)
        nodes.push_back({{"position_mm", vectorToJson(node.position)}, {"voxel", node.voxel}});
    json edges = json::array();
    for (const auto& edge : skeleton.edges)
    {
        json points = json::array();
        for (const auto& point : edge.points)
            points.push_back(vectorToJson(point));
        edges.push_back({{"from", edge.from}, {"to", edge.to}, {"voxels", edge.voxels}, {"points_mm", points},
                         {"radii_mm", edge.radii}});
    }
    return {{"nodes", nodes}, {"edges", edges}};
}

Eigen::Vector3d vectorFromJson(const json& value)
{
    return {value.at(0).get<double>(), value.at(1).get<double>(), value.at(2).get<double>()};
}

SkeletonGraph skeletonFromJson(const json& document)
{
    SkeletonGraph skeleton;
    for (const auto& node : document.at("nodes"))
        skeleton.nodes.push_back({vectorFromJson(node.at("position_mm")), node.at("voxel").get<std::array<int, 3>>()});
    for (const auto& entry : document.at("edges"))
    {
        SkeletonGraph::Edge edge;
        edge.from = entry.at("from").get<int>();
        edge.to = entry.at("to").get<int>();
        edge.voxels = entry.at("voxels").get<std::vector<std::array<int, 3>>>();
        for (const auto& point : entry.at("points_mm"))
            edge.points.push_back(vectorFromJson(point));
        edge.radii = entry.at("radii_mm").get<std::vector<double>>();
        skeleton.edges.push_back(std::move(edge));
    }
    skeleton.validate();
    return skeleton;
}

/// A view measurement: its kind, points and plane; the figures are written for readers and read back as written.
json measurementToJson(const ViewMeasurement& m)
{
    json points = json::array();
    for (const Eigen::Vector3d& point : m.pointsMm)
        points.push_back(vectorToJson(point));
    return {{"kind", kindName(m.kind)},        {"points_mm", points},           {"plane_right", vectorToJson(m.planeRight)},
            {"plane_up", vectorToJson(m.planeUp)}, {"length_mm", m.lengthMm},     {"angle_degrees", m.angleDegrees},
            {"mean_hu", m.meanHu},              {"sd_hu", m.sdHu},               {"area_mm2", m.areaMm2},
            {"samples", m.samples}};
}

ViewMeasurement measurementFromJson(const json& document)
{
    ViewMeasurement m;
    m.kind = measurementKindFromName(document.at("kind").get<std::string>());
    for (const auto& point : document.at("points_mm"))
        m.pointsMm.push_back(vectorFromJson(point));
    if (int(m.pointsMm.size()) != pointCount(m.kind))
        throw Error(Pattern{"a %1 takes %2 points", {kindName(m.kind), std::to_string(pointCount(m.kind))}});
    m.planeRight = vectorFromJson(document.at("plane_right"));
    m.planeUp = vectorFromJson(document.at("plane_up"));
    m.lengthMm = document.value("length_mm", 0.0);
    m.angleDegrees = document.value("angle_degrees", 0.0);
    m.meanHu = document.value("mean_hu", 0.0);
    m.sdHu = document.value("sd_hu", 0.0);
    m.areaMm2 = document.value("area_mm2", 0.0);
    m.samples = document.value("samples", 0LL);
    return m;
}

} // namespace

using detail::readVtkXml;
using detail::writeVtkXml;

ArtifactKind kindOf(const ArtifactData& data)
{
    static_assert(std::size(kArtifactKinds) == std::variant_size_v<ArtifactData>);
    return kArtifactKinds[data.index()];
}

std::string fileExtension(ArtifactKind kind)
{
    switch (kind)
    {
    case ArtifactKind::Image:
    case ArtifactKind::Label: return ".nrrd";
    case ArtifactKind::Surface: return ".vtp";
    case ArtifactKind::TetMesh: return ".vtu";
    case ArtifactKind::Skeleton:
    case ArtifactKind::Network:
    case ArtifactKind::Measurement:
    case ArtifactKind::Run: return ".json";
    case ArtifactKind::Report: return ".pdf";
    }
    return {};
}

std::string folderName(ArtifactKind kind)
{
    switch (kind)
    {
    case ArtifactKind::Image: return "images";
    case ArtifactKind::Label: return "labels";
    case ArtifactKind::Surface: return "surfaces";
    case ArtifactKind::TetMesh: return "meshes";
    case ArtifactKind::Skeleton: return "skeletons";
    case ArtifactKind::Network: return "networks";
    case ArtifactKind::Report: return "reports";
    case ArtifactKind::Run: return "runs";
    case ArtifactKind::Measurement: return "measurements";
    }
    return {};
}

std::filesystem::path artifactFilePath(ArtifactKind kind, const std::string& id)
{
    if (kind == ArtifactKind::Run)
        return std::filesystem::path(folderName(kind)) / id / "run.json";
    return std::filesystem::path(folderName(kind)) / (id + fileExtension(kind));
}

void writeArtifactFile(const ArtifactData& data, const std::filesystem::path& file)
{
    switch (kindOf(data))
    {
    case ArtifactKind::Image: interop::writeNrrd(std::get<CtVolume>(data), file, false); break;
    case ArtifactKind::Label: interop::writeNrrd(std::get<LabelVolume>(data), file, true); break;
    case ArtifactKind::Surface:
        writeVtkXml<vtkXMLPolyDataWriter>(interop::toVtk(std::get<TriangleMesh>(data)).Get(), file);
        break;
    case ArtifactKind::TetMesh:
        writeVtkXml<vtkXMLUnstructuredGridWriter>(interop::toVtk(std::get<TetMesh>(data)).Get(), file);
        break;
    case ArtifactKind::Skeleton:
    {
        std::ofstream stream(file, std::ios::trunc);
        stream << skeletonToJson(std::get<SkeletonGraph>(data)).dump();
        if (!stream.flush())
            throw Error("cannot write skeleton", {{"file", file.string()}});
        break;
    }
    case ArtifactKind::Network: writeNetworkFile(std::get<VesselNetwork>(data), file); break;
    case ArtifactKind::Report:
    {
        std::ofstream stream(file, std::ios::binary | std::ios::trunc);
        const std::string& bytes = std::get<Document>(data).bytes;
        if (!stream.write(bytes.data(), std::streamsize(bytes.size())) || !stream.flush())
            throw Error("cannot write the report", {{"file", file.string()}});
        break;
    }
    case ArtifactKind::Run: writeRunFolder(std::get<SolverRun>(data), file); break;
    case ArtifactKind::Measurement:
    {
        std::ofstream stream(file, std::ios::trunc);
        stream << measurementToJson(std::get<ViewMeasurement>(data)).dump(2);
        if (!stream.flush())
            throw Error("cannot write the measurement", {{"file", file.string()}});
        break;
    }
    }
    syncFile(file);
}

VolumeGeometry readVolumeGeometry(const std::filesystem::path& file)
{
    return interop::readNrrdGeometry(file);
}

ArtifactData readArtifactFile(ArtifactKind kind, const std::filesystem::path& file)
{
    switch (kind)
    {
    case ArtifactKind::Image: return interop::readNrrd<std::int16_t>(file);
    case ArtifactKind::Label: return interop::readNrrd<std::uint8_t>(file);
    case ArtifactKind::Surface:
        return interop::triangleMeshFromVtk(readVtkXml<vtkXMLPolyDataReader>(file).Get());
    case ArtifactKind::TetMesh:
        return interop::tetMeshFromVtk(readVtkXml<vtkXMLUnstructuredGridReader>(file).Get());
    case ArtifactKind::Skeleton:
        try
        {
            return skeletonFromJson(json::parse(readTextFile(file)));
        }
        catch (const json::exception& exception)
        {
            throw Error("cannot parse skeleton", {{"file", file.string()}, {"reason", exception.what()}});
        }
    case ArtifactKind::Network: return readNetworkFile(file);
    case ArtifactKind::Report: return Document{readTextFile(file)};
    case ArtifactKind::Run: return readRunFolder(file, true);
    case ArtifactKind::Measurement:
        try
        {
            return measurementFromJson(json::parse(readTextFile(file)));
        }
        catch (const json::exception& exception)
        {
            throw Error("cannot parse the measurement", {{"file", file.string()}, {"reason", exception.what()}});
        }
    }
    throw Error("unknown artifact kind");
}

} // namespace vsim::study
