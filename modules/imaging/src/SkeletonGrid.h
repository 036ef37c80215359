#pragma once

// A binary voxel grid cropped to an object's bounding box with one voxel of background padding, so that every
// object voxel has all 26 neighbours inside the array: the working space of thinning, VDSM and graph tracing.

#include "vsim/core/ImageVolume.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace vsim::imaging {

struct SkeletonGrid
{
    std::array<int, 3> dims{};        ///< padded size
    std::array<int, 3> start{};       ///< label index of padded voxel (0, 0, 0) (may be -1)
    std::vector<std::uint8_t> voxels; ///< 1 = object
    std::array<std::ptrdiff_t, 26> neighbour{}; ///< linear offsets of the 26 neighbours
    std::array<std::array<int, 3>, 26> step{};  ///< their (di, dj, dk)

    /// Crops the voxels equal to `value`; throws vsim::Error when there are none.
    static SkeletonGrid fromLabel(const LabelVolume& label, std::uint8_t value);
    /// The voxels of `label` equal to `value` on this grid (the crop and padding of this grid).
    std::vector<std::uint8_t> maskOf(const LabelVolume& label, std::uint8_t value) const;
    /// The object voxels pasted into a label volume of `geometry` (1 = object).
    LabelVolume toLabel(const VolumeGeometry& geometry) const;

    std::array<int, 3> voxelOf(std::size_t index) const;  ///< in label indices
    std::size_t indexOf(const std::array<int, 3>& labelVoxel) const;
    /// The 26 neighbours as bits (bit (di+1) + 3 (dj+1) + 9 (dk+1); the voxel's own bit 13 is 0).
    std::uint32_t neighbourhood(std::size_t index) const;
    /// Number of object voxels among the 26 neighbours.
    int degree(std::size_t index) const;
    /// Bertrand & Malandain: one 26-connected object component in N26 minus the voxel, and one 6-connected
    /// background component in N18 that is 6-adjacent to it.
    bool isSimple(std::size_t index) const { return isSimpleNeighbourhood(neighbourhood(index)); }
    static bool isSimpleNeighbourhood(std::uint32_t neighbours);
};

} // namespace vsim::imaging
