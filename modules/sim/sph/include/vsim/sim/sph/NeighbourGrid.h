#pragma once

// Neighbour search on a uniform grid whose cell is half the kernel's support (issue 18): each build counts the
// particles per cell, prefix-sums the counts (a counting sort) and lists the particles cell by cell, so that
// the neighbours of a particle lie in the 27 cells around its own. order() is that list (the permutation that
// sorts the particles by cell); the solver reorders its particle arrays by it now and then, so that
// neighbours lie near in memory, and builds again. An axis can be periodic over [0, L) (the validation
// channels): its cells wrap around and the offsets between particles are the nearest images. The CUDA backend
// builds the same structure (cell index, counting sort, reorder) on the device.

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace vsim::sim::sph {

class NeighbourGrid
{
public:
    /// `reachM` > 0: the kernel support (2h); the cells are half of it (a query scans 5 x 5 x 5 cells: 42 % fewer
    /// candidates than 3 x 3 x 3 cells of the whole reach). `periodicLengthM[a]` > 0 makes axis a periodic over
    /// [0, L) (L at least 2.5 reaches: throws vsim::Error otherwise); 0 leaves it open.
    explicit NeighbourGrid(double reachM, const Eigen::Vector3d& periodicLengthM = Eigen::Vector3d::Zero());

    /// Sorts `positionsM` by cell. Throws vsim::Error when a position is not finite or the particles spread
    /// over more cells than kMaxCells (a run whose particles fled: the solver's guard catches it first).
    void build(const std::vector<Eigen::Vector3d>& positionsM);
    /// sorted index -> index in the positions given to build().
    const std::vector<int>& order() const { return m_order; }
    /// Reorders `values` (one per particle, in build()'s order) into the sorted order.
    template <class T> void reorder(std::vector<T>& values) const;

    /// Calls f(j, rij, r) for every particle j != i within the cell size of particle i, with rij = x_i - x_j
    /// (m) and r = |rij|; `positionsM` and the indices are those given to build().
    template <class F>
    void forEachNeighbour(const std::vector<Eigen::Vector3d>& positionsM, int i, F&& f) const
    {
        forEachNear(positionsM, positionsM[std::size_t(i)], i, std::forward<F>(f));
    }
    /// Calls f(j, rij, r) for every particle j != `skip` within the cell size of the point `xM` (m; within the
    /// grid's reach of the particles), rij = x - x_j: the open boundaries' interpolation at mirror points.
    template <class F>
    void forEachNear(const std::vector<Eigen::Vector3d>& positionsM, const Eigen::Vector3d& xM, int skip, F&& f) const;

    double reach() const { return m_reach; }
    static constexpr int kCellsPerReach = 2;
    /// x_i - x_j, as the nearest image across the periodic axes.
    Eigen::Vector3d offset(const Eigen::Vector3d& xi, const Eigen::Vector3d& xj) const
    {
        Eigen::Vector3d rij = xi - xj;
        for (int a = 0; a < 3; ++a)
            if (m_period[a] > 0.0)
                rij[a] -= m_period[a] * std::round(rij[a] / m_period[a]);
        return rij;
    }
    /// `positionM` brought back into [0, L) along the periodic axes.
    Eigen::Vector3d wrap(Eigen::Vector3d positionM) const
    {
        for (int a = 0; a < 3; ++a)
            if (m_period[a] > 0.0)
                positionM[a] -= m_period[a] * std::floor(positionM[a] / m_period[a]);
        return positionM;
    }
    const Eigen::Vector3d& periodicLength() const { return m_period; }
    std::array<int, 3> dims() const { return m_dims; }
    static constexpr std::int64_t kMaxCells = 1LL << 27;

private:
    std::array<int, 3> cellOf(const Eigen::Vector3d& positionM) const;
    std::int64_t cellIndex(const std::array<int, 3>& cell) const
    {
        return cell[0] + std::int64_t(m_dims[0]) * (cell[1] + std::int64_t(m_dims[1]) * cell[2]);
    }

    double m_reach, m_cellSize;
    Eigen::Vector3d m_period;                         ///< m per axis; 0: open
    Eigen::Vector3d m_cell = Eigen::Vector3d::Zero(); ///< the cell's edge per axis (a period's share, >= the support)
    Eigen::Vector3d m_origin = Eigen::Vector3d::Zero();
    std::array<int, 3> m_dims{0, 0, 0};
    std::vector<int> m_cellStart; ///< first sorted particle of each cell; one more entry: the particle count
    std::vector<int> m_order;
};

template <class T> void NeighbourGrid::reorder(std::vector<T>& values) const
{
    std::vector<T> sorted;
    sorted.reserve(m_order.size());
    for (int original : m_order)
        sorted.push_back(values[std::size_t(original)]);
    values.swap(sorted);
}

template <class F>
void NeighbourGrid::forEachNear(const std::vector<Eigen::Vector3d>& positionsM, const Eigen::Vector3d& xi, int i,
                               F&& f) const
{
    const std::array<int, 3> c = cellOf(xi);
    const double reach2 = m_reach * m_reach;
    constexpr int k = kCellsPerReach;
    auto visit = [&](std::int64_t firstCell, std::int64_t lastCell) { // cells first..last, consecutive along x
        for (int s = m_cellStart[std::size_t(firstCell)]; s < m_cellStart[std::size_t(lastCell) + 1]; ++s)
        {
            const int j = m_order[std::size_t(s)];
            if (j == i)
                continue;
            const Eigen::Vector3d rij = offset(xi, positionsM[std::size_t(j)]);
            const double r2 = rij.squaredNorm();
            if (r2 < reach2)
                f(j, rij, std::sqrt(r2));
        }
    };
    for (int dz = -k; dz <= k; ++dz)
        for (int dy = -k; dy <= k; ++dy)
        {
            std::array<int, 3> n{c[0], c[1] + dy, c[2] + dz};
            bool outside = false;
            for (std::size_t a = 1; a < 3; ++a)
            {
                if (m_period[int(a)] > 0.0)
                    n[a] = (n[a] + m_dims[a]) % m_dims[a];
                outside = outside || n[a] < 0 || n[a] >= m_dims[a];
            }
            if (outside)
                continue;
            if (m_period[0] > 0.0)
                for (int dx = -k; dx <= k; ++dx)
                {
                    n[0] = (c[0] + dx + m_dims[0]) % m_dims[0];
                    visit(cellIndex(n), cellIndex(n));
                }
            else
            {
                // Without a period along x the row's cells are consecutive in the sorted order: one range, visited in
                // the same order as cell by cell.
                std::array<int, 3> first = n, last = n;
                first[0] = std::max(0, c[0] - k), last[0] = std::min(m_dims[0] - 1, c[0] + k);
                if (first[0] <= last[0])
                    visit(cellIndex(first), cellIndex(last));
            }
        }
}

} // namespace vsim::sim::sph
