#pragma once

// The SPH tests' particle arrangements: the sites of a simple cubic lattice, counts.x() x counts.y() x counts.z()
// sites `spacing` apart (m) from the origin, each moved by a uniform random offset of up to `jitter` spacings per axis
// (a seeded std::mt19937; 0: the lattice itself), x fastest.

#include <Eigen/Core>

#include <random>
#include <vector>

namespace vsim::test {

inline std::vector<Eigen::Vector3d> jitteredLattice(const Eigen::Vector3i& counts, double spacing, double jitter,
                                                    unsigned seed)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> offset(-jitter, jitter);
    std::vector<Eigen::Vector3d> sites;
    for (int k = 0; k < counts.z(); ++k)
        for (int j = 0; j < counts.y(); ++j)
            for (int i = 0; i < counts.x(); ++i)
                sites.push_back(spacing * (Eigen::Vector3d(i, j, k) +
                                           Eigen::Vector3d(offset(random), offset(random), offset(random))));
    return sites;
}

} // namespace vsim::test
