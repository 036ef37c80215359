#pragma once

// Small label-volume helpers shared by the skeleton, centerline and segmentation code.

#include "vsim/core/ImageVolume.h"

#include <array>
#include <optional>
#include <utility>

namespace vsim::imaging {

/// Inclusive index bounds of the voxels equal to `value`; nullopt when there are none.
std::optional<std::pair<std::array<int, 3>, std::array<int, 3>>> labelBounds(const LabelVolume& label,
                                                                             std::uint8_t value);

/// Distance (mm) from every voxel equal to `value` to the nearest other voxel (ITK signed Maurer distance,
/// positive inside; negative outside), on the label's grid.
RealVolume insideDistanceMm(const LabelVolume& label, std::uint8_t value);

/// The voxels equal to `value` as 0/1 in their bounding box grown by `margin` voxels, clipped to the volume;
/// `start` is the label index of the crop's voxel (0, 0, 0). Throws vsim::Error for an empty label.
struct LabelCrop
{
    LabelVolume binary;
    std::array<int, 3> start{};
};
LabelCrop cropLabel(const LabelVolume& label, std::uint8_t value, int margin);

/// The distance map of the voxels equal to `value` computed only in their bounding box grown by `margin` voxels
/// (clipped to the volume, so the volume's own border is not taken for background): `start` is the label index
/// of the map's voxel (0, 0, 0). Same values as insideDistanceMm inside the object, at a fraction of the memory.
struct CroppedDistance
{
    RealVolume distance;
    std::array<int, 3> start{};
    float at(const std::array<int, 3>& labelVoxel) const
    {
        return distance.at(labelVoxel[0] - start[0], labelVoxel[1] - start[1], labelVoxel[2] - start[2]);
    }
};
CroppedDistance croppedInsideDistanceMm(const LabelVolume& label, std::uint8_t value, int margin);

} // namespace vsim::imaging
