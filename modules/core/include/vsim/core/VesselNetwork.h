#pragma once

#include <Eigen/Core>

#include <map>
#include <string>
#include <vector>

namespace vsim {

/// A vessel tree as a pipe network (thesis ch. 6): nodes in mm (LPS), segments as conical pipes between them, the
/// boundary conditions of outlets that are not left to the default, and per-segment result fields. Built from the
/// centerlines of a study or read from a network file (users add what imaging cannot see).
struct VesselNetwork
{
    struct Node
    {
        Eigen::Vector3d positionMm = Eigen::Vector3d::Zero();
        std::string name; ///< optional label for people ("A", "left hepatic")
    };
    struct Segment
    {
        int from = -1;
        int to = -1;
        double startRadiusMm = 0.0; ///< lumen radius at `from`
        double endRadiusMm = 0.0;   ///< lumen radius at `to`
        double lengthMm = 0.0;
        /// Pa s / m^3; when > 0 it replaces the conical Hagen-Poiseuille resistance (the radii then only size the
        /// volume the filling needs).
        double resistance = 0.0;
        std::vector<Eigen::Vector3d> pathMm; ///< the centerline for display (empty: the straight line)
        std::string name; ///< anatomical name ("gastroduodenal artery"); empty when unnamed
    };
    /// An outlet's condition: the pressure at the node, or a terminal resistance to a pressure beyond it.
    struct Outlet
    {
        enum class Type
        {
            Pressure,
            Resistance,
        };
        int node = -1;
        Type type = Type::Resistance;
        double pressurePa = 0.0;   ///< at the node (Pressure) or beyond the terminal resistance (Resistance)
        double resistance = 0.0;   ///< Pa s / m^3 (Resistance)
    };

    std::vector<Node> nodes;
    std::vector<Segment> segments;
    std::vector<Outlet> outlets;   ///< explicit conditions; other end nodes get the solver's default
    int root = -1;                 ///< the inlet of the tree (the end of the largest vessel); -1: unknown
    /// Results per segment (e.g. "flow_ml_min"), each with one value per segment.
    std::map<std::string, std::vector<double>> segmentFields;

    /// The segment's centerline for display (mm): its path, or the straight line between its nodes when it has none.
    std::vector<Eigen::Vector3d> segmentPath(std::size_t segment) const;
    /// Segments meeting at every node.
    std::vector<std::vector<int>> incidentSegments() const;
    /// Nodes with exactly one segment.
    std::vector<int> endNodes() const;
    /// Throws vsim::Error naming the segment or node: indices out of range, a segment from a node to itself,
    /// non-positive or non-finite radii (without an explicit resistance) or lengths, a cycle, an outlet on a
    /// missing node or with a bad value, a root out of range, a field of the wrong length.
    void validate() const;
};

} // namespace vsim
