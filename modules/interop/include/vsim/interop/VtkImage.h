#pragma once

// Edge adapter between vsim::ImageVolume and vtkImageData. Include it only from .cpp files.

#include "vsim/core/ImageVolume.h"

#include <vtkSmartPointer.h>

class vtkImageData;
class vtkMatrix4x4;

namespace vsim::interop {

/// Returns a vtkImageData whose point scalars alias the volume's voxels (no copy), with dims, spacing, origin
/// and direction matrix of the volume. The VTK image borrows the buffer: keep `volume` alive while it is used.
template <typename T>
vtkSmartPointer<vtkImageData> toVtk(const ImageVolume<T>& volume);

/// Returns a volume aliasing the image's point scalars (no copy); the scalar array is kept alive by the volume.
/// Throws vsim::Error when the image has no scalars, more than one component, or another scalar type than T.
template <typename T>
ImageVolume<T> fromVtk(vtkImageData* image);

/// The 4x4 matrix that maps VTK "scaled index" coordinates (index * spacing, origin 0, identity direction) to
/// the LPS patient frame in mm: the user matrix that places an axis-aligned VTK prop in patient space.
vtkSmartPointer<vtkMatrix4x4> scaledIndexToPatient(const VolumeGeometry& geometry);

} // namespace vsim::interop
