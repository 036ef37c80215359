#include "ArtifactFiles.h"

#include "BundleFiles.h"
#include "vsim/core/Error.h"
#include "vsim/interop/ItkImage.h"
#include "vsim/interop/VtkMesh.h"

#include <itkImageFileReader.h>
#include <itkImageFileWriter.h>
#include <itkNrrdImageIO.h>
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

template <typename T>
void writeNrrd(const ImageVolume<T>& volume, const std::filesystem::path& file, bool compress)
{
    auto writer = itk::ImageFileWriter<interop::ItkImage3<T>>::New();
    writer->SetImageIO(itk::NrrdImageIO::New());
    writer->SetInput(interop::toItk(volume));
    writer->SetFileName(file.string());
    writer->SetUseCompression(compress);
    try
    {
        writer->Update();
    }
    catch (const itk::ExceptionObject& exception)
    {
        throw Error("cannot write NRRD image", {{"file", file.string()}, {"reason", exception.GetDescription()}});
    }
}

template <typename T>
ImageVolume<T> readNrrd(const std::filesystem::path& file)
{
    auto reader = itk::ImageFileReader<interop::ItkImage3<T>>::New();
    reader->SetImageIO(itk::NrrdImageIO::New());
    reader->SetFileName(file.string());
    try
    {
        reader->Update();
    }
    catch (const itk::ExceptionObject& exception)
    {
        throw Error("cannot read NRRD image", {{"file", file.string()}, {"reason", exception.GetDescription()}});
    }
    return interop::fromItk<T>(reader->GetOutput());
}

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

template <typename Writer, typename DataSet>
void writeVtkXml(DataSet* data, const std::filesystem::path& file)
{
    auto writer = vtkSmartPointer<Writer>::New();
    writer->SetInputData(data);
    writer->SetFileName(file.c_str());
    writer->SetDataModeToBinary();
    if (writer->Write() != 1)
        throw Error("cannot write VTK XML file", {{"file", file.string()}});
}

template <typename Reader>
auto readVtkXml(const std::filesystem::path& file)
{
    if (!std::filesystem::exists(file))
        throw Error("file does not exist", {{"file", file.string()}});
    auto reader = vtkSmartPointer<Reader>::New();
    reader->SetFileName(file.c_str());
    reader->Update();
    if (reader->GetErrorCode() != 0 || !reader->GetOutput())
        throw Error("cannot read VTK XML file", {{"file", file.string()}});
    return vtkSmartPointer<std::remove_pointer_t<decltype(reader->GetOutput())>>(reader->GetOutput());
}

} // namespace

ArtifactKind kindOf(const ArtifactData& data)
{
    static constexpr ArtifactKind kinds[] = {ArtifactKind::Image, ArtifactKind::Label, ArtifactKind::Surface,
                                             ArtifactKind::TetMesh, ArtifactKind::Skeleton};
    return kinds[data.index()];
}

std::string fileExtension(ArtifactKind kind)
{
    switch (kind)
    {
    case ArtifactKind::Image:
    case ArtifactKind::Label: return ".nrrd";
    case ArtifactKind::Surface: return ".vtp";
    case ArtifactKind::TetMesh: return ".vtu";
    case ArtifactKind::Skeleton: return ".json";
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
    }
    return {};
}

void writeArtifactFile(const ArtifactData& data, const std::filesystem::path& file)
{
    switch (kindOf(data))
    {
    case ArtifactKind::Image: writeNrrd(std::get<CtVolume>(data), file, false); break;
    case ArtifactKind::Label: writeNrrd(std::get<LabelVolume>(data), file, true); break;
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
    }
    syncFile(file);
}

VolumeGeometry readVolumeGeometry(const std::filesystem::path& file)
{
    auto io = itk::NrrdImageIO::New();
    io->SetFileName(file.string());
    try
    {
        io->ReadImageInformation();
    }
    catch (const itk::ExceptionObject& exception)
    {
        throw Error("cannot read NRRD header", {{"file", file.string()}, {"reason", exception.GetDescription()}});
    }
    if (io->GetNumberOfDimensions() != 3)
        throw Error("image file is not 3D", {{"file", file.string()}});
    VolumeGeometry geometry;
    for (unsigned axis = 0; axis < 3; ++axis)
    {
        geometry.dims[axis] = static_cast<int>(io->GetDimensions(axis));
        geometry.spacing[axis] = io->GetSpacing(axis);
        geometry.origin[axis] = io->GetOrigin(axis);
        const std::vector<double> column = io->GetDirection(axis);
        for (unsigned row = 0; row < 3; ++row)
            geometry.direction(row, axis) = column[row];
    }
    return geometry;
}

ArtifactData readArtifactFile(ArtifactKind kind, const std::filesystem::path& file)
{
    switch (kind)
    {
    case ArtifactKind::Image: return readNrrd<std::int16_t>(file);
    case ArtifactKind::Label: return readNrrd<std::uint8_t>(file);
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
    }
    throw Error("unknown artifact kind");
}

} // namespace vsim::study
