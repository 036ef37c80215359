#include "vsim/core/TetMesh.h"

#include <algorithm>
#include <map>

#include "vsim/core/Error.h"

#include <Eigen/Geometry>

namespace vsim {

double TetMesh::elementVolume(std::size_t tet) const
{
    const auto& element = tets[tet];
    const Eigen::Vector3d& p0 = points[element[0]];
    return (points[element[1]] - p0).cross(points[element[2]] - p0).dot(points[element[3]] - p0) / 6.0;
}

double TetMesh::totalVolume() const
{
    double total = 0.0;
    for (std::size_t tet = 0; tet < tets.size(); ++tet)
        total += elementVolume(tet);
    return total;
}

void TetMesh::validate() const
{
    const int count = static_cast<int>(points.size());
    for (std::size_t tet = 0; tet < tets.size(); ++tet)
    {
        for (int index : tets[tet])
            if (index < 0 || index >= count)
                throw Error("tetrahedron refers to a missing point",
                            {{"element", std::to_string(tet)}, {"point", std::to_string(index)}});
        if (!(elementVolume(tet) > 0.0))
            throw Error("inverted or degenerate tetrahedron",
                        {{"element", std::to_string(tet)}, {"volume_mm3", std::to_string(elementVolume(tet))}});
    }
    for (const auto& [name, values] : pointFields)
        if (values.size() != points.size())
            throw Error("point field length differs from the point count", {{"field", name}});
    for (const auto& [name, values] : cellFields)
        if (values.size() != tets.size())
            throw Error("cell field length differs from the element count", {{"field", name}});
}

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

} // namespace vsim
