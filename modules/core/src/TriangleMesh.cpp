#include "vsim/core/TriangleMesh.h"

#include "vsim/core/Error.h"

#include <Eigen/Geometry>

namespace vsim {

std::vector<Eigen::Vector3d> TriangleMesh::vertexNormals() const
{
    std::vector<Eigen::Vector3d> normals(points.size(), Eigen::Vector3d::Zero());
    for (const auto& t : triangles)
    {
        const Eigen::Vector3d& a = points[std::size_t(t[0])];
        const Eigen::Vector3d areaNormal = (points[std::size_t(t[1])] - a).cross(points[std::size_t(t[2])] - a);
        for (int corner : t)
            normals[std::size_t(corner)] += areaNormal;
    }
    for (Eigen::Vector3d& normal : normals)
        if (normal.norm() > 0.0)
            normal.normalize();
    return normals;
}

double TriangleMesh::area() const
{
    double total = 0.0;
    for (const auto& triangle : triangles)
    {
        const Eigen::Vector3d& a = points[triangle[0]];
        total += 0.5 * (points[triangle[1]] - a).cross(points[triangle[2]] - a).norm();
    }
    return total;
}

double TriangleMesh::signedVolume() const
{
    double total = 0.0; // divergence theorem: sum of signed tetrahedra against the origin
    for (const auto& triangle : triangles)
        total += points[triangle[0]].dot(points[triangle[1]].cross(points[triangle[2]])) / 6.0;
    return total;
}

void TriangleMesh::validate() const
{
    const int count = static_cast<int>(points.size());
    for (std::size_t t = 0; t < triangles.size(); ++t)
    {
        const auto& triangle = triangles[t];
        for (int index : triangle)
            if (index < 0 || index >= count)
                throw Error("triangle refers to a missing point",
                            {{"triangle", std::to_string(t)}, {"point", std::to_string(index)}});
        if (triangle[0] == triangle[1] || triangle[1] == triangle[2] || triangle[0] == triangle[2])
            throw Error("triangle repeats a point", {{"triangle", std::to_string(t)}});
    }
    for (const auto& [name, values] : pointFields)
        if (values.size() != points.size())
            throw Error("point field length differs from the point count", {{"field", name}});
}

} // namespace vsim
