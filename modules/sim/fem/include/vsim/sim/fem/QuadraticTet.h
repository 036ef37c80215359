#pragma once

// The quadratic (10-node) tetrahedron: the linear mesh's corners plus a node at the middle of every edge (straight
// edges: the geometry stays the linear tet's, the displacement is quadratic, so strain varies linearly inside the
// element and it does not lock in bending or near incompressibility as the constant-strain tet does). Node order
// as VTK's quadratic tetra and CalculiX's C3D10: corners 0-3, then the edges 01, 12, 20, 03, 13, 23. Integrated
// by the 4-point rule of degree 2 (as CalculiX's C3D10).

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace vsim::sim::fem {

/// The corners of each of the 10-node element's 6 edges (nodes 4..9 in this order).
inline constexpr int kQuadraticEdges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};

struct QuadraticTetMesh
{
    std::vector<Eigen::Vector3d> points;       ///< the linear mesh's points (same indices), then the edge midpoints
    std::vector<std::array<int, 10>> elements;
    std::size_t cornerCount = 0;               ///< points before the first edge midpoint
    /// The edge-midpoint node between corner nodes a and b (either order); -1 when a-b is not an edge.
    int midpoint(int a, int b) const;

    std::unordered_map<std::uint64_t, int> edgeMidpoints; ///< key: smaller corner << 32 | larger corner
};

/// Adds a midpoint node on every edge of the linear tetrahedra (any units; the midpoints are the edges' centres).
QuadraticTetMesh quadraticFromLinear(const std::vector<Eigen::Vector3d>& points,
                                     const std::vector<std::array<int, 4>>& tets);

/// The 6-node faces (corners a, b, c then the midpoints of ab, bc, ca) of triangles given by their corners.
std::vector<std::array<int, 6>> quadraticFaces(const QuadraticTetMesh& mesh,
                                               const std::vector<std::array<int, 3>>& cornerFaces);

/// Constraints (3 per node, 1 = held) of the quadratic mesh from its corners' (`cornerConstraints`, 3 per corner
/// node): corners keep theirs, an edge midpoint is held where both its corners are.
std::vector<std::uint8_t> quadraticConstraints(const QuadraticTetMesh& mesh, const std::vector<std::uint8_t>& cornerConstraints);

/// The 4-point rule of degree 2: barycentric coordinates (L0..L3) of the points; each weighs a quarter of the
/// element's volume.
const std::array<Eigen::Vector4d, 4>& tetQuadraturePoints();

/// Gradients (one row per node, 1/length) of the 10 shape functions at barycentric point `l`, from the linear
/// tet's shape-function gradients `g` (one row per corner): corner i (4 L_i - 1) g_i, edge ij 4 (L_j g_i + L_i g_j).
Eigen::Matrix<double, 10, 3> quadraticShapeGradients(const Eigen::Matrix<double, 4, 3>& g, const Eigen::Vector4d& l);

/// The 6-node triangle at (xi, eta) (third coordinate 1 - xi - eta): shape values and their derivatives by xi and eta.
struct QuadraticTriangleShape
{
    Eigen::Matrix<double, 6, 1> n, dXi, dEta;
};
QuadraticTriangleShape quadraticTriangleShape(double xi, double eta);

/// A 6-point rule of degree 4 on the triangle (Dunavant 1985): (xi, eta, weight), the weights summing to 1/2 (the
/// reference triangle's area).
const std::array<Eigen::Vector3d, 6>& triangleQuadraturePoints();

} // namespace vsim::sim::fem
