#include "vsim/sim/smoke/PoissonMultigrid.h"

#include <algorithm>

namespace vsim::sim::smoke {
namespace {

constexpr int kCoarsestSweeps = 30;     // symmetric sweeps that stand for a solve on the coarsest level
constexpr std::size_t kCoarsestCells = 512;
constexpr std::size_t kParallelCells = 32768; // smaller levels run on one thread: a parallel region costs more there

bool open(const DomainBoundaries& boundaries, int face)
{
    return boundaries[std::size_t(face)] == DomainBoundary::Open;
}

} // namespace

PoissonMultigrid::Level PoissonMultigrid::makeLevel(int nx, int ny, int nz, std::vector<std::uint8_t> fluid,
                                                    const std::vector<std::uint8_t>& ambient,
                                                    const DomainBoundaries& boundaries)
{
    Level level;
    level.nx = nx, level.ny = ny, level.nz = nz;
    level.fluid = std::move(fluid);
    level.diagonal.assign(level.fluid.size(), 0);
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i)
            {
                const std::size_t c = level.index(i, j, k);
                if (!level.fluid[c])
                    continue;
                int count = 0;
                const int at[6][3] = {{i - 1, j, k}, {i + 1, j, k}, {i, j - 1, k}, {i, j + 1, k}, {i, j, k - 1}, {i, j, k + 1}};
                for (int f = 0; f < 6; ++f)
                {
                    const auto [a, b, d] = at[f];
                    if (a < 0 || b < 0 || d < 0 || a >= nx || b >= ny || d >= nz)
                        count += open(boundaries, f) ? 1 : 0;
                    else
                        count += level.fluid[level.index(a, b, d)] || ambient[level.index(a, b, d)] ? 1 : 0;
                }
                level.diagonal[c] = std::uint8_t(count);
            }
    level.x.assign(level.fluid.size(), 0.0f);
    level.b.assign(level.fluid.size(), 0.0f);
    level.r.assign(level.fluid.size(), 0.0f);
    return level;
}

bool PoissonMultigrid::isSingular(const SmokeGrid& grid)
{
    return std::none_of(grid.boundaries.begin(), grid.boundaries.end(),
                        [](DomainBoundary b) { return b == DomainBoundary::Open; }) &&
           std::none_of(grid.solid.begin(), grid.solid.end(), [](std::uint8_t s) { return s == kVent; });
}

void PoissonMultigrid::prepare(const SmokeGrid& grid)
{
    m_boundaries = grid.boundaries;
    m_singular = isSingular(grid);
    m_levels.clear();
    std::vector<std::uint8_t> fluid(grid.cells()), ambient(grid.cells());
    for (std::size_t c = 0; c < fluid.size(); ++c)
        fluid[c] = grid.solid[c] == kFluid, ambient[c] = grid.solid[c] == kVent;
    m_levels.push_back(makeLevel(grid.nx, grid.ny, grid.nz, std::move(fluid), ambient, m_boundaries));
    while (m_levels.back().fluid.size() > kCoarsestCells)
    {
        const Level& fine = m_levels.back();
        const int cx = (fine.nx + 1) / 2, cy = (fine.ny + 1) / 2, cz = (fine.nz + 1) / 2;
        if (cx < 2 || cy < 2 || cz < 2)
            break;
        // A coarse cell is fluid when any child is; a vent when none is fluid and one is a vent.
        std::vector<std::uint8_t> coarse(std::size_t(cx) * cy * cz, 0), coarseAmbient(coarse.size(), 0);
        for (int k = 0; k < fine.nz; ++k)
            for (int j = 0; j < fine.ny; ++j)
                for (int i = 0; i < fine.nx; ++i)
                {
                    const std::size_t parent = std::size_t(i / 2) + std::size_t(cx) * (j / 2 + std::size_t(cy) * (k / 2));
                    if (fine.fluid[fine.index(i, j, k)])
                        coarse[parent] = 1;
                    else if (ambient[fine.index(i, j, k)])
                        coarseAmbient[parent] = 1;
                }
        for (std::size_t c = 0; c < coarse.size(); ++c)
            coarseAmbient[c] = coarseAmbient[c] && !coarse[c];
        m_levels.push_back(makeLevel(cx, cy, cz, std::move(coarse), coarseAmbient, m_boundaries));
        ambient = std::move(coarseAmbient);
    }
}

void PoissonMultigrid::applyLevel(const Level& level, const std::vector<float>& x, std::vector<float>& y) const
{
    const int nx = level.nx, ny = level.ny, nz = level.nz;
#pragma omp parallel for schedule(static) if (level.fluid.size() >= kParallelCells)
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i)
            {
                const std::size_t c = level.index(i, j, k);
                if (!level.fluid[c])
                {
                    y[c] = 0.0f;
                    continue;
                }
                // x is 0 in every cell that is not fluid (the V-cycle and CG keep it so): all neighbours add.
                float sum = float(level.diagonal[c]) * x[c];
                if (i > 0)
                    sum -= x[c - 1];
                if (i + 1 < nx)
                    sum -= x[c + 1];
                const std::size_t row = std::size_t(nx), slab = std::size_t(nx) * ny;
                if (j > 0)
                    sum -= x[c - row];
                if (j + 1 < ny)
                    sum -= x[c + row];
                if (k > 0)
                    sum -= x[c - slab];
                if (k + 1 < nz)
                    sum -= x[c + slab];
                y[c] = sum;
            }
}

