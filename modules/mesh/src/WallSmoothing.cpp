#include "WallSmoothing.h"

#include "vsim/mesh/WallMesh.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>

namespace vsim::mesh::detail {
namespace {

constexpr int kSmoothingSweeps = 6;
constexpr double kFirstStepFraction = 0.4; // of maxMoveMm
constexpr double kLastStepFraction = 0.01;

double volume6(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c, const Eigen::Vector3d& d)
{
    return (b - a).cross(c - a).dot(d - a);
}

class Smoother
{
public:
    Smoother(TetMesh& mesh) : m_mesh(mesh), m_around(mesh.points.size())
    {
        for (std::size_t t = 0; t < mesh.tets.size(); ++t)
            for (int v : mesh.tets[t])
                m_around[std::size_t(v)].push_back(t);
    }

    double angleOf(std::size_t t) const
    {
        const auto& tet = m_mesh.tets[t];
        const auto& p = m_mesh.points;
        return minDihedralAngle(p[std::size_t(tet[0])], p[std::size_t(tet[1])], p[std::size_t(tet[2])], p[std::size_t(tet[3])]);
    }

    /// The smallest dihedral angle of the elements around node v with v at x; -1 where one would invert.
    double qualityAt(std::size_t v, const Eigen::Vector3d& x) const
    {
        double worst = 180.0;
        for (std::size_t t : m_around[v])
        {
            std::array<Eigen::Vector3d, 4> corner;
            for (int k = 0; k < 4; ++k)
            {
                const auto n = std::size_t(m_mesh.tets[t][std::size_t(k)]);
                corner[std::size_t(k)] = n == v ? x : m_mesh.points[n];
            }
            if (volume6(corner[0], corner[1], corner[2], corner[3]) <= 0.0)
                return -1.0;
            worst = std::min(worst, minDihedralAngle(corner[0], corner[1], corner[2], corner[3]));
        }
        return worst;
    }

    /// Pattern search for node v in the plane across `direction`, within maxMove of `home`; returns whether it moved.
    bool improve(std::size_t v, const Eigen::Vector3d& home, const Eigen::Vector3d& direction, double maxMove)
    {
        const Eigen::Vector3d across1 = direction.unitOrthogonal(), across2 = direction.cross(across1);
        Eigen::Vector3d best = m_mesh.points[v];
        double quality = qualityAt(v, best);
        if (quality < 0.0)
            return false;
        for (double step = kFirstStepFraction * maxMove; step > kLastStepFraction * maxMove;)
        {
            bool better = false;
            for (const Eigen::Vector3d& axis : {across1, across2})
                for (double sign : {1.0, -1.0})
                {
                    const Eigen::Vector3d x = best + sign * step * axis;
                    if ((x - home).norm() > maxMove)
                        continue;
                    const double q = qualityAt(v, x);
                    if (q > quality + 1e-9)
                        quality = q, best = x, better = true;
                }
            if (!better)
                step *= 0.5;
        }
        const bool moved = best != m_mesh.points[v];
        m_mesh.points[v] = best;
        return moved;
    }

private:
    TetMesh& m_mesh;
    std::vector<std::vector<std::size_t>> m_around;
};

} // namespace

double raiseDihedralAngles(TetMesh& mesh, const std::vector<Eigen::Vector3d>& direction, double targetDeg,
                           const std::vector<double>& maxMoveMm, const std::vector<Eigen::Vector3d>& built)
{
    Smoother smoother(mesh);
    const std::vector<Eigen::Vector3d> home = built.empty() ? mesh.points : built;
    std::vector<double> angle(mesh.tets.size());
    double smallestBefore = 180.0;
    for (std::size_t t = 0; t < mesh.tets.size(); ++t)
        smallestBefore = std::min(smallestBefore, angle[t] = smoother.angleOf(t));
    for (int sweep = 0; sweep < kSmoothingSweeps; ++sweep)
    {
        std::vector<bool> candidate(mesh.points.size(), false);
        for (std::size_t t = 0; t < mesh.tets.size(); ++t)
            if (angle[t] < targetDeg)
                for (int v : mesh.tets[t])
                    candidate[std::size_t(v)] = direction[std::size_t(v)].squaredNorm() > 0.0;
        bool any = false;
        for (std::size_t v = 0; v < mesh.points.size(); ++v)
            if (candidate[v] && smoother.improve(v, home[v], direction[v], maxMoveMm[v]))
                any = true;
        if (!any)
            break;
        for (std::size_t t = 0; t < mesh.tets.size(); ++t)
            angle[t] = smoother.angleOf(t);
    }
    return smallestBefore;
}

} // namespace vsim::mesh::detail
