#pragma once

// Edge adapter between vsim::ImageVolume and itk::Image. Include it only from .cpp files: ITK types stay out
// of the headers that modules exchange (ARCHITECTURE.md, "Data types at module boundaries").

#include "vsim/core/Error.h"
#include "vsim/core/ImageVolume.h"

#include <itkImage.h>

namespace vsim::interop {

template <typename T>
using ItkImage3 = itk::Image<T, 3>;

/// Returns an itk::Image that aliases the volume's voxels (no copy). The ITK image borrows the buffer: keep
/// `volume` (or a copy of it) alive while the ITK image is used. Writes through ITK are seen by the volume.
template <typename T>
typename ItkImage3<T>::Pointer toItk(const ImageVolume<T>& volume)
{
    const VolumeGeometry& geometry = volume.geometry();
    auto image = ItkImage3<T>::New();
    typename ItkImage3<T>::RegionType region;
    typename ItkImage3<T>::SpacingType spacing;
    typename ItkImage3<T>::PointType origin;
    typename ItkImage3<T>::DirectionType direction;
    for (unsigned axis = 0; axis < 3; ++axis)
    {
        region.SetIndex(axis, 0);
        region.SetSize(axis, static_cast<itk::SizeValueType>(geometry.dims[axis]));
        spacing[axis] = geometry.spacing[axis];
        origin[axis] = geometry.origin[axis];
        for (unsigned column = 0; column < 3; ++column)
            direction[axis][column] = geometry.direction(axis, column);
    }
    image->SetRegions(region);
    image->SetSpacing(spacing);
    image->SetOrigin(origin);
    image->SetDirection(direction);
    image->GetPixelContainer()->SetImportPointer(const_cast<T*>(volume.data()), volume.size(), false);
    return image;
}

/// Returns the geometry of an ITK image (its largest possible region).
template <typename T>
VolumeGeometry geometryOf(const ItkImage3<T>& image)
{
    VolumeGeometry geometry;
    const auto size = image.GetLargestPossibleRegion().GetSize();
    for (unsigned axis = 0; axis < 3; ++axis)
    {
        geometry.dims[axis] = static_cast<int>(size[axis]);
        geometry.spacing[axis] = image.GetSpacing()[axis];
        geometry.origin[axis] = image.GetOrigin()[axis];
        for (unsigned column = 0; column < 3; ++column)
            geometry.direction(axis, column) = image.GetDirection()[axis][column];
    }
    return geometry;
}

/// Returns a volume that aliases the ITK image's voxels (no copy) and keeps the ITK image alive.
/// Throws vsim::Error when the buffered region is not the whole image starting at index 0.
template <typename T>
ImageVolume<T> fromItk(ItkImage3<T>* image)
{
    if (!image || image->GetBufferedRegion() != image->GetLargestPossibleRegion() ||
        image->GetLargestPossibleRegion().GetIndex() != typename ItkImage3<T>::IndexType{{0, 0, 0}})
        throw Error("ITK image is not fully buffered from index 0; cannot adopt it");
    typename ItkImage3<T>::Pointer keepAlive = image;
    std::shared_ptr<T[]> voxels(image->GetBufferPointer(), [keepAlive](T*) {});
    return ImageVolume<T>(geometryOf(*image), std::move(voxels));
}

} // namespace vsim::interop
