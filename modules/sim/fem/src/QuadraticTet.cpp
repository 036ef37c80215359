#include "vsim/sim/fem/QuadraticTet.h"

#include <algorithm>

namespace vsim::sim::fem {
namespace {

std::uint64_t edgeKey(int a, int b)
{
    const auto [low, high] = std::minmax(a, b);
    return (std::uint64_t(std::uint32_t(low)) << 32) | std::uint32_t(high);
}

} // namespace

int QuadraticTetMesh::midpoint(int a, int b) const
{
    const auto found = edgeMidpoints.find(edgeKey(a, b));
    return found == edgeMidpoints.end() ? -1 : found->second;
}

QuadraticTetMesh quadraticFromLinear(const std::vector<Eigen::Vector3d>& points,
                                     const std::vector<std::array<int, 4>>& tets)
{
    QuadraticTetMesh mesh;
    mesh.points = points;
    mesh.cornerCount = points.size();
    mesh.elements.reserve(tets.size());
    mesh.edgeMidpoints.reserve(tets.size() * 2);
    for (const auto& tet : tets)
    {
        std::array<int, 10> element{};
        for (int c = 0; c < 4; ++c)
            element[std::size_t(c)] = tet[std::size_t(c)];
        for (int e = 0; e < 6; ++e)
        {
            const int a = tet[std::size_t(kQuadraticEdges[e][0])], b = tet[std::size_t(kQuadraticEdges[e][1])];
            const auto [where, added] = mesh.edgeMidpoints.try_emplace(edgeKey(a, b), int(mesh.points.size()));
            if (added)
                mesh.points.push_back(0.5 * (points[std::size_t(a)] + points[std::size_t(b)]));
            element[std::size_t(4 + e)] = where->second;
        }
        mesh.elements.push_back(element);
    }
    return mesh;
}

std::vector<std::array<int, 6>> quadraticFaces(const QuadraticTetMesh& mesh,
                                               const std::vector<std::array<int, 3>>& cornerFaces)
{
    std::vector<std::array<int, 6>> faces;
    faces.reserve(cornerFaces.size());
    for (const auto& [a, b, c] : cornerFaces)
        faces.push_back({a, b, c, mesh.midpoint(a, b), mesh.midpoint(b, c), mesh.midpoint(c, a)});
    return faces;
}

std::vector<std::uint8_t> quadraticConstraints(const QuadraticTetMesh& mesh, const std::vector<std::uint8_t>& corners)
{
    std::vector<std::uint8_t> held(3 * mesh.points.size(), 0);
    std::copy(corners.begin(), corners.end(), held.begin());
    for (const auto& element : mesh.elements)
        for (int e = 0; e < 6; ++e)
        {
            const int a = element[std::size_t(kQuadraticEdges[e][0])], b = element[std::size_t(kQuadraticEdges[e][1])];
            for (int k = 0; k < 3; ++k)
                if (corners[std::size_t(3 * a + k)] && corners[std::size_t(3 * b + k)])
                    held[std::size_t(3 * element[std::size_t(4 + e)] + k)] = 1;
        }
    return held;
}

const std::array<Eigen::Vector4d, 4>& tetQuadraturePoints()
{
    // (5 + 3 sqrt 5) / 20 and (5 - sqrt 5) / 20: exact for quadratic integrands.
    constexpr double a = 0.5854101966249685, b = 0.1381966011250105;
    static const std::array<Eigen::Vector4d, 4> points = {Eigen::Vector4d(a, b, b, b), Eigen::Vector4d(b, a, b, b),
                                                          Eigen::Vector4d(b, b, a, b), Eigen::Vector4d(b, b, b, a)};
    return points;
}

Eigen::Matrix<double, 10, 3> quadraticShapeGradients(const Eigen::Matrix<double, 4, 3>& g, const Eigen::Vector4d& l)
{
    Eigen::Matrix<double, 10, 3> out;
    for (int i = 0; i < 4; ++i)
        out.row(i) = (4.0 * l[i] - 1.0) * g.row(i);
    for (int e = 0; e < 6; ++e)
    {
        const int i = kQuadraticEdges[e][0], j = kQuadraticEdges[e][1];
        out.row(4 + e) = 4.0 * (l[j] * g.row(i) + l[i] * g.row(j));
    }
    return out;
}

QuadraticTriangleShape quadraticTriangleShape(double xi, double eta)
{
    // Barycentric (L0, L1, L2) = (1 - xi - eta, xi, eta); nodes: corners 0, 1, 2, then edges 01, 12, 20.
    const double l0 = 1.0 - xi - eta, l1 = xi, l2 = eta;
    QuadraticTriangleShape s;
    s.n << l0 * (2 * l0 - 1), l1 * (2 * l1 - 1), l2 * (2 * l2 - 1), 4 * l0 * l1, 4 * l1 * l2, 4 * l2 * l0;
    // d/dxi: dL0 = -1, dL1 = 1, dL2 = 0; d/deta: dL0 = -1, dL1 = 0, dL2 = 1.
    s.dXi << -(4 * l0 - 1), 4 * l1 - 1, 0.0, 4 * (l0 - l1), 4 * l2, -4 * l2;
    s.dEta << -(4 * l0 - 1), 0.0, 4 * l2 - 1, -4 * l1, 4 * l1, 4 * (l0 - l2);
    return s;
}

const std::array<Eigen::Vector3d, 6>& triangleQuadraturePoints()
{
    constexpr double a1 = 0.445948490915965, w1 = 0.223381589678011 / 2;
    constexpr double a2 = 0.091576213509771, w2 = 0.109951743655322 / 2;
    static const std::array<Eigen::Vector3d, 6> points = {
        Eigen::Vector3d(a1, a1, w1), Eigen::Vector3d(1 - 2 * a1, a1, w1), Eigen::Vector3d(a1, 1 - 2 * a1, w1),
        Eigen::Vector3d(a2, a2, w2), Eigen::Vector3d(1 - 2 * a2, a2, w2), Eigen::Vector3d(a2, 1 - 2 * a2, w2)};
    return points;
}

} // namespace vsim::sim::fem
