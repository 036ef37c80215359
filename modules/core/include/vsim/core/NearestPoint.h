#pragma once

// Nearest of a fixed set of points (mm) to a query point: the points binned on a uniform grid, the query searching
// shells of cells outwards until no nearer point can remain. Exact (ties go to the lower index). For nearest-
// centerline and distance-to-region queries over millions of voxels.

#include <Eigen/Core>

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

} // namespace vsim
