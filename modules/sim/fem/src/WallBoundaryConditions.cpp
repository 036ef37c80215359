#include "vsim/sim/fem/WallBoundaryConditions.h"

#include "vsim/core/Error.h"

#include <algorithm>

namespace vsim::sim::fem {

std::vector<std::array<int, 3>> WallBoundaryConditions::faceNodes(const std::vector<std::array<int, 4>>& tets) const
{
    std::vector<std::array<int, 3>> nodes;
    nodes.reserve(lumenFaces.size());
    for (const Face& face : lumenFaces)
    {
        const auto& tet = tets[face.element];
        nodes.push_back({tet[std::size_t(kTetFaces[face.opposite][0])], tet[std::size_t(kTetFaces[face.opposite][1])],
                         tet[std::size_t(kTetFaces[face.opposite][2])]});
    }
    return nodes;
}

void requireWallFields(const TetMesh& wall)
{
    if (!wall.pointFields.count("wall_layer") || !wall.pointFields.count("end_set"))
        throw Error("the tetrahedral mesh is not a vessel wall (wall_layer / end_set fields missing): build it with "
                    "'mesh wall'");
}

WallBoundaryConditions wallBoundaryConditions(const TetMesh& wall, const std::function<bool(const Eigen::Vector3d&)>& loaded)
{
    requireWallFields(wall);
    const std::vector<double>& layer = wall.pointFields.at("wall_layer");
    const std::vector<double>& endSet = wall.pointFields.at("end_set");
    WallBoundaryConditions conditions;
    conditions.fixed.assign(3 * wall.points.size(), 0);
    std::size_t fixedNodes = 0;
    for (std::size_t i = 0; i < wall.points.size(); ++i)
        if (endSet[i] > 0.0)
        {
            conditions.fixed[3 * i] = conditions.fixed[3 * i + 1] = conditions.fixed[3 * i + 2] = 1;
            ++fixedNodes;
        }
    if (fixedNodes == 0)
        throw Error("the wall has no fixed end (end_set is 0 everywhere): build it from centerlines with ends");
    std::vector<std::size_t> owners;
    const std::vector<std::array<int, 3>> boundary = boundaryFaces(wall.tets, &owners);
    for (std::size_t f = 0; f < boundary.size(); ++f)
    {
        const auto& face = boundary[f];
        if (layer[std::size_t(face[0])] != 0.0 || layer[std::size_t(face[1])] != 0.0 || layer[std::size_t(face[2])] != 0.0)
            continue;
        const Eigen::Vector3d centroid =
            (wall.points[std::size_t(face[0])] + wall.points[std::size_t(face[1])] + wall.points[std::size_t(face[2])]) / 3.0;
        if (loaded && !loaded(centroid))
            continue;
        const auto& tet = wall.tets[owners[f]];
        int opposite = 0;
        while (std::find(face.begin(), face.end(), tet[std::size_t(opposite)]) != face.end())
            ++opposite;
        conditions.lumenFaces.push_back({owners[f], opposite});
    }
    if (conditions.lumenFaces.empty())
        throw Error("no lumen face carries the pressure");
    return conditions;
}

} // namespace vsim::sim::fem
