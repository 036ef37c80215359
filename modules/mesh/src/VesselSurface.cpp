#include "vsim/mesh/VesselSurface.h"

#include "vsim/core/Localized.h"
#include "vsim/interop/VtkMesh.h"

#include <vtkFieldData.h>
#include <vtkFlyingEdges3D.h>
#include <vtkHausdorffDistancePointSetFilter.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkQuadricDecimation.h>
#include <vtkSTLWriter.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowedSincPolyDataFilter.h>

#include <algorithm>

namespace vsim::mesh {
namespace {

/// The voxels equal to `value` as a 0/1 image in voxel coordinates (origin 0, spacing 1).
vtkSmartPointer<vtkImageData> binaryImage(const LabelVolume& label, std::uint8_t value)
{
    const auto& dims = label.geometry().dims;
    auto image = vtkSmartPointer<vtkImageData>::New();
    image->SetDimensions(dims[0], dims[1], dims[2]);
    auto scalars = vtkSmartPointer<vtkUnsignedCharArray>::New();
    scalars->SetNumberOfValues(vtkIdType(label.size()));
    std::size_t inside = 0;
    for (std::size_t i = 0; i < label.size(); ++i)
    {
        const bool in = label.data()[i] == value;
        scalars->SetValue(vtkIdType(i), in ? 1 : 0);
        inside += in;
    }
    if (inside == 0)
        throw Error("the label is empty: segment the vessels first");
    image->GetPointData()->SetScalars(scalars);
    return image;
}

/// Voxel coordinates -> patient frame (mm), in place.
void toPatientFrame(vtkPolyData* surface, const VolumeGeometry& geometry)
{
    vtkPoints* points = surface->GetPoints();
    for (vtkIdType p = 0; p < points->GetNumberOfPoints(); ++p)
    {
        double index[3];
        points->GetPoint(p, index);
        const Eigen::Vector3d patient = geometry.indexToPatient(Eigen::Vector3d(index[0], index[1], index[2]));
        points->SetPoint(p, patient.x(), patient.y(), patient.z());
    }
}

double meanOf(vtkDataArray* distances)
{
    double sum = 0;
    for (vtkIdType i = 0; i < distances->GetNumberOfTuples(); ++i)
        sum += distances->GetTuple1(i);
    return distances->GetNumberOfTuples() ? sum / double(distances->GetNumberOfTuples()) : 0.0;
}

} // namespace

std::vector<ParameterSpec> surfaceParameters()
{
    const std::string group = "Surface";
    return {
        {"smoothing_iterations", "Smoothing iterations", "", 20, 0, 200, group,
         "Windowed-sinc smoothing iterations (Taubin et al. 1996).", ParameterSpec::Kind::Integer},
        {"smoothing_passband", "Smoothing passband", "", 0.05, 0.001, 1, group,
         "Windowed-sinc pass band: lower is smoother."},
        {"target_vertices", "Vertex budget", "", 0, 0, 10000000, group,
         "Decimate to about this many vertices (thesis: 1,427-2,251 for simulation); 0 keeps every vertex.",
         ParameterSpec::Kind::Integer},
    };
}

VesselSurface extractVesselSurface(const LabelVolume& label, std::uint8_t value, const ParameterSet& p,
                                   const Progress& progress)
{
    progress.report(0.0, localized("vsim::Progress", "iso-surface"));
    auto iso = vtkSmartPointer<vtkFlyingEdges3D>::New();
    iso->SetInputData(binaryImage(label, value));
    iso->SetValue(0, 0.5);
    iso->ComputeNormalsOff();
    iso->ComputeGradientsOff();
    iso->ComputeScalarsOff();
    iso->Update();
    vtkSmartPointer<vtkPolyData> surface = iso->GetOutput();
    toPatientFrame(surface, label.geometry());
    progress.report(0.3, localized("vsim::Progress", "smoothing"));

    const int iterations = int(p.get("smoothing_iterations"));
    if (iterations > 0)
    {
        auto smooth = vtkSmartPointer<vtkWindowedSincPolyDataFilter>::New();
        smooth->SetInputData(surface);
        smooth->SetNumberOfIterations(iterations);
        smooth->SetPassBand(p.get("smoothing_passband"));
        smooth->NormalizeCoordinatesOn();
        smooth->BoundarySmoothingOff();
        smooth->FeatureEdgeSmoothingOff();
        smooth->NonManifoldSmoothingOn();
        smooth->Update();
        surface = smooth->GetOutput();
    }
    progress.throwIfCancelled();

    VesselSurface result;
    result.fullVertices = std::size_t(surface->GetNumberOfPoints());
    const double target = p.get("target_vertices");
    if (target > 0 && target < double(result.fullVertices))
    {
        progress.report(0.6, localized("vsim::Progress", "decimating"));
        auto decimate = vtkSmartPointer<vtkQuadricDecimation>::New();
        decimate->SetInputData(surface);
        decimate->SetTargetReduction(1.0 - target / double(result.fullVertices));
        decimate->VolumePreservationOn();
        decimate->Update();
        vtkSmartPointer<vtkPolyData> decimated = decimate->GetOutput();
        auto distance = vtkSmartPointer<vtkHausdorffDistancePointSetFilter>::New();
        distance->SetInputData(0, decimated);
        distance->SetInputData(1, surface);
        distance->SetTargetDistanceMethodToPointToCell();
        distance->Update();
        const double there = meanOf(distance->GetOutput(0)->GetPointData()->GetArray("Distance"));
        const double back = meanOf(distance->GetOutput(1)->GetPointData()->GetArray("Distance"));
        result.meanErrorMm = 0.5 * (there + back);
        result.hausdorffMm = distance->GetHausdorffDistance();
        surface = decimated;
    }
    result.surface = interop::triangleMeshFromVtk(surface);
    if (result.surface.signedVolume() < 0.0) // a left-handed direction matrix turns the triangles inside out
        for (auto& triangle : result.surface.triangles)
            std::swap(triangle[1], triangle[2]);
    progress.report(1.0, localized("vsim::Progress", "surface"));
    return result;
}

void writeStl(const TriangleMesh& surface, const std::filesystem::path& file)
{
    auto writer = vtkSmartPointer<vtkSTLWriter>::New();
    writer->SetInputData(interop::toVtk(surface));
    writer->SetFileName(file.string().c_str());
    writer->SetFileTypeToBinary();
    if (writer->Write() != 1)
        throw Error("cannot write STL file", {{"file", file.string()}});
}

} // namespace vsim::mesh
