#pragma once

// The guided segmentation's work box (WaveFront.cpp): the sub-grid of the CT its fronts can reach.

#include "WaveFront.h"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace vsim::imaging::detail {

/// The work box: a sub-grid of the CT with its own linear indices.
struct WorkBox
{
    std::array<int, 3> low{0, 0, 0}, size{0, 0, 0};
    std::size_t count() const { return std::size_t(size[0]) * std::size_t(size[1]) * std::size_t(size[2]); }
    std::uint32_t index(int i, int j, int k) const
    {
        return std::uint32_t((i - low[0]) + size[0] * ((j - low[1]) + size[1] * (k - low[2])));
    }
    std::array<int, 3> voxel(std::uint32_t b) const
    {
        const int i = int(b % std::uint32_t(size[0])), j = int((b / std::uint32_t(size[0])) % std::uint32_t(size[1]));
        const int k = int(b / (std::uint32_t(size[0]) * std::uint32_t(size[1])));
        return {i + low[0], j + low[1], k + low[2]};
    }
};

inline WorkBox workBox(const CtVolume& ct, const std::vector<FrontSeed>& seeds)
{
    const VolumeGeometry& g = ct.geometry();
    Eigen::Vector3d low = Eigen::Vector3d::Constant(1e300), high = Eigen::Vector3d::Constant(-1e300);
    for (const FrontSeed& seed : seeds)
    {
        const double reach = std::min(seed.maxLengthMm, 1e5);
        for (int corner = 0; corner < 8; ++corner)
        {
            const Eigen::Vector3d offset((corner & 1) ? reach : -reach, (corner & 2) ? reach : -reach, (corner & 4) ? reach : -reach);
            const Eigen::Vector3d index = g.patientToIndex(seed.pointMm + offset);
            low = low.cwiseMin(index), high = high.cwiseMax(index);
        }
    }
    WorkBox box;
    for (int a = 0; a < 3; ++a)
    {
        box.low[a] = std::clamp(int(std::floor(low[a])), 0, g.dims[a] - 1);
        box.size[a] = std::clamp(int(std::ceil(high[a])), 0, g.dims[a] - 1) - box.low[a] + 1;
    }
    return box;
}

} // namespace vsim::imaging::detail
