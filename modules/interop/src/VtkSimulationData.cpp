#include "vsim/interop/VtkSimulationData.h"

#include "vsim/core/Error.h"

#include "VtkFields.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkImageData.h>
#include <vtkIntArray.h>
#include <vtkMatrix3x3.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>

namespace vsim::interop {
namespace {

const std::vector<std::string> kSegmentArrays = {"segment_start_radius_mm", "segment_end_radius_mm", "segment_length_mm",
                                                 "segment_resistance_pa_s_m3"};

vtkDataArray* requiredArray(vtkFieldData* data, const char* name)
{
    vtkDataArray* array = data ? data->GetArray(name) : nullptr;
    if (!array)
        throw Error(Pattern{"not a vessel network frame: the array %1 is missing", {name}});
    return array;
}

} // namespace

vtkSmartPointer<vtkPolyData> toVtk(const VesselNetwork& network)
{
    std::vector<Eigen::Vector3d> points;
    std::vector<double> nodeIndex;
    for (std::size_t n = 0; n < network.nodes.size(); ++n)
        points.push_back(network.nodes[n].positionMm), nodeIndex.push_back(double(n));
    auto lines = vtkSmartPointer<vtkCellArray>::New();
    std::map<std::string, std::vector<double>> segmentArrays;
    for (const VesselNetwork::Segment& segment : network.segments)
    {
        std::vector<vtkIdType> ids{segment.from};
        for (std::size_t p = 1; p + 1 < segment.pathMm.size(); ++p)
            ids.push_back(vtkIdType(points.size())), points.push_back(segment.pathMm[p]), nodeIndex.push_back(-1.0);
        ids.push_back(segment.to);
        lines->InsertNextCell(vtkIdType(ids.size()), ids.data());
        segmentArrays[kSegmentArrays[0]].push_back(segment.startRadiusMm);
        segmentArrays[kSegmentArrays[1]].push_back(segment.endRadiusMm);
        segmentArrays[kSegmentArrays[2]].push_back(segment.lengthMm);
        segmentArrays[kSegmentArrays[3]].push_back(segment.resistance);
    }
    auto polyData = vtkSmartPointer<vtkPolyData>::New();
    polyData->SetPoints(pointsToVtk(points));
    polyData->SetLines(lines);
    fieldsToVtk({{"node_index", nodeIndex}}, polyData->GetPointData());
    fieldsToVtk(segmentArrays, polyData->GetCellData());
    fieldsToVtk(network.segmentFields, polyData->GetCellData());
    std::map<std::string, std::vector<double>> conditions{{"root", {double(network.root)}}};
    for (const VesselNetwork::Outlet& outlet : network.outlets)
    {
        conditions["outlet_node"].push_back(outlet.node);
        conditions["outlet_is_pressure"].push_back(outlet.type == VesselNetwork::Outlet::Type::Pressure ? 1.0 : 0.0);
        conditions["outlet_pressure_pa"].push_back(outlet.pressurePa);
        conditions["outlet_resistance_pa_s_m3"].push_back(outlet.resistance);
    }
    fieldsToVtk(conditions, polyData->GetFieldData());
    return polyData;
}

VesselNetwork networkFromVtk(vtkPolyData* polyData)
{
    if (!polyData)
        throw Error("no vessel network to convert");
    const std::vector<Eigen::Vector3d> points = pointsFromVtk(polyData->GetPoints());
    vtkDataArray* nodeIndex = requiredArray(polyData->GetPointData(), "node_index");
    VesselNetwork network;
    for (vtkIdType p = 0; p < vtkIdType(points.size()); ++p)
        if (const int n = int(nodeIndex->GetComponent(p, 0)); n >= 0)
        {
            if (std::size_t(n) >= network.nodes.size())
                network.nodes.resize(std::size_t(n) + 1);
            network.nodes[std::size_t(n)].positionMm = points[std::size_t(p)];
        }
    vtkDataArray* segmentArrays[4];
    for (int a = 0; a < 4; ++a)
        segmentArrays[a] = requiredArray(polyData->GetCellData(), kSegmentArrays[std::size_t(a)].c_str());
    auto ids = vtkSmartPointer<vtkIdList>::New();
    vtkCellArray* lines = polyData->GetLines();
    lines->InitTraversal();
    for (vtkIdType cell = 0; lines->GetNextCell(ids); ++cell)
    {
        VesselNetwork::Segment segment;
        const vtkIdType first = ids->GetId(0), last = ids->GetId(ids->GetNumberOfIds() - 1);
        segment.from = int(nodeIndex->GetComponent(first, 0)), segment.to = int(nodeIndex->GetComponent(last, 0));
        if (ids->GetNumberOfIds() < 2 || segment.from < 0 || segment.to < 0)
            throw Error("not a vessel network frame: a line does not run from node to node",
                        {{"line", std::to_string(cell)}});
        if (ids->GetNumberOfIds() > 2)
            for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
                segment.pathMm.push_back(points[std::size_t(ids->GetId(k))]);
        segment.startRadiusMm = segmentArrays[0]->GetComponent(cell, 0);
        segment.endRadiusMm = segmentArrays[1]->GetComponent(cell, 0);
        segment.lengthMm = segmentArrays[2]->GetComponent(cell, 0);
        segment.resistance = segmentArrays[3]->GetComponent(cell, 0);
        network.segments.push_back(segment);
    }
    network.segmentFields = fieldsFromVtk(polyData->GetCellData(), kSegmentArrays);
    const auto conditions = fieldsFromVtk(polyData->GetFieldData());
    if (const auto root = conditions.find("root"); root != conditions.end() && !root->second.empty())
        network.root = int(root->second.front());
    if (const auto nodes = conditions.find("outlet_node"); nodes != conditions.end())
        for (std::size_t o = 0; o < nodes->second.size(); ++o)
        {
            VesselNetwork::Outlet outlet;
            outlet.node = int(nodes->second[o]);
            outlet.type = conditions.at("outlet_is_pressure").at(o) > 0.5 ? VesselNetwork::Outlet::Type::Pressure
                                                                           : VesselNetwork::Outlet::Type::Resistance;
            outlet.pressurePa = conditions.at("outlet_pressure_pa").at(o);
            outlet.resistance = conditions.at("outlet_resistance_pa_s_m3").at(o);
            network.outlets.push_back(outlet);
        }
    return network;
}

vtkSmartPointer<vtkImageData> toVtk(const GridFields& grid)
{
    const VolumeGeometry& g = grid.geometry;
    auto image = vtkSmartPointer<vtkImageData>::New();
    image->SetDimensions(g.dims[0], g.dims[1], g.dims[2]);
    image->SetSpacing(g.spacing.x(), g.spacing.y(), g.spacing.z());
    image->SetOrigin(g.origin.x(), g.origin.y(), g.origin.z());
    double direction[9];
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            direction[3 * r + c] = g.direction(r, c);
    image->SetDirectionMatrix(direction);
    for (const auto& [name, field] : grid.fields)
    {
        if (field.geometry().dims != g.dims)
            throw Error("a grid field does not match its grid", {{"field", name}});
        auto array = vtkSmartPointer<vtkFloatArray>::New();
        array->SetName(name.c_str());
        array->SetNumberOfValues(vtkIdType(field.size()));
        std::copy(field.data(), field.data() + field.size(), array->GetPointer(0));
        image->GetPointData()->AddArray(array);
    }
    return image;
}

GridFields gridFieldsFromVtk(vtkImageData* image)
{
    if (!image || image->GetPointData()->GetNumberOfArrays() == 0)
        throw Error("not a voxel-grid frame: no point arrays");
    GridFields grid;
    int dims[3];
    image->GetDimensions(dims);
    grid.geometry.dims = {dims[0], dims[1], dims[2]};
    image->GetSpacing(grid.geometry.spacing.data());
    image->GetOrigin(grid.geometry.origin.data());
    vtkMatrix3x3* direction = image->GetDirectionMatrix();
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            grid.geometry.direction(r, c) = direction->GetElement(r, c);
    grid.geometry.validate();
    for (int a = 0; a < image->GetPointData()->GetNumberOfArrays(); ++a)
    {
        vtkDataArray* array = image->GetPointData()->GetArray(a);
        if (!array || !array->GetName() || array->GetNumberOfComponents() != 1 ||
            array->GetNumberOfTuples() != vtkIdType(grid.geometry.voxelCount()))
            throw Error("not a voxel-grid frame: a point array is not one value per voxel");
        RealVolume field = RealVolume::uninitialized(grid.geometry);
        for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
            field.data()[i] = float(array->GetComponent(i, 0));
        grid.fields.emplace(array->GetName(), field);
    }
    return grid;
}

vtkSmartPointer<vtkPolyData> toVtk(const ParticleSet& particles)
{
    particles.validate();
    auto vertices = vtkSmartPointer<vtkCellArray>::New();
    for (vtkIdType i = 0; i < vtkIdType(particles.positionsMm.size()); ++i)
        vertices->InsertNextCell(1, &i);
    auto polyData = vtkSmartPointer<vtkPolyData>::New();
    polyData->SetPoints(pointsToVtk(particles.positionsMm));
    polyData->SetVerts(vertices);
    fieldsToVtk(particles.fields, polyData->GetPointData());
    return polyData;
}

ParticleSet particlesFromVtk(vtkPolyData* polyData)
{
    if (!polyData || polyData->GetNumberOfLines() > 0 || polyData->GetNumberOfPolys() > 0 || polyData->GetNumberOfStrips() > 0)
        throw Error("not a particle frame: it has lines or polygons");
    ParticleSet particles;
    if (polyData->GetPoints())
        particles.positionsMm = pointsFromVtk(polyData->GetPoints());
    particles.fields = fieldsFromVtk(polyData->GetPointData(), {});
    particles.validate();
    return particles;
}

} // namespace vsim::interop
