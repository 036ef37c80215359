#include "GuidedHelpers.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace vsim::imaging::detail {

std::string mmText(const Eigen::Vector3d& p)
{
    char text[96];
    std::snprintf(text, sizeof text, "(%.1f, %.1f, %.1f) mm", p.x(), p.y(), p.z());
    return text;
}

double smoothedHu(const CtVolume& ct, int i, int j, int k)
{
    const VolumeGeometry& g = ct.geometry();
    double sum = 0.0, weights = 0.0;
    for (int dk = -1; dk <= 1; ++dk)
        for (int dj = -1; dj <= 1; ++dj)
            for (int di = -1; di <= 1; ++di)
            {
                const double w = double((2 - std::abs(di)) * (2 - std::abs(dj)) * (2 - std::abs(dk)));
                sum += w * ct.at(std::clamp(i + di, 0, g.dims[0] - 1), std::clamp(j + dj, 0, g.dims[1] - 1),
                                 std::clamp(k + dk, 0, g.dims[2] - 1));
                weights += w;
            }
    return sum / weights;
}

} // namespace vsim::imaging::detail
