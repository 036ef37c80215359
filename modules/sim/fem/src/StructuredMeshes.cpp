#include "vsim/sim/fem/StructuredMeshes.h"

#include "vsim/core/Error.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <functional>

namespace vsim::sim::fem {
namespace {

/// The grid of `cells` with node positions from `place(i, j, k)`, every hexahedron split into six tets; with
/// `periodicJ` the last layer of cells along j closes onto j = 0 (a full tube).
StructuredTetMesh kuhnMesh(const std::array<int, 3>& cells, const std::function<Eigen::Vector3d(int, int, int)>& place,
                           bool periodicJ = false)
{
    if (*std::min_element(cells.begin(), cells.end()) < 1)
        throw Error("a structured mesh needs at least one cell per axis");
    StructuredTetMesh mesh;
    mesh.cells = cells;
    mesh.periodicJ = periodicJ;
    const int nodesJ = periodicJ ? cells[1] : cells[1] + 1;
    for (int k = 0; k <= cells[2]; ++k)
        for (int j = 0; j < nodesJ; ++j)
            for (int i = 0; i <= cells[0]; ++i)
                mesh.points.push_back(place(i, j, k));
    auto nodeOf = [&](int i, int j, int k) { return i + (cells[0] + 1) * (j % nodesJ + nodesJ * k); };
    static constexpr int kPermutations[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    for (int k = 0; k < cells[2]; ++k)
        for (int j = 0; j < cells[1]; ++j)
            for (int i = 0; i < cells[0]; ++i)
                for (const auto& order : kPermutations)
                {
                    // Walk from corner (0,0,0) to (1,1,1) one axis at a time.
                    std::array<int, 3> at{i, j, k};
                    std::array<int, 4> tet{};
                    tet[0] = nodeOf(at[0], at[1], at[2]);
                    for (int step = 0; step < 3; ++step)
                    {
                        ++at[std::size_t(order[step])];
                        tet[std::size_t(step + 1)] = nodeOf(at[0], at[1], at[2]);
                    }
                    Eigen::Matrix3d edges;
                    const Eigen::Vector3d& p0 = mesh.points[std::size_t(tet[0])];
                    edges << mesh.points[std::size_t(tet[1])] - p0, mesh.points[std::size_t(tet[2])] - p0,
                        mesh.points[std::size_t(tet[3])] - p0;
                    if (edges.determinant() < 0.0)
                        std::swap(tet[1], tet[2]);
                    mesh.tets.push_back(tet);
                }
    return mesh;
}

} // namespace

StructuredTetMesh boxTetMesh(const Eigen::Vector3d& size, const std::array<int, 3>& cells)
{
    return kuhnMesh(cells, [&](int i, int j, int k) {
        return Eigen::Vector3d(size.x() * i / cells[0], size.y() * j / cells[1], size.z() * k / cells[2]);
    });
}

StructuredTetMesh tubeWallTetMesh(double inner, double outer, double length, const std::array<int, 3>& cells)
{
    if (!(inner > 0.0 && outer > inner && length > 0.0) || cells[1] < 3)
        throw Error("a tube wall needs 0 < inner < outer radius, a positive length and at least 3 cells around");
    return kuhnMesh(
        cells,
        [&](int i, int j, int k) {
            const double r = inner + (outer - inner) * i / cells[0], phi = 2.0 * M_PI * j / cells[1];
            return Eigen::Vector3d(r * std::cos(phi), r * std::sin(phi), length * k / cells[2]);
        },
        true);
}

StructuredTetMesh annulusSectorTetMesh(double inner, double outer, double angle, double height,
                                       const std::array<int, 3>& cells)
{
    if (!(inner > 0.0 && outer > inner && angle > 0.0 && height > 0.0))
        throw Error("an annulus sector needs 0 < inner < outer radius, a positive angle and height");
    return kuhnMesh(cells, [&](int i, int j, int k) {
        const double r = inner + (outer - inner) * i / cells[0], phi = angle * j / cells[1];
        return Eigen::Vector3d(r * std::cos(phi), r * std::sin(phi), height * k / cells[2]);
    });
}

} // namespace vsim::sim::fem
