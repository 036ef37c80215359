#include "vsim/core/DistanceTransform.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace vsim {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// One line: d[q] = min_p ((q - p)^2 h^2 + f[p]) over the sites p with a finite f.
void transformLine(const double* f, double* d, int n, double h, std::vector<int>& v, std::vector<double>& z)
{
    int k = -1;
    for (int q = 0; q < n; ++q)
    {
        if (!std::isfinite(f[q]))
            continue;
        while (true)
        {
            if (k < 0)
            {
                k = 0, v[0] = q, z[0] = -kInfinity, z[1] = kInfinity;
                break;
            }
            const int p = v[std::size_t(k)];
            const double qh = q * h, ph = p * h;
            const double s = ((f[q] + qh * qh) - (f[p] + ph * ph)) / (2.0 * (qh - ph)); // where the parabolas cross
            if (s <= z[std::size_t(k)])
            {
                --k;
                continue;
            }
            ++k, v[std::size_t(k)] = q, z[std::size_t(k)] = s, z[std::size_t(k) + 1] = kInfinity;
            break;
        }
    }
    if (k < 0)
    {
        for (int q = 0; q < n; ++q)
            d[q] = kInfinity;
        return;
    }
    k = 0;
    for (int q = 0; q < n; ++q)
    {
        const double x = q * h;
        while (z[std::size_t(k) + 1] < x)
            ++k;
        const double offset = x - v[std::size_t(k)] * h;
        d[q] = offset * offset + f[v[std::size_t(k)]];
    }
}

} // namespace

void squaredDistanceTransform(std::vector<double>& values, const std::array<int, 3>& dims, const std::array<double, 3>& spacingMm)
{
    for (double& value : values)
        value = value == 0.0 ? 0.0 : kInfinity;
    const std::array<std::size_t, 3> stride{1, std::size_t(dims[0]), std::size_t(dims[0]) * std::size_t(dims[1])};
    const std::size_t longest = std::size_t(std::max(dims[0], std::max(dims[1], dims[2])));
    std::vector<double> line(longest), out(longest), z(longest + 1);
    std::vector<int> v(longest);
    for (int axis = 0; axis < 3; ++axis)
    {
        const int a = (axis + 1) % 3, b = (axis + 2) % 3;
        for (int j = 0; j < dims[std::size_t(b)]; ++j)
            for (int i = 0; i < dims[std::size_t(a)]; ++i)
            {
                const std::size_t start = std::size_t(i) * stride[std::size_t(a)] + std::size_t(j) * stride[std::size_t(b)];
                for (int q = 0; q < dims[std::size_t(axis)]; ++q)
                    line[std::size_t(q)] = values[start + std::size_t(q) * stride[std::size_t(axis)]];
                transformLine(line.data(), out.data(), dims[std::size_t(axis)], spacingMm[std::size_t(axis)], v, z);
                for (int q = 0; q < dims[std::size_t(axis)]; ++q)
                    values[start + std::size_t(q) * stride[std::size_t(axis)]] = out[std::size_t(q)];
            }
    }
}

} // namespace vsim
