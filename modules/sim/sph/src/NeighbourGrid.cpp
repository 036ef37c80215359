#include "vsim/sim/sph/NeighbourGrid.h"

#include "vsim/core/Error.h"

#include <algorithm>
#include <cmath>

namespace vsim::sim::sph {

NeighbourGrid::NeighbourGrid(double reachM, const Eigen::Vector3d& periodicLengthM)
    : m_reach(reachM), m_cellSize(reachM / kCellsPerReach), m_period(periodicLengthM)
{
    if (!(reachM > 0.0) || !std::isfinite(reachM))
        throw Error("the neighbour grid's reach must be a positive length");
    // A periodic axis needs 2 k + 1 cells, so that a query visits each cell once.
    for (int a = 0; a < 3; ++a)
        if (!(m_period[a] >= 0.0) || (m_period[a] > 0.0 && m_period[a] < (2 * kCellsPerReach + 1) * m_cellSize))
            throw Error(Pattern{"a periodic axis must be at least 2.5 kernel supports long (%1 mm)",
                                {std::to_string(2.5e3 * reachM)}});
}

std::array<int, 3> NeighbourGrid::cellOf(const Eigen::Vector3d& positionM) const
{
    std::array<int, 3> cell{};
    for (int a = 0; a < 3; ++a)
        cell[std::size_t(a)] =
            std::clamp(int(std::floor((positionM[a] - m_origin[a]) / m_cell[a])), 0, m_dims[std::size_t(a)] - 1);
    return cell;
}

void NeighbourGrid::build(const std::vector<Eigen::Vector3d>& positionsM)
{
    Eigen::Vector3d low = Eigen::Vector3d::Constant(0.0), high = Eigen::Vector3d::Constant(0.0);
    if (!positionsM.empty())
        low = high = positionsM.front();
    for (const Eigen::Vector3d& p : positionsM)
    {
        if (!p.allFinite())
            throw Error("a particle's position is not finite: the neighbour grid cannot place it");
        low = low.cwiseMin(p), high = high.cwiseMax(p);
    }
    m_origin = low;
    std::int64_t cells = 1;
    for (int a = 0; a < 3; ++a)
    {
        if (m_period[a] > 0.0) // whole cells over the period, each at least half the support
        {
            m_origin[a] = 0.0;
            m_dims[std::size_t(a)] = int(std::floor(m_period[a] / m_cellSize));
            m_cell[a] = m_period[a] / m_dims[std::size_t(a)];
        }
        else
        {
            m_cell[a] = m_cellSize;
            m_dims[std::size_t(a)] = int(std::floor((high[a] - low[a]) / m_cellSize)) + 1;
        }
        cells *= m_dims[std::size_t(a)];
        if (cells > kMaxCells)
            throw Error(Pattern{"the particles spread over more than %1 neighbour cells", {std::to_string(kMaxCells)}});
    }
    // Counting sort: count per cell, prefix sum, place.
    std::vector<std::int64_t> cellOfParticle(positionsM.size());
    m_cellStart.assign(std::size_t(cells) + 1, 0);
    for (std::size_t i = 0; i < positionsM.size(); ++i)
    {
        cellOfParticle[i] = cellIndex(cellOf(positionsM[i]));
        ++m_cellStart[std::size_t(cellOfParticle[i]) + 1];
    }
    for (std::size_t c = 1; c < m_cellStart.size(); ++c)
        m_cellStart[c] += m_cellStart[c - 1];
    std::vector<int> next(m_cellStart.begin(), m_cellStart.end() - 1);
    m_order.assign(positionsM.size(), 0);
    for (std::size_t i = 0; i < positionsM.size(); ++i) // stable: the particles of a cell keep their order
        m_order[std::size_t(next[std::size_t(cellOfParticle[i])]++)] = int(i);
}

} // namespace vsim::sim::sph
