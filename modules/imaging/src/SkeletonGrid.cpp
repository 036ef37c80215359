#include "SkeletonGrid.h"

#include "vsim/core/Error.h"

#include <algorithm>
#include <cstdlib>

namespace vsim::imaging {
namespace {

constexpr int kCentre = 13; // local index (dx+1) + 3 (dy+1) + 9 (dz+1) of the voxel itself

struct LocalTables
{
    std::array<std::vector<int>, 27> adjacent26;
    std::array<std::vector<int>, 27> adjacent6;
    std::array<bool, 27> inN18{};
    std::array<int, 6> faces{};

    LocalTables()
    {
        auto coordinates = [](int l) { return std::array<int, 3>{l % 3 - 1, (l / 3) % 3 - 1, l / 9 - 1}; };
        int face = 0;
        for (int a = 0; a < 27; ++a)
        {
            const auto ca = coordinates(a);
            const int fromCentre = std::abs(ca[0]) + std::abs(ca[1]) + std::abs(ca[2]);
            inN18[std::size_t(a)] = fromCentre >= 1 && fromCentre <= 2;
            if (fromCentre == 1)
                faces[std::size_t(face++)] = a;
            for (int b = 0; b < 27; ++b)
            {
                const auto cb = coordinates(b);
                const int dx = std::abs(ca[0] - cb[0]), dy = std::abs(ca[1] - cb[1]), dz = std::abs(ca[2] - cb[2]);
                if (a == b || std::max({dx, dy, dz}) > 1)
                    continue;
                adjacent26[std::size_t(a)].push_back(b);
                if (dx + dy + dz == 1)
                    adjacent6[std::size_t(a)].push_back(b);
            }
        }
    }
};

const LocalTables& tables()
{
    static const LocalTables instance;
    return instance;
}

} // namespace

SkeletonGrid SkeletonGrid::fromLabel(const LabelVolume& label, std::uint8_t value)
{
    const auto& d = label.geometry().dims;
    std::array<int, 3> low{d[0], d[1], d[2]}, high{-1, -1, -1};
    for (int k = 0; k < d[2]; ++k)
        for (int j = 0; j < d[1]; ++j)
            for (int i = 0; i < d[0]; ++i)
                if (label.at(i, j, k) == value)
                {
                    low = {std::min(low[0], i), std::min(low[1], j), std::min(low[2], k)};
                    high = {std::max(high[0], i), std::max(high[1], j), std::max(high[2], k)};
                }
    if (high[0] < 0)
        throw Error("the label is empty: segment the vessels first");
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

int SkeletonGrid::degree(std::size_t index) const
{
    int count = 0;
    for (std::ptrdiff_t offset : neighbour)
        count += voxels[std::size_t(std::ptrdiff_t(index) + offset)];
    return count;
}

bool SkeletonGrid::isSimple(std::size_t index) const
{
    const LocalTables& t = tables();
    std::array<std::uint8_t, 27> local{};
    for (std::size_t n = 0; n < 26; ++n)
    {
        const int l = (step[n][0] + 1) + 3 * (step[n][1] + 1) + 9 * (step[n][2] + 1);
        local[std::size_t(l)] = voxels[std::size_t(std::ptrdiff_t(index) + neighbour[n])];
    }
    // One 26-connected object component among the 26 neighbours.
    std::uint32_t seen = 0;
    int components = 0;
    int stack[27];
    for (int l = 0; l < 27; ++l)
    {
        if (l == kCentre || !local[std::size_t(l)] || (seen >> l & 1u))
            continue;
        if (++components > 1)
            return false;
        int top = 0;
        stack[top++] = l;
        seen |= 1u << l;
        while (top > 0)
        {
            const int current = stack[--top];
            for (int next : t.adjacent26[std::size_t(current)])
                if (next != kCentre && local[std::size_t(next)] && !(seen >> next & 1u))
                {
                    seen |= 1u << next;
                    stack[top++] = next;
                }
        }
    }
    if (components != 1)
        return false;
    // One 6-connected background component in N18 touching a face neighbour.
    seen = 0;
    components = 0;
    for (int face : t.faces)
    {
        if (local[std::size_t(face)] || (seen >> face & 1u))
            continue;
        if (++components > 1)
            return false;
        int top = 0;
        stack[top++] = face;
        seen |= 1u << face;
        while (top > 0)
        {
            const int current = stack[--top];
            for (int next : t.adjacent6[std::size_t(current)])
                if (t.inN18[std::size_t(next)] && !local[std::size_t(next)] && !(seen >> next & 1u))
                {
                    seen |= 1u << next;
                    stack[top++] = next;
                }
        }
    }
    return components == 1;
}

} // namespace vsim::imaging
