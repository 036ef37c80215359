#include "vsim/sim/network/NetworkBuild.h"

#include "vsim/core/Error.h"
#include "vsim/core/Median.h"
#include "vsim/core/StoredText.h"
#include "vsim/sim/network/TipOrientation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <random>
#include <string>

namespace vsim::sim::network {
namespace {

double polylineLength(const std::vector<Eigen::Vector3d>& path)
{
    double length = 0.0;
    for (std::size_t i = 1; i < path.size(); ++i)
        length += (path[i] - path[i - 1]).norm();
    return length;
}

/// Where a point is nearest to a path: the piece index, the parameter on it, the arc length there, the distance.
struct PathPoint
{
    std::size_t piece = 0;
    double t = 0.0, arc = 0.0, distance = std::numeric_limits<double>::infinity();
};

PathPoint nearestOnPath(const std::vector<Eigen::Vector3d>& path, const Eigen::Vector3d& p)
{
    PathPoint best;
    double arc = 0.0;
    for (std::size_t i = 1; i < path.size(); ++i)
    {
        const Eigen::Vector3d d = path[i] - path[i - 1];
        const double length = d.norm();
        const double t = length > 0.0 ? std::clamp((p - path[i - 1]).dot(d) / (length * length), 0.0, 1.0) : 0.0;
        const double distance = (path[i - 1] + t * d - p).norm();
        if (distance < best.distance)
            best = {i - 1, t, arc + t * length, distance};
        arc += length;
    }
    return best;
}

/// Leaves out the thinnest segment of every loop (Kruskal's maximum spanning forest by mean radius).
void breakLoops(VesselNetwork& network, std::vector<std::string>* warnings)
{
    std::vector<std::size_t> order(network.segments.size());
    std::iota(order.begin(), order.end(), 0);
    auto radius = [&](std::size_t s) { return network.segments[s].startRadiusMm + network.segments[s].endRadiusMm; };
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return radius(a) > radius(b); });
    std::vector<int> parent(network.nodes.size());
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&](int x) {
        while (parent[std::size_t(x)] != x)
            x = parent[std::size_t(x)] = parent[std::size_t(parent[std::size_t(x)])];
        return x;
    };
    std::vector<char> keep(network.segments.size(), 1);
    for (std::size_t s : order)
    {
        const int a = find(network.segments[s].from), b = find(network.segments[s].to);
        if (a == b)
        {
            keep[s] = 0;
            if (warnings)
                warnings->push_back("centerline edge " + std::to_string(s) + " closed a loop (nodes " +
                                    std::to_string(network.segments[s].from) + " - " +
                                    std::to_string(network.segments[s].to) +
                                    ") and was left out of the network: check the skeleton there");
        }
        else
            parent[std::size_t(a)] = b;
    }
    std::vector<VesselNetwork::Segment> kept;
    for (std::size_t s = 0; s < network.segments.size(); ++s)
        if (keep[s])
            kept.push_back(std::move(network.segments[s]));
    network.segments = std::move(kept);
}

} // namespace

VesselNetwork networkFromCenterlines(const SkeletonGraph& centerlines, const std::vector<std::array<double, 2>>& endRadiiMm,
                                     std::vector<std::string>* warnings, const std::vector<std::string>& names)
{
    if (centerlines.edges.empty())
        throw Error("the centerlines have no vessel segments: extract them first (vascusim-cli centerline)");
    if (!endRadiiMm.empty() && endRadiiMm.size() != centerlines.edges.size())
        throw Error(Pattern{"end radii are given for %1 of %2 centerline edges",
                            {std::to_string(endRadiiMm.size()), std::to_string(centerlines.edges.size())}});
    VesselNetwork network;
    for (const SkeletonGraph::Node& node : centerlines.nodes)
        network.nodes.push_back({node.position, {}});
    for (std::size_t e = 0; e < centerlines.edges.size(); ++e)
    {
        const SkeletonGraph::Edge& edge = centerlines.edges[e];
        VesselNetwork::Segment segment;
        segment.from = edge.from;
        segment.to = edge.to;
        segment.pathMm = edge.points;
        segment.lengthMm = edge.length();
        if (e < names.size())
            segment.name = names[e];
        if (!endRadiiMm.empty())
            segment.startRadiusMm = endRadiiMm[e][0], segment.endRadiusMm = endRadiiMm[e][1];
        else if (!edge.radii.empty())
        {
            const std::size_t quarter = std::max<std::size_t>(1, edge.radii.size() / 4);
            const auto head = edge.radii.begin() + std::ptrdiff_t(quarter);
            const auto tail = edge.radii.end() - std::ptrdiff_t(quarter);
            segment.startRadiusMm = median(std::vector<double>(edge.radii.begin(), head));
            segment.endRadiusMm = median(std::vector<double>(tail, edge.radii.end()));
        }
        if (!(segment.startRadiusMm > 0.0 && segment.endRadiusMm > 0.0))
            throw Error(Pattern{"centerline edge %1 has no positive radius: measure the vessels again",
                                {std::to_string(e)}},
                        {{"segment", std::to_string(e)}});
        network.segments.push_back(std::move(segment));
    }
    breakLoops(network, warnings);
    network.root = largestEnd(network);
    network.validate();
    return network;
}

