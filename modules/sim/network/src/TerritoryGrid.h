#pragma once

// What the territories and the lesions both read of the liver's voxels (Territories.cpp, Lesions.cpp).

#include "vsim/sim/network/Territories.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace vsim::sim::network::detail {

constexpr double kSampleMm = 0.5; ///< spacing of the points sampled along centerlines

/// Points along a polyline no further apart than `step` (mm), its vertices included.
inline std::vector<Eigen::Vector3d> sampled(const std::vector<Eigen::Vector3d>& path, double step)
{
    std::vector<Eigen::Vector3d> points;
    for (std::size_t i = 0; i + 1 < path.size(); ++i)
    {
        const int pieces = std::max(1, int(std::ceil((path[i + 1] - path[i]).norm() / step)));
        for (int k = 0; k < pieces; ++k)
            points.push_back(path[i] + (path[i + 1] - path[i]) * (double(k) / pieces));
    }
    if (!path.empty())
        points.push_back(path.back());
    return points;
}

/// The liver voxel (an index into territories.voxels) of a linear index; -1 when it is not liver.
inline long liverVoxel(const LiverTerritories& t, std::size_t linear)
{
    const auto found = std::lower_bound(t.voxels.begin(), t.voxels.end(), linear);
    return found != t.voxels.end() && *found == linear ? long(found - t.voxels.begin()) : -1;
}

/// The linear index of the voxel nearest a point; -1 off the grid.
inline long nearestLinear(const VolumeGeometry& g, const Eigen::Vector3d& pointMm)
{
    const Eigen::Vector3d index = g.patientToIndex(pointMm);
    const int i = int(std::lround(index.x())), j = int(std::lround(index.y())), k = int(std::lround(index.z()));
    return g.contains(i, j, k) ? long(g.linearIndex(i, j, k)) : -1;
}

} // namespace vsim::sim::network::detail
