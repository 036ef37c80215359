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

std::vector<std::array<int, 3>> boundaryFaces(const std::vector<std::array<int, 4>>& tets,
                                              std::vector<std::size_t>* owners)
{
    struct Seen
    {
        int count;
        std::array<int, 3> face;
        std::size_t owner;
    };
    std::map<std::array<int, 3>, Seen> faces; // sorted corners -> what was seen
    for (std::size_t t = 0; t < tets.size(); ++t)
        for (const auto& local : kTetFaces)
        {
            const std::array<int, 3> face{tets[t][std::size_t(local[0])], tets[t][std::size_t(local[1])],
                                          tets[t][std::size_t(local[2])]};
            std::array<int, 3> key = face;
            std::sort(key.begin(), key.end());
            ++faces.try_emplace(key, Seen{0, face, t}).first->second.count;
        }
    std::vector<std::array<int, 3>> boundary;
    if (owners)
        owners->clear();
    for (const auto& [key, seen] : faces)
        if (seen.count == 1)
        {
            boundary.push_back(seen.face);
            if (owners)
                owners->push_back(seen.owner);
        }
    return boundary;
}

} // namespace vsim
