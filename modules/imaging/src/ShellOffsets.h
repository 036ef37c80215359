#pragma once

// Voxel offsets of a spherical shell, and the lazily computed median HU of such a shell around voxels of a box: the
// background beside a vessel edge (LocalHalfLevel.h) and beside a thin vessel's voxel (WaveFront.cpp).

#include "vsim/core/ImageVolume.h"

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <vector>

namespace vsim::imaging::detail {

/// Offsets (voxels) of the voxel centres between two distances (mm) from a voxel, on a grid of `spacing`.
std::vector<std::array<int, 3>> shellOffsets(const Eigen::Vector3d& spacing, double innerMm, double outerMm);

/// The median raw HU of the shell between innerMm and outerMm around a voxel, computed once per box index.
class ShellMedians
{
public:
    ShellMedians(const CtVolume& ct, std::size_t boxVoxels, double innerMm, double outerMm);
    /// At CT voxel (i, j, k), whose box index is `b`.
    float at(std::size_t b, int i, int j, int k);

private:
    const CtVolume& m_ct;
    std::vector<std::array<int, 3>> m_shell;
    std::vector<float> m_cache;
};

} // namespace vsim::imaging::detail