std::string branchName(const VesselNetwork& network, int segment)
{
    const auto& own = network.segments[std::size_t(segment)];
    return own.name.empty() ? storedText(Pattern{"unnamed (nodes %1-%2)", {std::to_string(own.from), std::to_string(own.to)}})
                            : own.name;
}

std::pair<int, double> nearestSegment(const VesselNetwork& network, const Eigen::Vector3d& pointMm,
                                      const std::function<bool(int)>& eligible)
{
    std::pair<int, double> best{-1, std::numeric_limits<double>::infinity()};
    for (std::size_t s = 0; s < network.segments.size(); ++s)
    {
        if (eligible && !eligible(int(s)))
            continue;
        const double distance = nearestOnPath(network.segmentPath(s), pointMm).distance;
        if (distance < best.second)
            best = {int(s), distance};
    }
    return best;
}

Eigen::Vector3d segmentMiddle(const VesselNetwork& network, int segment)
{
    const std::vector<Eigen::Vector3d> path = network.segmentPath(std::size_t(segment));
    const double half = 0.5 * polylineLength(path);
    double arc = 0.0;
    for (std::size_t i = 1; i < path.size(); ++i)
    {
        const double length = (path[i] - path[i - 1]).norm();
        if (arc + length >= half && length > 0.0)
            return path[i - 1] + (half - arc) / length * (path[i] - path[i - 1]);
        arc += length;
    }
    return path.front();
}

int placeNode(VesselNetwork& network, const Eigen::Vector3d& pointMm, double snapMm, double reachMm)
{
    int nearestNode = -1;
    double nodeDistance = std::numeric_limits<double>::infinity();
    for (std::size_t n = 0; n < network.nodes.size(); ++n)
    {
        const double distance = (network.nodes[n].positionMm - pointMm).norm();
        if (distance < nodeDistance)
            nodeDistance = distance, nearestNode = int(n);
    }
    const auto [s, distance] = nearestSegment(network, pointMm);
    if (s < 0 || distance > reachMm)
    {
        char text[160];
        std::snprintf(text, sizeof text, "the point (%.1f, %.1f, %.1f) mm is %.1f mm from the vessel tree (at most %.1f)",
                      pointMm.x(), pointMm.y(), pointMm.z(), distance, reachMm);
        throw Error(text);
    }
    if (nodeDistance <= snapMm)
        return nearestNode;
    VesselNetwork::Segment& segment = network.segments[std::size_t(s)];
    const std::vector<Eigen::Vector3d> path = network.segmentPath(std::size_t(s));
    const PathPoint at = nearestOnPath(path, pointMm);
    const double pathLength = polylineLength(path), fraction = pathLength > 0.0 ? at.arc / pathLength : 0.5;
    if (fraction <= 1e-6) // the nearest point is an end of the segment: that node
        return segment.from;
    if (fraction >= 1.0 - 1e-6)
        return segment.to;
    const Eigen::Vector3d split = path[at.piece] + at.t * (path[at.piece + 1] - path[at.piece]);
    const int node = int(network.nodes.size());
    network.nodes.push_back({split, {}});
    VesselNetwork::Segment distal = segment;
    const double splitRadius = segment.startRadiusMm + (segment.endRadiusMm - segment.startRadiusMm) * fraction;
    std::vector<Eigen::Vector3d> first(path.begin(), path.begin() + std::ptrdiff_t(at.piece) + 1), second{split};
    first.push_back(split);
    second.insert(second.end(), path.begin() + std::ptrdiff_t(at.piece) + 1, path.end());
    segment.to = node;
    segment.endRadiusMm = splitRadius;
    segment.lengthMm = distal.lengthMm * fraction;
    segment.resistance = distal.resistance * fraction;
    segment.pathMm = std::move(first);
    distal.from = node;
    distal.startRadiusMm = splitRadius;
    distal.lengthMm *= 1.0 - fraction;
    distal.resistance *= 1.0 - fraction;
    distal.pathMm = std::move(second);
    network.segments.push_back(std::move(distal)); // `segment` is not used after this
    network.segmentFields.clear();
    return node;
}

VesselNetwork randomTree(int segments, std::uint32_t seed)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    VesselNetwork network;
    network.nodes.push_back({Eigen::Vector3d::Zero(), {}});
    for (int s = 0; s < segments; ++s)
    {
        const int parent = std::min(int(unit(random) * double(network.nodes.size())), int(network.nodes.size()) - 1);
        const Eigen::Vector3d offset(unit(random), unit(random), 1.0);
        network.nodes.push_back({network.nodes[std::size_t(parent)].positionMm + offset, {}});
        VesselNetwork::Segment segment;
        segment.from = parent;
        segment.to = int(network.nodes.size()) - 1;
        segment.startRadiusMm = 0.3 + 2.7 * unit(random);
        segment.endRadiusMm = segment.startRadiusMm * (0.7 + 0.3 * unit(random));
        segment.lengthMm = 2.0 + 20.0 * unit(random);
        network.segments.push_back(segment);
    }
    network.root = 0;
    return network;
}

} // namespace vsim::sim::network
