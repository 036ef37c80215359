#include "vsim/interop/VtkImage.h"

#include "vsim/core/Error.h"

#include <vtkAOSDataArrayTemplate.h>
#include <vtkImageData.h>
#include <vtkMatrix3x3.h>
#include <vtkMatrix4x4.h>
#include <vtkPointData.h>
#include <vtkType.h>

#include <cstdint>

namespace vsim::interop {

template <typename T>
vtkSmartPointer<vtkImageData> toVtk(const ImageVolume<T>& volume)
{
    const VolumeGeometry& geometry = volume.geometry();
    auto image = vtkSmartPointer<vtkImageData>::New();
    image->SetDimensions(geometry.dims[0], geometry.dims[1], geometry.dims[2]);
    image->SetSpacing(geometry.spacing.data());
    image->SetOrigin(geometry.origin.data());
    double direction[9];
    for (int row = 0; row < 3; ++row)
        for (int column = 0; column < 3; ++column)
            direction[3 * row + column] = geometry.direction(row, column);
    image->SetDirectionMatrix(direction);

    auto scalars = vtkSmartPointer<vtkAOSDataArrayTemplate<T>>::New();
    scalars->SetName("scalars");
    scalars->SetNumberOfComponents(1);
    // save = 1: VTK never frees the buffer, the ImageVolume owns it.
    scalars->SetArray(const_cast<T*>(volume.data()), static_cast<vtkIdType>(volume.size()), 1);
    image->GetPointData()->SetScalars(scalars);
    return image;
}

template <typename T>
ImageVolume<T> fromVtk(vtkImageData* image)
{
    if (!image || !image->GetPointData()->GetScalars())
        throw Error("VTK image has no scalars");
    auto* scalars = vtkAOSDataArrayTemplate<T>::FastDownCast(image->GetPointData()->GetScalars());
    if (!scalars || scalars->GetNumberOfComponents() != 1)
        throw Error("VTK image scalars are not single-component of the expected type",
                    {{"vtk type", image->GetPointData()->GetScalars()->GetDataTypeAsString()}});
    VolumeGeometry geometry;
    int dims[3];
    image->GetDimensions(dims);
    for (int axis = 0; axis < 3; ++axis)
    {
        geometry.dims[axis] = dims[axis];
        geometry.spacing[axis] = image->GetSpacing()[axis];
        geometry.origin[axis] = image->GetOrigin()[axis];
        for (int column = 0; column < 3; ++column)
            geometry.direction(axis, column) = image->GetDirectionMatrix()->GetElement(axis, column);
    }
    vtkSmartPointer<vtkAOSDataArrayTemplate<T>> keepAlive = scalars;
    std::shared_ptr<T[]> voxels(scalars->GetPointer(0), [keepAlive](T*) {});
    return ImageVolume<T>(geometry, std::move(voxels));
}

vtkSmartPointer<vtkMatrix4x4> scaledIndexToPatient(const VolumeGeometry& geometry)
{
    auto matrix = vtkSmartPointer<vtkMatrix4x4>::New();
    for (int row = 0; row < 3; ++row)
    {
        for (int column = 0; column < 3; ++column)
            matrix->SetElement(row, column, geometry.direction(row, column));
        matrix->SetElement(row, 3, geometry.origin[row]);
    }
    return matrix;
}

template vtkSmartPointer<vtkImageData> toVtk(const ImageVolume<std::int16_t>&);
template vtkSmartPointer<vtkImageData> toVtk(const ImageVolume<std::uint8_t>&);
template vtkSmartPointer<vtkImageData> toVtk(const ImageVolume<float>&);
template ImageVolume<std::int16_t> fromVtk(vtkImageData*);
template ImageVolume<std::uint8_t> fromVtk(vtkImageData*);
template ImageVolume<float> fromVtk(vtkImageData*);

} // namespace vsim::interop
