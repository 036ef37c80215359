#include "SliceFieldLayer.h"
#include "SliceDepths.h"

#include "FieldScene.h"

#include "vsim/core/Error.h"
#include "vsim/interop/VtkMesh.h"
#include "vsim/interop/VtkSimulationData.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCutter.h>
#include <vtkDataSetMapper.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkLookupTable.h>
#include <vtkMatrix4x4.h>
#include <vtkPlane.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTransform.h>
#include <vtkTransformFilter.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <cmath>

namespace vsim::viz {
namespace {

constexpr double kSmallestTubeMm = 0.3; // a segment sized only by its resistance still shows as a ring

[[noreturn]] void noField(const SimulationData& frame, const std::string& field)
{
    throw Error(Pattern{"the %1 frame has no field '%2' to show in the slices", {dataKindName(frame), field}});
}

/// The frame as a VTK dataset whose array `field` (cell data when `cellData`) holds the values to colour by.
vtkSmartPointer<vtkDataSet> frameDataSet(const SimulationData& frame, const std::string& field,
                                         bool& cellData)
{
    if (const auto* mesh = std::get_if<TetMesh>(&frame))
    {
        cellData = mesh->cellFields.count(field) > 0;
        if (!cellData && !mesh->pointFields.count(field))
            noField(frame, field);
        return interop::toVtk(*mesh);
    }
    if (const auto* network = std::get_if<VesselNetwork>(&frame))
    {
        const auto values = network->segmentFields.find(field);
        if (values == network->segmentFields.end())
            noField(frame, field);
        std::vector<std::vector<Eigen::Vector3d>> lines;
        std::vector<std::array<double, 2>> radii;
        for (std::size_t s = 0; s < network->segments.size(); ++s)
        {
            lines.push_back(network->segmentPath(s));
            const VesselNetwork::Segment& segment = network->segments[s];
            radii.push_back({std::max(kSmallestTubeMm, segment.startRadiusMm),
                             std::max(kSmallestTubeMm, segment.endRadiusMm)});
        }
        cellData = true;
        vtkSmartPointer<vtkPolyData> tubes = detail::fieldTubes(lines, values->second, radii);
        tubes->GetCellData()->GetScalars()->SetName(field.c_str());
        return tubes;
    }
    const GridFields& grid = std::get<GridFields>(frame);
    if (!grid.fields.count(field))
        noField(frame, field);
    cellData = false;
    return interop::toVtk(grid);
}

} // namespace

SliceFieldLayer::SliceFieldLayer(vtkRenderer* renderer)
    : m_renderer(renderer), m_pickedParticles(vtkSmartPointer<vtkPolyData>::New()), m_plane(vtkSmartPointer<vtkPlane>::New()),
      m_cutter(vtkSmartPointer<vtkCutter>::New()), m_toSlice(vtkSmartPointer<vtkTransform>::New()),
      m_toSliceFilter(vtkSmartPointer<vtkTransformFilter>::New()),
      m_mapper(vtkSmartPointer<vtkDataSetMapper>::New()), m_actor(vtkSmartPointer<vtkActor>::New())
{
    m_cutter->SetCutFunction(m_plane);
    m_toSliceFilter->SetTransform(m_toSlice);
    m_toSliceFilter->SetInputConnection(m_cutter->GetOutputPort());
    m_mapper->SetInputConnection(m_toSliceFilter->GetOutputPort());
    m_actor->SetMapper(m_mapper);
    m_actor->GetProperty()->LightingOff(); // a flat cut: its colour is the value
    m_actor->GetProperty()->SetLineWidth(2.5);
    m_actor->GetProperty()->SetPointSize(5.0);
    m_actor->VisibilityOff();
    m_renderer->AddViewProp(m_actor);
}

SliceFieldLayer::~SliceFieldLayer()
{
    m_renderer->RemoveViewProp(m_actor);
}

void SliceFieldLayer::setField(const SimulationData& frame, const std::string& field, double low, double high)
{
    bool cellData = false;
    m_particles.reset();
    if (const auto* particles = std::get_if<ParticleSet>(&frame))
    {
        if (!particles->fields.count(field))
            noField(frame, field);
        m_particles = *particles;
        m_field = field;
        m_cutter->RemoveAllInputs();
        m_toSliceFilter->SetInputData(m_pickedParticles);
    }
    else
    {
        m_cutter->SetInputData(frameDataSet(frame, field, cellData));
        m_toSliceFilter->SetInputConnection(m_cutter->GetOutputPort());
    }
    m_mapper->SetLookupTable(detail::fieldLookupTable(low, high));
    m_mapper->SetScalarRange(low, high);
    m_mapper->ScalarVisibilityOn();
    if (cellData)
        m_mapper->SetScalarModeToUseCellFieldData();
    else
        m_mapper->SetScalarModeToUsePointFieldData();
    m_mapper->SelectColorArray(field.c_str());
    m_actor->VisibilityOn();
}

void SliceFieldLayer::clear()
{
    m_particles.reset();
    m_cutter->RemoveAllInputs();
    m_actor->VisibilityOff();
}

bool SliceFieldLayer::isEmpty() const
{
    return !m_actor->GetVisibility();
}

void SliceFieldLayer::pickParticles(const Eigen::Vector3d& cursorMm, const Eigen::Vector3d& normal,
                                    double thicknessMm)
{
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToDouble();
    auto vertices = vtkSmartPointer<vtkCellArray>::New();
    auto values = vtkSmartPointer<vtkDoubleArray>::New();
    values->SetName(m_field.c_str());
    const std::vector<double>& field = m_particles->fields.at(m_field);
    for (std::size_t i = 0; i < m_particles->positionsMm.size(); ++i)
        if (std::abs((m_particles->positionsMm[i] - cursorMm).dot(normal)) <= 0.5 * thicknessMm)
        {
            const vtkIdType id = points->InsertNextPoint(m_particles->positionsMm[i].data());
            vertices->InsertNextCell(1, &id);
            values->InsertNextValue(field[i]);
        }
    m_pickedParticles->Initialize();
    m_pickedParticles->SetPoints(points);
    m_pickedParticles->SetVerts(vertices);
    m_pickedParticles->GetPointData()->AddArray(values);
    m_pickedParticles->Modified();
}

void SliceFieldLayer::update(const Eigen::Vector3d& cursorMm, const ScreenAxes& axes, double thicknessMm)
{
    const Eigen::Vector3d normal = axes.normal();
    if (m_particles)
        pickParticles(cursorMm, normal, thicknessMm);
    m_plane->SetOrigin(cursorMm.data());
    m_plane->SetNormal(normal.data());
    // Patient mm -> slice coordinates: rows right, up, normal applied to (p - cursor), pushed to slice_depth::kField.
    auto matrix = vtkSmartPointer<vtkMatrix4x4>::New();
    const Eigen::Vector3d rows[3] = {axes.right, axes.up, normal};
    for (int r = 0; r < 3; ++r)
    {
        for (int c = 0; c < 3; ++c)
            matrix->SetElement(r, c, rows[r][c]);
        matrix->SetElement(r, 3, -rows[r].dot(cursorMm) + (r == 2 ? slice_depth::kField : 0.0));
    }
    m_toSlice->SetMatrix(matrix);
}

long long SliceFieldLayer::cellsShown() const
{
    if (isEmpty())
        return 0;
    m_toSliceFilter->Update();
    return m_toSliceFilter->GetOutput()->GetNumberOfCells();
}

} // namespace vsim::viz
