#include "vsim/sim/fem/SurfaceLoads.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <map>

namespace vsim::sim::fem {

std::vector<std::array<int, 3>> boundaryFaces(const std::vector<std::array<int, 4>>& tets)
{
    // The face opposite corner a of a positively oriented tet, in this order, has an outward normal.
    static constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
    std::map<std::array<int, 3>, std::pair<int, std::array<int, 3>>> faces; // sorted corners -> (count, face)
    for (const auto& tet : tets)
        for (const auto& local : kFaces)
        {
            const std::array<int, 3> face{tet[std::size_t(local[0])], tet[std::size_t(local[1])], tet[std::size_t(local[2])]};
            std::array<int, 3> key = face;
            std::sort(key.begin(), key.end());
            ++faces.try_emplace(key, 0, face).first->second.first;
        }
    std::vector<std::array<int, 3>> boundary;
    for (const auto& [key, entry] : faces)
        if (entry.first == 1)
            boundary.push_back(entry.second);
    return boundary;
}

void addPressureForces(const std::vector<std::array<int, 3>>& faces, const Eigen::VectorXd& positions,
                       double pressurePa, Eigen::VectorXd& forces)
{
    for (const auto& face : faces)
    {
        const Eigen::Vector3d p0 = positions.segment<3>(3 * face[0]);
        // (p1 - p0) x (p2 - p0) = 2 A n
        const Eigen::Vector3d areaNormal =
            0.5 * (positions.segment<3>(3 * face[1]) - p0).cross(positions.segment<3>(3 * face[2]) - p0);
        const Eigen::Vector3d share = -pressurePa * areaNormal / 3.0;
        for (int node : face)
            forces.segment<3>(3 * node) += share;
    }
}

void addGravityForces(const Eigen::VectorXd& mass, const Eigen::Vector3d& gravity, Eigen::VectorXd& forces)
{
    for (Eigen::Index i = 0; i < mass.size(); i += 3)
        forces.segment<3>(i) += mass.segment<3>(i).cwiseProduct(gravity);
}

} // namespace vsim::sim::fem
