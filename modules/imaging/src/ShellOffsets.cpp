#include "ShellOffsets.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vsim::imaging::detail {

std::vector<std::array<int, 3>> shellOffsets(const Eigen::Vector3d& spacing, double innerMm, double outerMm)
{
    std::vector<std::array<int, 3>> offsets;
    const int ri = int(std::ceil(outerMm / spacing.x())), rj = int(std::ceil(outerMm / spacing.y())),
              rk = int(std::ceil(outerMm / spacing.z()));
    for (int dk = -rk; dk <= rk; ++dk)
        for (int dj = -rj; dj <= rj; ++dj)
            for (int di = -ri; di <= ri; ++di)
            {
                const double d = Eigen::Vector3d(di * spacing.x(), dj * spacing.y(), dk * spacing.z()).norm();
                if (d >= innerMm && d <= outerMm)
                    offsets.push_back({di, dj, dk});
            }
    return offsets;
}

ShellMedians::ShellMedians(const CtVolume& ct, std::size_t boxVoxels, double innerMm, double outerMm)
    : m_ct(ct), m_shell(shellOffsets(ct.geometry().spacing, innerMm, outerMm)),
      m_cache(boxVoxels, std::numeric_limits<float>::quiet_NaN())
{
}

float ShellMedians::at(std::size_t b, int i, int j, int k)
{
    float& cached = m_cache[b];
    if (std::isnan(cached))
    {
        const VolumeGeometry& g = m_ct.geometry();
        std::vector<float> values;
        values.reserve(m_shell.size());
        for (const auto& [di, dj, dk] : m_shell)
            if (g.contains(i + di, j + dj, k + dk))
                values.push_back(float(m_ct.at(i + di, j + dj, k + dk)));
        std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(values.size() / 2), values.end());
        cached = values.empty() ? 0.0f : values[values.size() / 2];
    }
    return cached;
}

} // namespace vsim::imaging::detail