void PoissonMultigrid::apply(const std::vector<float>& x, std::vector<float>& y) const
{
    applyLevel(m_levels.front(), x, y);
}

void PoissonMultigrid::smooth(const Level& level, std::vector<float>& x, const std::vector<float>& b,
                              int colourFirst) const
{
    const int nx = level.nx, ny = level.ny, nz = level.nz;
    const std::size_t row = std::size_t(nx), slab = std::size_t(nx) * ny;
    for (int pass = 0; pass < 2; ++pass)
    {
        const int colour = (colourFirst + pass) % 2;
#pragma omp parallel for schedule(static) if (level.fluid.size() >= kParallelCells)
        for (int k = 0; k < nz; ++k)
            for (int j = 0; j < ny; ++j)
                for (int i = (j + k + colour) % 2; i < nx; i += 2)
                {
                    const std::size_t c = level.index(i, j, k);
                    if (!level.fluid[c] || level.diagonal[c] == 0)
                        continue;
                    float sum = b[c];
                    if (i > 0)
                        sum += x[c - 1];
                    if (i + 1 < nx)
                        sum += x[c + 1];
                    if (j > 0)
                        sum += x[c - row];
                    if (j + 1 < ny)
                        sum += x[c + row];
                    if (k > 0)
                        sum += x[c - slab];
                    if (k + 1 < nz)
                        sum += x[c + slab];
                    x[c] = sum / float(level.diagonal[c]);
                }
    }
}

void PoissonMultigrid::vcycle(std::size_t depth, const std::vector<float>& b, std::vector<float>& x) const
{
    const Level& level = m_levels[depth];
    std::fill(x.begin(), x.end(), 0.0f);
    if (depth + 1 == m_levels.size())
    {
        for (int sweep = 0; sweep < kCoarsestSweeps; ++sweep)
            smooth(level, x, b, 0);
        for (int sweep = 0; sweep < kCoarsestSweeps; ++sweep)
            smooth(level, x, b, 1);
        return;
    }
    const int sweeps = smoothingSweeps(depth);
    for (int sweep = 0; sweep < sweeps; ++sweep)
        smooth(level, x, b, 0);
    applyLevel(level, x, level.r);
    const Level& coarse = m_levels[depth + 1];
    // Each coarse cell gathers half the residual of its (up to eight) fluid children.
#pragma omp parallel for schedule(static) if (coarse.fluid.size() >= kParallelCells)
    for (int K = 0; K < coarse.nz; ++K)
        for (int J = 0; J < coarse.ny; ++J)
            for (int I = 0; I < coarse.nx; ++I)
            {
                float sum = 0.0f;
                for (int k = 2 * K; k < std::min(2 * K + 2, level.nz); ++k)
                    for (int j = 2 * J; j < std::min(2 * J + 2, level.ny); ++j)
                        for (int i = 2 * I; i < std::min(2 * I + 2, level.nx); ++i)
                        {
                            const std::size_t c = level.index(i, j, k);
                            if (level.fluid[c])
                                sum += b[c] - level.r[c];
                        }
                coarse.b[coarse.index(I, J, K)] = 0.5f * sum;
            }
    vcycle(depth + 1, coarse.b, coarse.x);
#pragma omp parallel for schedule(static) if (level.fluid.size() >= kParallelCells)
    for (int k = 0; k < level.nz; ++k)
        for (int j = 0; j < level.ny; ++j)
            for (int i = 0; i < level.nx; ++i)
            {
                const std::size_t c = level.index(i, j, k);
                if (level.fluid[c])
                    x[c] += coarse.x[coarse.index(i / 2, j / 2, k / 2)];
            }
    for (int sweep = 0; sweep < sweeps; ++sweep)
        smooth(level, x, b, 1);
}

void PoissonMultigrid::precondition(const std::vector<float>& r, std::vector<float>& z) const
{
    vcycle(0, r, z);
    removeNullSpace(z);
}

void PoissonMultigrid::removeNullSpace(std::vector<float>& x) const
{
    if (!m_singular)
        return;
    const Level& level = m_levels.front();
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t c = 0; c < x.size(); ++c)
        if (level.fluid[c])
            sum += x[c], ++count;
    const float mean = count ? float(sum / double(count)) : 0.0f;
    for (std::size_t c = 0; c < x.size(); ++c)
        if (level.fluid[c])
            x[c] -= mean;
}

} // namespace vsim::sim::smoke
