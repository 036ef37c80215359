#pragma once

// Plain loops over binary masks on a voxel grid (i fastest): flood fill, 6-neighbour and ball erosion and dilation. They
// run on whole CT volumes, where ITK's generic filters would first need float or label copies of them.

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

namespace vsim::imaging {

using Dims = std::array<int, 3>;

/// Grows from `seeds` (linear indices) through voxels where `accept(index)` holds, 26-connected (6-connected
/// when `faceOnly`), setting them to 1 in `out` (same size as the grid; voxels already 1 are not revisited).
/// Returns the number of voxels added; appends them to `members` when given.
std::size_t floodFill(const Dims& dims, const std::vector<std::size_t>& seeds,
                      const std::function<bool(std::size_t)>& accept, std::vector<std::uint8_t>& out,
                      bool faceOnly = false, std::vector<std::size_t>* members = nullptr);

/// One step of 6-neighbour erosion: a voxel stays 1 when it and its 6 face neighbours are 1 (border voxels go).
std::vector<std::uint8_t> erode6(const Dims& dims, const std::vector<std::uint8_t>& mask);
/// One step of 6-neighbour dilation.
std::vector<std::uint8_t> dilate6(const Dims& dims, const std::vector<std::uint8_t>& mask);

/// The mask with its enclosed cavities filled: every voxel the grid's border cannot reach (6-connected) without
/// crossing the mask.
std::vector<std::uint8_t> withCavitiesFilled(const Dims& dims, const std::vector<std::uint8_t>& mask);

/// Erosion and dilation by a ball of `radiusMm` (exact Euclidean distances, anisotropic spacing): a voxel stays in
/// the erosion when no voxel outside the mask lies within the radius, and joins the dilation when one inside does.
std::vector<std::uint8_t> erodeBall(const Dims& dims, const std::vector<std::uint8_t>& mask,
                                    const std::array<double, 3>& spacingMm, double radiusMm);
std::vector<std::uint8_t> dilateBall(const Dims& dims, const std::vector<std::uint8_t>& mask,
                                     const std::array<double, 3>& spacingMm, double radiusMm);

} // namespace vsim::imaging
