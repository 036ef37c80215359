#include "MaskOps.h"

#include "vsim/core/DistanceTransform.h"

#include <cstdlib>

namespace vsim::imaging {

std::size_t floodFill(const Dims& dims, const std::vector<std::size_t>& seeds,
                      const std::function<bool(std::size_t)>& accept, std::vector<std::uint8_t>& out, bool faceOnly,
                      std::vector<std::size_t>* members)
{
    const std::size_t nx = std::size_t(dims[0]), ny = std::size_t(dims[1]), nz = std::size_t(dims[2]);
    const std::size_t slice = nx * ny;
    std::vector<std::size_t> stack;
    std::size_t added = 0;
    for (std::size_t seed : seeds)
        if (seed < out.size() && !out[seed] && accept(seed))
        {
            out[seed] = 1;
            stack.push_back(seed);
            ++added;
        }
    while (!stack.empty())
    {
        const std::size_t index = stack.back();
        stack.pop_back();
        if (members)
            members->push_back(index);
        const std::size_t k = index / slice, j = (index % slice) / nx, i = index % nx;
        for (int dk = -1; dk <= 1; ++dk)
            for (int dj = -1; dj <= 1; ++dj)
                for (int di = -1; di <= 1; ++di)
                {
                    const int manhattan = std::abs(di) + std::abs(dj) + std::abs(dk);
                    if (manhattan == 0 || (faceOnly && manhattan > 1))
                        continue;
                    if ((di < 0 && i == 0) || (di > 0 && i + 1 == nx) || (dj < 0 && j == 0) || (dj > 0 && j + 1 == ny) ||
                        (dk < 0 && k == 0) || (dk > 0 && k + 1 == nz))
                        continue;
                    const std::size_t next = index + std::size_t(std::ptrdiff_t(di) + std::ptrdiff_t(dj) * std::ptrdiff_t(nx) +
                                                                 std::ptrdiff_t(dk) * std::ptrdiff_t(slice));
                    if (out[next] || !accept(next))
                        continue;
                    out[next] = 1;
                    stack.push_back(next);
                    ++added;
                }
    }
    return added;
}

namespace {

template <bool Erode>
std::vector<std::uint8_t> morph6(const Dims& dims, const std::vector<std::uint8_t>& mask)
{
    const std::size_t nx = std::size_t(dims[0]), ny = std::size_t(dims[1]), nz = std::size_t(dims[2]);
    const std::size_t slice = nx * ny;
    std::vector<std::uint8_t> out(mask.size(), 0);
    for (std::size_t k = 0; k < nz; ++k)
        for (std::size_t j = 0; j < ny; ++j)
        {
            const std::size_t row = k * slice + j * nx;
            for (std::size_t i = 0; i < nx; ++i)
            {
                const std::size_t index = row + i;
                auto at = [&](bool inside, std::size_t neighbour) { return inside ? mask[neighbour] : std::uint8_t(0); };
                const std::uint8_t neighbours[6] = {
                    at(i > 0, index - 1),          at(i + 1 < nx, index + 1),          at(j > 0, index - nx),
                    at(j + 1 < ny, index + nx),    at(k > 0, index - slice),           at(k + 1 < nz, index + slice)};
                if constexpr (Erode)
                {
                    std::uint8_t all = mask[index];
                    for (std::uint8_t n : neighbours)
                        all &= n;
                    out[index] = all;
                }
                else
                {
                    std::uint8_t any = mask[index];
                    for (std::uint8_t n : neighbours)
                        any |= n;
                    out[index] = any;
                }
            }
        }
    return out;
}

} // namespace

std::vector<std::uint8_t> erode6(const Dims& dims, const std::vector<std::uint8_t>& mask)
{
    return morph6<true>(dims, mask);
}

std::vector<std::uint8_t> dilate6(const Dims& dims, const std::vector<std::uint8_t>& mask)
{
    return morph6<false>(dims, mask);
}

std::vector<std::uint8_t> withCavitiesFilled(const Dims& dims, const std::vector<std::uint8_t>& mask)
{
    std::vector<std::size_t> border;
    for (int k = 0; k < dims[2]; ++k)
        for (int j = 0; j < dims[1]; ++j)
            for (int i = 0; i < dims[0]; ++i)
            {
                const std::size_t v = std::size_t(i) + std::size_t(dims[0]) * (std::size_t(j) + std::size_t(dims[1]) * std::size_t(k));
                if ((i == 0 || j == 0 || k == 0 || i == dims[0] - 1 || j == dims[1] - 1 || k == dims[2] - 1) && !mask[v])
                    border.push_back(v);
            }
    std::vector<std::uint8_t> outside(mask.size(), 0);
    floodFill(dims, border, [&](std::size_t v) { return mask[v] == 0; }, outside, true);
    for (std::uint8_t& v : outside)
        v = v ? 0 : 1;
    return outside;
}

std::vector<std::uint8_t> dilateBall(const Dims& dims, const std::vector<std::uint8_t>& mask,
                                     const std::array<double, 3>& spacingMm, double radiusMm)
{
    std::vector<double> distance(mask.size());
    for (std::size_t i = 0; i < mask.size(); ++i)
        distance[i] = mask[i] ? 0.0 : 1.0;
    squaredDistanceTransform(distance, dims, spacingMm);
    std::vector<std::uint8_t> out(mask.size());
    for (std::size_t i = 0; i < mask.size(); ++i)
        out[i] = distance[i] <= radiusMm * radiusMm ? 1 : 0;
    return out;
}

std::vector<std::uint8_t> erodeBall(const Dims& dims, const std::vector<std::uint8_t>& mask,
                                    const std::array<double, 3>& spacingMm, double radiusMm)
{
    std::vector<std::uint8_t> outside(mask.size());
    for (std::size_t i = 0; i < mask.size(); ++i)
        outside[i] = mask[i] ? 0 : 1;
    std::vector<std::uint8_t> grown = dilateBall(dims, outside, spacingMm, radiusMm);
    for (std::size_t i = 0; i < mask.size(); ++i)
        grown[i] = mask[i] && !grown[i] ? 1 : 0;
    return grown;
}

} // namespace vsim::imaging
