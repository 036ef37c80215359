#pragma once

#include "vsim/core/Error.h"
#include "vsim/core/VolumeGeometry.h"

#include <cstdint>
#include <memory>
#include <string>

namespace vsim {

/// A 3D scalar image in the patient frame. The voxel buffer is shared (copies of an ImageVolume alias the
/// same voxels) so that the ITK and VTK adapters can wrap it without copying; the buffer's owner can be
/// foreign (e.g. an ITK image kept alive by the deleter).
template <typename T>
class ImageVolume
{
public:
    using ValueType = T;

    ImageVolume() = default;
    /// Allocates a zero-filled volume; throws vsim::Error for an invalid geometry.
    explicit ImageVolume(const VolumeGeometry& geometry) : m_geometry(geometry)
    {
        geometry.validate();
        m_voxels = std::shared_ptr<T[]>(new T[geometry.voxelCount()]());
    }
    /// Adopts an existing buffer of geometry.voxelCount() values; `voxels` keeps its owner alive.
    ImageVolume(const VolumeGeometry& geometry, std::shared_ptr<T[]> voxels)
        : m_geometry(geometry), m_voxels(std::move(voxels))
    {
        geometry.validate();
        if (!m_voxels)
            throw Error("image volume adopted an empty buffer");
    }

    /// Allocates without zero-filling, for producers that write every voxel before anything reads it (decoders,
    /// resamplers): saves a pass over the memory. Throws vsim::Error for an invalid geometry.
    static ImageVolume uninitialized(const VolumeGeometry& geometry)
    {
        geometry.validate();
        return ImageVolume(geometry, std::shared_ptr<T[]>(new T[geometry.voxelCount()]));
    }

    const VolumeGeometry& geometry() const { return m_geometry; }
    bool isEmpty() const { return !m_voxels; }
    std::size_t size() const { return m_voxels ? m_geometry.voxelCount() : 0; }
    T* data() { return m_voxels.get(); }
    const T* data() const { return m_voxels.get(); }
    const std::shared_ptr<T[]>& buffer() const { return m_voxels; }

    T& at(int i, int j, int k) { return m_voxels[m_geometry.linearIndex(i, j, k)]; }
    T at(int i, int j, int k) const { return m_voxels[m_geometry.linearIndex(i, j, k)]; }

    /// A deep copy with its own buffer.
    ImageVolume clone() const
    {
        ImageVolume copy(m_geometry);
        std::copy(data(), data() + size(), copy.data());
        return copy;
    }

private:
    VolumeGeometry m_geometry;
    std::shared_ptr<T[]> m_voxels;
};

/// CT in Hounsfield units.
using CtVolume = ImageVolume<std::int16_t>;
/// Segmentation labels: 0 background, 1.. structure ids.
using LabelVolume = ImageVolume<std::uint8_t>;
/// Derived real-valued images (vesselness, distance maps, ...).
using RealVolume = ImageVolume<float>;

} // namespace vsim
