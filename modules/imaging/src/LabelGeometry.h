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

} // namespace vsim::imaging
