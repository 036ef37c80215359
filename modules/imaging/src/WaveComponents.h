#pragma once

// The cross-sections of the guided segmentation's waves (WaveFront.cpp): each wave's 26-connected pieces, linked to
// the pieces they grew from, and the cross-section the leak test reads from them.

#include <algorithm>
#include <cstdint>
#include <vector>

namespace vsim::imaging::detail {

struct WaveComponent
{
    int parent = -1;
    int seed = 0;
    std::size_t wave = 0;
    double areaMm2 = 0.0; ///< voxels x voxel volume / wave width
    bool branch = false;
    double branchStartMm = 0.0;
    double trunkAreaMm2 = 0.0; ///< median cross-section of the trunk this component belongs to or left
    bool blocked = false;
    bool side = false; ///< split off as the smaller part while its parent went on elsewhere
    std::vector<int> children;
    std::vector<std::uint32_t> voxels;
};

/// The cross-section (mm2) of component `id` averaged with its ancestors' over `waves` waves: on voxels thicker than
/// a wave, consecutive waves alternately hold one voxel layer and none, and `waves` = the waves a layer spans reads
/// the vessel's cross-section instead of that alternation (1 where voxels are thinner than a wave: its own area).
inline double averagedAreaMm2(const std::vector<WaveComponent>& components, int id, std::size_t waves)
{
    double sum = 0.0;
    std::size_t n = 0;
    for (int a = id; a >= 0 && n < waves; a = components[std::size_t(a)].parent, ++n)
        sum += components[std::size_t(a)].areaMm2;
    return sum / double(std::max<std::size_t>(n, 1));
}

} // namespace vsim::imaging::detail
