#pragma once

// Nearest of a fixed set of points (mm) to a query point: the points binned on a uniform grid, the query searching
// shells of cells outwards until no nearer point can remain. Exact (ties go to the lower index). The grown trees'
// truth territories (GrownTree.h): each voxel to its nearest hidden terminal.

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace vsim {

class NearestPoint
{
public:
    /// `cellMm` about the spacing of the points; an empty set answers every query with -1.
    NearestPoint(std::vector<Eigen::Vector3d> points, double cellMm);

    /// Index of the nearest point, and its distance (mm) into `distanceMm` when given; -1 for an empty set.
    int nearest(const Eigen::Vector3d& query, double* distanceMm = nullptr) const;
    /// True when some point lies within `radiusMm` of `query` (stops at the first).
    bool anyWithin(const Eigen::Vector3d& query, double radiusMm) const;

    const std::vector<Eigen::Vector3d>& points() const { return m_points; }

private:
    Eigen::Vector3i cellOf(const Eigen::Vector3d& p) const;
    std::vector<Eigen::Vector3d> m_points;
    double m_cell = 1.0;
    Eigen::Vector3d m_lower = Eigen::Vector3d::Zero();
    Eigen::Vector3i m_cells = Eigen::Vector3i::Zero();
    std::vector<int> m_start; ///< per cell: first entry in m_order (counting sort), size cells + 1
    std::vector<int> m_order; ///< point indices by cell
};


inline NearestPoint::NearestPoint(std::vector<Eigen::Vector3d> points, double cellMm) : m_points(std::move(points)), m_cell(cellMm)
{
    if (m_points.empty())
        return;
    Eigen::Vector3d lower = m_points.front(), upper = m_points.front();
    for (const Eigen::Vector3d& p : m_points)
        lower = lower.cwiseMin(p), upper = upper.cwiseMax(p);
    // At most about 4 million cells: coarsen the cell for sparse sets spread wide.
    const Eigen::Vector3d extent = upper - lower;
    while ((extent / m_cell).array().floor().prod() > 4e6)
        m_cell *= 2.0;
    m_lower = lower;
    m_cells = ((extent / m_cell).array().floor() + 1.0).cast<int>().matrix();
    const std::size_t cellCount = std::size_t(m_cells.x()) * std::size_t(m_cells.y()) * std::size_t(m_cells.z());
    m_start.assign(cellCount + 1, 0);
    std::vector<std::size_t> cell(m_points.size());
    for (std::size_t i = 0; i < m_points.size(); ++i)
    {
        const Eigen::Vector3i c = cellOf(m_points[i]);
        cell[i] = std::size_t(c.x()) + std::size_t(m_cells.x()) * (std::size_t(c.y()) + std::size_t(m_cells.y()) * std::size_t(c.z()));
        ++m_start[cell[i] + 1];
    }
    for (std::size_t c = 0; c < cellCount; ++c)
        m_start[c + 1] += m_start[c];
    m_order.resize(m_points.size());
    std::vector<int> next(m_start.begin(), m_start.end() - 1);
    for (std::size_t i = 0; i < m_points.size(); ++i)
        m_order[std::size_t(next[cell[i]]++)] = int(i);
}

inline Eigen::Vector3i NearestPoint::cellOf(const Eigen::Vector3d& p) const
{
    const Eigen::Vector3d c = ((p - m_lower) / m_cell).array().floor();
    return c.cwiseMax(Eigen::Vector3d::Zero()).cwiseMin((m_cells - Eigen::Vector3i::Ones()).cast<double>()).cast<int>();
}

inline int NearestPoint::nearest(const Eigen::Vector3d& query, double* distanceMm) const
{
    if (m_points.empty())
    {
        if (distanceMm)
            *distanceMm = std::numeric_limits<double>::infinity();
        return -1;
    }
    const Eigen::Vector3i centre = cellOf(query);
    // The query's distance outside the grid's box: every point is at least that far.
    const Eigen::Vector3d upper = m_lower + m_cells.cast<double>() * m_cell;
    const double outside = (m_lower - query).cwiseMax(query - upper).cwiseMax(Eigen::Vector3d::Zero()).norm();
    int best = -1;
    double bestSquared = std::numeric_limits<double>::infinity();
    const int largest = m_cells.maxCoeff();
    for (int shell = 0; shell <= largest; ++shell)
    {
        // Points in shell s are at least (s - 1) cells from the query's projection onto the grid's box, and the
        // projection onto a convex set is a right angle: |q x|^2 >= outside^2 + |p x|^2.
        const double inside = std::max(0, shell - 1) * m_cell;
        if (best >= 0 && outside * outside + inside * inside > bestSquared)
            break;
        for (int dz = -shell; dz <= shell; ++dz)
            for (int dy = -shell; dy <= shell; ++dy)
                for (int dx = -shell; dx <= shell; ++dx)
                {
                    if (std::max({std::abs(dx), std::abs(dy), std::abs(dz)}) != shell)
                        continue;
                    const Eigen::Vector3i c = centre + Eigen::Vector3i(dx, dy, dz);
                    if ((c.array() < 0).any() || (c.array() >= m_cells.array()).any())
                        continue;
                    const std::size_t cell =
                        std::size_t(c.x()) + std::size_t(m_cells.x()) * (std::size_t(c.y()) + std::size_t(m_cells.y()) * std::size_t(c.z()));
                    for (int k = m_start[cell]; k < m_start[cell + 1]; ++k)
                    {
                        const int i = m_order[std::size_t(k)];
                        const double d = (m_points[std::size_t(i)] - query).squaredNorm();
                        if (d < bestSquared || (d == bestSquared && i < best))
                            bestSquared = d, best = i;
                    }
                }
    }
    if (distanceMm)
        *distanceMm = std::sqrt(bestSquared);
    return best;
}

inline bool NearestPoint::anyWithin(const Eigen::Vector3d& query, double radiusMm) const
{
    if (m_points.empty())
        return false;
    const Eigen::Vector3i lowest = cellOf(query - Eigen::Vector3d::Constant(radiusMm));
    const Eigen::Vector3i highest = cellOf(query + Eigen::Vector3d::Constant(radiusMm));
    const double squared = radiusMm * radiusMm;
    for (int z = lowest.z(); z <= highest.z(); ++z)
        for (int y = lowest.y(); y <= highest.y(); ++y)
            for (int x = lowest.x(); x <= highest.x(); ++x)
            {
                const std::size_t cell = std::size_t(x) + std::size_t(m_cells.x()) * (std::size_t(y) + std::size_t(m_cells.y()) * std::size_t(z));
                for (int k = m_start[cell]; k < m_start[cell + 1]; ++k)
                    if ((m_points[std::size_t(m_order[std::size_t(k)])] - query).squaredNorm() <= squared)
                        return true;
            }
    return false;
}

} // namespace vsim
