#include "SkeletonGrid.h"

#include "LabelGeometry.h"

#include "vsim/core/Error.h"

#include <algorithm>
#include <cstdlib>

namespace vsim::imaging {
namespace {

constexpr int kCentre = 13; // bit (dx+1) + 3 (dy+1) + 9 (dz+1) of the voxel itself

/// Bit masks over the 3 x 3 x 3 neighbourhood: 26- and 6-adjacency of each position, N18, the six faces.
struct LocalTables
{
    std::array<std::uint32_t, 27> adjacent26{};
    std::array<std::uint32_t, 27> adjacent6{};
    std::uint32_t n18 = 0;
    std::uint32_t faces = 0;

    LocalTables()
    {
        auto coordinates = [](int l) { return std::array<int, 3>{l % 3 - 1, (l / 3) % 3 - 1, l / 9 - 1}; };
        for (int a = 0; a < 27; ++a)
        {
            const auto ca = coordinates(a);
            const int fromCentre = std::abs(ca[0]) + std::abs(ca[1]) + std::abs(ca[2]);
            if (fromCentre >= 1 && fromCentre <= 2)
                n18 |= 1u << a;
            if (fromCentre == 1)
                faces |= 1u << a;
            for (int b = 0; b < 27; ++b)
            {
                const auto cb = coordinates(b);
                const int dx = std::abs(ca[0] - cb[0]), dy = std::abs(ca[1] - cb[1]), dz = std::abs(ca[2] - cb[2]);
                if (a == b || std::max({dx, dy, dz}) > 1)
                    continue;
                adjacent26[std::size_t(a)] |= 1u << b;
                if (dx + dy + dz == 1)
                    adjacent6[std::size_t(a)] |= 1u << b;
            }
        }
    }
};

const LocalTables& tables()
{
    static const LocalTables instance;
    return instance;
}

/// The component of `start` (one bit) within `within` under the adjacency masks.
std::uint32_t componentOf(std::uint32_t start, std::uint32_t within, const std::array<std::uint32_t, 27>& adjacency)
{
    std::uint32_t component = start, frontier = start;
    while (frontier)
    {
        std::uint32_t grown = 0;
        for (std::uint32_t bits = frontier; bits; bits &= bits - 1)
            grown |= adjacency[std::size_t(__builtin_ctz(bits))];
        frontier = grown & within & ~component;
        component |= frontier;
    }
    return component;
}

} // namespace

SkeletonGrid SkeletonGrid::fromLabel(const LabelVolume& label, std::uint8_t value)
{
    const auto bounds = labelBounds(label, value);
    if (!bounds)
        throw Error("the label is empty: segment the vessels first");
    const auto& [low, high] = *bounds;
    SkeletonGrid grid;
    for (int a = 0; a < 3; ++a)
    {
        grid.start[a] = low[a] - 1;
        grid.dims[a] = high[a] - low[a] + 3;
    }
    grid.voxels.assign(std::size_t(grid.dims[0]) * grid.dims[1] * grid.dims[2], 0);
    for (int k = low[2]; k <= high[2]; ++k)
        for (int j = low[1]; j <= high[1]; ++j)
            for (int i = low[0]; i <= high[0]; ++i)
                if (label.at(i, j, k) == value)
                    grid.voxels[grid.indexOf({i, j, k})] = 1;
    int n = 0;
    for (int dk = -1; dk <= 1; ++dk)
        for (int dj = -1; dj <= 1; ++dj)
            for (int di = -1; di <= 1; ++di)
                if (di || dj || dk)
                {
                    grid.step[std::size_t(n)] = {di, dj, dk};
                    grid.neighbour[std::size_t(n++)] =
                        std::ptrdiff_t(di) + std::ptrdiff_t(grid.dims[0]) * (dj + std::ptrdiff_t(grid.dims[1]) * dk);
                }
    return grid;
}

std::vector<std::uint8_t> SkeletonGrid::maskOf(const LabelVolume& label, std::uint8_t value) const
{
    std::vector<std::uint8_t> mask(voxels.size(), 0);
    for (std::size_t index = 0; index < voxels.size(); ++index)
    {
        const auto v = voxelOf(index);
        mask[index] = label.geometry().contains(v[0], v[1], v[2]) && label.at(v[0], v[1], v[2]) == value;
    }
    return mask;
}

LabelVolume SkeletonGrid::toLabel(const VolumeGeometry& geometry) const
{
    LabelVolume label(geometry);
    for (std::size_t index = 0; index < voxels.size(); ++index)
        if (voxels[index])
        {
            const auto v = voxelOf(index);
            label.at(v[0], v[1], v[2]) = 1;
        }
    return label;
}

std::array<int, 3> SkeletonGrid::voxelOf(std::size_t index) const
{
    const std::size_t nx = std::size_t(dims[0]), slice = nx * std::size_t(dims[1]);
    return {int(index % nx) + start[0], int((index % slice) / nx) + start[1], int(index / slice) + start[2]};
}

std::size_t SkeletonGrid::indexOf(const std::array<int, 3>& v) const
{
    return std::size_t(v[0] - start[0]) +
           std::size_t(dims[0]) * (std::size_t(v[1] - start[1]) + std::size_t(dims[1]) * std::size_t(v[2] - start[2]));
}

std::uint32_t SkeletonGrid::neighbourhood(std::size_t index) const
{
    std::uint32_t bits = 0;
    for (std::size_t n = 0; n < 26; ++n)
        if (voxels[std::size_t(std::ptrdiff_t(index) + neighbour[n])])
            bits |= 1u << ((step[n][0] + 1) + 3 * (step[n][1] + 1) + 9 * (step[n][2] + 1));
    return bits;
}

int SkeletonGrid::degree(std::size_t index) const
{
    return __builtin_popcount(neighbourhood(index));
}

bool SkeletonGrid::isSimpleNeighbourhood(std::uint32_t neighbours)
{
    const LocalTables& t = tables();
    // One 26-connected object component among the 26 neighbours.
    const std::uint32_t object = neighbours & ~(1u << kCentre);
    if (!object || componentOf(object & (~object + 1), object, t.adjacent26) != object)
        return false;
    // One 6-connected background component in N18 that touches a face neighbour.
    const std::uint32_t background = ~neighbours & t.n18;
    const std::uint32_t faces = background & t.faces;
    if (!faces)
        return false;
    return (faces & ~componentOf(faces & (~faces + 1), background, t.adjacent6)) == 0;
}

} // namespace vsim::imaging
