// The ITK and VTK adapters keep the patient-frame geometry exact (dims, spacing, origin, an oblique direction)
// both ways, and alias the voxel buffer instead of copying it.
#include "vsim/interop/ItkImage.h"
#include "vsim/interop/VtkImage.h"
#include "vsim/interop/VtkMesh.h"

#include <Eigen/Geometry>
#include <QtTest>
#include <vtkImageData.h>
#include <vtkMatrix3x3.h>
#include <vtkMatrix4x4.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>

namespace {

/// A CT-like volume with an oblique, left-handed-free direction (rotation about an arbitrary axis).
vsim::CtVolume obliqueVolume()
{
    vsim::VolumeGeometry geometry;
    geometry.dims = {7, 5, 3};
    geometry.spacing = {0.68, 0.71, 1.25};
    geometry.origin = {-171.3, -200.5, 1432.75};
    geometry.direction = Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    vsim::CtVolume volume(geometry);
    for (std::size_t v = 0; v < volume.size(); ++v)
        volume.data()[v] = static_cast<std::int16_t>(v * 7 - 100);
    return volume;
}

} // namespace

class TestAdapters : public QObject
{
    Q_OBJECT
private slots:
    void itkRoundTripKeepsGeometryAndAliasesVoxels()
    {
        const vsim::CtVolume volume = obliqueVolume();
        auto itkImage = vsim::interop::toItk(volume);
        QCOMPARE(itkImage->GetBufferPointer(), volume.data()); // zero copy
        // ITK's own index->physical mapping must agree with the core geometry (LPS, mm).
        itk::Index<3> index{{4, 3, 2}};
        itk::Point<double, 3> point;
        itkImage->TransformIndexToPhysicalPoint(index, point);
        const Eigen::Vector3d expected = volume.geometry().indexToPatient({4, 3, 2});
        for (int axis = 0; axis < 3; ++axis)
            QVERIFY(std::abs(point[axis] - expected[axis]) < 1e-9);
        QCOMPARE(itkImage->GetPixel(index), volume.at(4, 3, 2));

        const vsim::CtVolume back = vsim::interop::fromItk<std::int16_t>(itkImage.GetPointer());
        QVERIFY(back.geometry().isClose(volume.geometry(), 1e-12));
        QCOMPARE(back.data(), volume.data());
    }

    void volumeFromItkKeepsTheItkImageAlive()
    {
        vsim::CtVolume adopted;
        {
            auto image = vsim::interop::ItkImage3<std::int16_t>::New();
            itk::ImageRegion<3> region;
            region.SetSize({{4, 4, 4}});
            image->SetRegions(region);
            image->Allocate();
            image->FillBuffer(321);
            adopted = vsim::interop::fromItk<std::int16_t>(image.GetPointer());
        } // the last ITK smart pointer of the test is gone here
        QCOMPARE(adopted.at(3, 3, 3), std::int16_t(321));
    }

    void vtkRoundTripKeepsGeometryAndAliasesVoxels()
    {
        const vsim::CtVolume volume = obliqueVolume();
        vtkSmartPointer<vtkImageData> image = vsim::interop::toVtk(volume);
        QCOMPARE(image->GetScalarPointer(), static_cast<void*>(const_cast<std::int16_t*>(volume.data())));
        double point[3];
        image->TransformIndexToPhysicalPoint(4, 3, 2, point);
        const Eigen::Vector3d expected = volume.geometry().indexToPatient({4, 3, 2});
        for (int axis = 0; axis < 3; ++axis)
            QVERIFY(std::abs(point[axis] - expected[axis]) < 1e-9);
        QCOMPARE(image->GetScalarComponentAsDouble(4, 3, 2, 0), double(volume.at(4, 3, 2)));

        const vsim::CtVolume back = vsim::interop::fromVtk<std::int16_t>(image);
        QVERIFY(back.geometry().isClose(volume.geometry(), 1e-12));
        QCOMPARE(back.data(), volume.data());
        QVERIFY_THROWS_EXCEPTION(vsim::Error, vsim::interop::fromVtk<float>(image)); // wrong scalar type
    }

    void scaledIndexMatrixPlacesVoxelsInThePatientFrame()
    {
        const vsim::CtVolume volume = obliqueVolume();
        auto matrix = vsim::interop::scaledIndexToPatient(volume.geometry());
        const Eigen::Vector3d scaled = volume.geometry().spacing.cwiseProduct(Eigen::Vector3d(4, 3, 2));
        double in[4] = {scaled.x(), scaled.y(), scaled.z(), 1.0};
        double out[4];
        matrix->MultiplyPoint(in, out);
        const Eigen::Vector3d expected = volume.geometry().indexToPatient({4, 3, 2});
        for (int axis = 0; axis < 3; ++axis)
            QVERIFY(std::abs(out[axis] - expected[axis]) < 1e-9);
    }

    void meshesSurviveVtkWithTheirFields()
    {
        vsim::TetMesh tets;
        tets.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        tets.tets = {{0, 1, 2, 3}};
        tets.pointFields["displacement_mm"] = {0, 0.1, 0.2, 0.3};
        tets.cellFields["von_mises_kpa"] = {42.0};
        const vsim::TetMesh tetsBack = vsim::interop::tetMeshFromVtk(vsim::interop::toVtk(tets));
        QCOMPARE(tetsBack.tets, tets.tets);
        QCOMPARE(tetsBack.pointFields, tets.pointFields);
        QCOMPARE(tetsBack.cellFields, tets.cellFields);
        QVERIFY(std::abs(tetsBack.totalVolume() - 1.0 / 6.0) < 1e-15);

        vsim::TriangleMesh surface;
        surface.points = tets.points;
        surface.triangles = {{0, 2, 1}, {0, 1, 3}};
        const vsim::TriangleMesh surfaceBack = vsim::interop::triangleMeshFromVtk(vsim::interop::toVtk(surface));
        QCOMPARE(surfaceBack.triangles, surface.triangles);
        QCOMPARE(surfaceBack.points.size(), surface.points.size());
    }
};

QTEST_APPLESS_MAIN(TestAdapters)
#include "tst_adapters.moc"
