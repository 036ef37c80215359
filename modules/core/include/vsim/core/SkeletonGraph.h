#pragma once

#include <Eigen/Core>

#include <array>
#include <vector>

namespace vsim {

/// The vessel tree as a graph: nodes are endpoints and junctions of the unit-width skeleton, edges the
/// vessel segments between them with their voxel path, the same path in mm, and the radius along it.
struct SkeletonGraph
{
    struct Node
    {
        Eigen::Vector3d position;      ///< mm, LPS
        std::array<int, 3> voxel{};    ///< index in the label volume it came from
    };
    struct Edge
    {
        int from = -1;
        int to = -1;
        std::vector<std::array<int, 3>> voxels; ///< path from `from` to `to`, both ends included
        std::vector<Eigen::Vector3d> points;    ///< the same path in mm
        std::vector<double> radii;              ///< mm, one per point (from the distance map)

        /// Polyline length in mm.
        double length() const;
    };

    std::vector<Node> nodes;
    std::vector<Edge> edges;

    /// Number of edges meeting at node `node`.
    int degree(int node) const;
    /// Nodes of degree 1.
    std::vector<int> endpoints() const;
    /// Nodes of degree >= 3.
    std::vector<int> junctions() const;
    /// Throws vsim::Error when an edge refers to a missing node, has fewer than two points, or its point,
    /// voxel and radius lists differ in length, or a radius is not positive.
    void validate() const;
};

} // namespace vsim
