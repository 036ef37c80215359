#pragma once

// The centerline graph as a tree for reading anatomy (VesselNames.cpp): rooted at its upstream end, oriented along
// its widest paths, with the vessel-following primitives the naming rules use (children that are vessels rather
// than skeleton spurs, directions in the patient frame, how far a subtree reaches, divisions).

#include "vsim/core/Median.h"
#include "vsim/core/SkeletonGraph.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace vsim::imaging::detail {

using Eigen::Vector3d;

constexpr double kAortaMinRadiusMm = 5.0;   // median lumen radius of the aorta's first segment
constexpr double kDirectionLengthMm = 15.0; // a branch's direction: its first 15 mm beyond the parent's lumen

struct Division
{
    std::vector<int> edges; ///< the vessel's edges, junction bridges included, upstream first
    std::vector<int> kids;  ///< the children where it ended (largest first); empty at a free end
    int last = -1;          ///< its last edge
};

class VesselTree
{
public:
    explicit VesselTree(const SkeletonGraph& graph) : g_(graph) {}

protected:
    /// The upstream end: of the endpoints whose segment is at least 0.6 x the widest end segment, the highest
    /// when that is aorta-wide (the aortic inlet, or the ascending aorta's root), else the widest (a branch tree).
    int rootNode() const
    {
        std::vector<int> ends = g_.endpoints();
        if (ends.empty())
            return g_.edges.front().from;
        std::vector<double> endRadius;
        for (int node : ends)
            for (std::size_t e = 0; e < g_.edges.size(); ++e)
                if (g_.edges[e].from == node || g_.edges[e].to == node)
                {
                    endRadius.push_back(median(g_.edges[e].radii, true));
                    break;
                }
        const double widest = *std::max_element(endRadius.begin(), endRadius.end());
        int best = -1;
        for (std::size_t i = 0; i < ends.size(); ++i)
        {
            if (widest < kAortaMinRadiusMm)
            {
                if (endRadius[i] == widest)
                    return ends[i];
                continue;
            }
            if (endRadius[i] >= 0.6 * widest &&
                (best < 0 || g_.nodes[std::size_t(ends[i])].position.z() > g_.nodes[std::size_t(best)].position.z()))
                best = ends[i];
        }
        return best;
    }

    /// Orients every edge away from the root along the widest paths (Dijkstra with the cost length / r^2 per
    /// edge, so that a path keeps to the wide lumen rather than to the skeleton's loops in a sac); an edge that
    /// closes a loop starts at its cheaper node and gets no children.
    void orient(int root)
    {
        const std::size_t edgeCount = g_.edges.size();
        std::vector<std::vector<int>> incident(g_.nodes.size());
        for (std::size_t e = 0; e < edgeCount; ++e)
        {
            incident[std::size_t(g_.edges[e].from)].push_back(int(e));
            if (g_.edges[e].to != g_.edges[e].from)
                incident[std::size_t(g_.edges[e].to)].push_back(int(e));
        }
        start_.assign(edgeCount, -1);
        parent_.assign(edgeCount, -1);
        children_.assign(edgeCount, {});
        radius_.resize(edgeCount);
        for (std::size_t e = 0; e < edgeCount; ++e)
            radius_[e] = median(g_.edges[e].radii, true);
        std::vector<double> cost(g_.nodes.size(), std::numeric_limits<double>::infinity());
        std::vector<int> via(g_.nodes.size(), -1);
        std::vector<bool> done(g_.nodes.size(), false);
        using Entry = std::pair<double, int>;
        std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
        cost[std::size_t(root)] = 0.0;
        queue.push({0.0, root});
        while (!queue.empty())
        {
            const auto [c, node] = queue.top();
            queue.pop();
            if (done[std::size_t(node)])
                continue;
            done[std::size_t(node)] = true;
            for (int e : incident[std::size_t(node)])
            {
                const auto& edge = g_.edges[std::size_t(e)];
                const int far = edge.from == node ? edge.to : edge.from;
                const double r = std::max(radius(e), 0.3);
                const double next = c + length(e) / (r * r);
                if (!done[std::size_t(far)] && next < cost[std::size_t(far)])
                {
                    cost[std::size_t(far)] = next;
                    via[std::size_t(far)] = e;
                    queue.push({next, far});
                }
            }
        }
        for (std::size_t e = 0; e < edgeCount; ++e)
        {
            const auto& edge = g_.edges[e];
            if (!std::isfinite(cost[std::size_t(edge.from)]))
                continue; // another component
            const bool fromFirst = via[std::size_t(edge.to)] == int(e) ||
                                   (via[std::size_t(edge.from)] != int(e) && cost[std::size_t(edge.from)] <= cost[std::size_t(edge.to)]);
            start_[e] = fromFirst ? edge.from : edge.to;
        }
        for (std::size_t e = 0; e < edgeCount; ++e)
        {
            if (start_[e] < 0)
                continue;
            const int parent = via[std::size_t(start_[e])];
            if (parent >= 0 && parent != int(e))
            {
                children_[std::size_t(parent)].push_back(int(e));
                parent_[e] = parent;
            }
            else if (start_[e] == root && (rootEdge_ < 0 || radius(int(e)) > radius(rootEdge_)))
                rootEdge_ = int(e);
        }
    }

    int endNode(int e) const
    {
        const auto& edge = g_.edges[std::size_t(e)];
        return edge.from == start_[std::size_t(e)] ? edge.to : edge.from;
    }
    bool forward(int e) const { return g_.edges[std::size_t(e)].from == start_[std::size_t(e)]; }
    double radius(int e) const { return radius_[std::size_t(e)]; }
    double length(int e) const { return g_.edges[std::size_t(e)].length(); }

    /// Median of `values` (of the middle 60 % when `middle`, away from the junctions' widening).
    static double median(std::vector<double> values, bool middle)
    {
        if (middle && values.size() >= 5)
            values = std::vector<double>(values.begin() + long(values.size() / 5), values.end() - long(values.size() / 5));
        return vsim::median(std::move(values), 0.0);
    }

    /// The lumen radius where edge `e` ends (its last five points), mm.
    double radiusAtEnd(int e) const
    {
        const auto& radii = g_.edges[std::size_t(e)].radii;
        const std::size_t n = std::min<std::size_t>(5, radii.size());
        std::vector<double> last = forward(e) ? std::vector<double>(radii.end() - long(n), radii.end())
                                              : std::vector<double>(radii.begin(), radii.begin() + long(n));
        return median(last, false);
    }

    /// How far `p` lies outside the aortic lumen (mm; the distance to the aortic centerline less its radius there;
    /// infinite before the aorta is found or without one).
    double outsideAorta(const Vector3d& p) const
    {
        double nearest = std::numeric_limits<double>::infinity();
        for (const auto& [q, r] : aortic_)
            nearest = std::min(nearest, (p - q).norm() - r);
        return nearest;
    }

    /// The longest path (mm) from the start of edge `e` down its subtree.
    double reach(int e) const
    {
        double deepest = 0.0;
        for (int c : children_[std::size_t(e)])
            deepest = std::max(deepest, reach(c));
        return length(e) + deepest;
    }

    /// Edge `e`'s points from its start (mm).
    std::vector<Vector3d> points(int e) const
    {
        std::vector<Vector3d> p = g_.edges[std::size_t(e)].points;
        if (!forward(e))
            std::reverse(p.begin(), p.end());
        return p;
    }

    /// The direction of the vessel starting with edge `e`: from `skipMm` along it (outside the parent's lumen) to
    /// kDirectionLengthMm (or `lengthMm`) further, carrying on into the widest child where the edge is shorter.
    Vector3d direction(int e, double skipMm, double lengthMm = kDirectionLengthMm) const
    {
        std::vector<Vector3d> path;
        double total = 0.0;
        for (int current = e; current >= 0 && total < skipMm + lengthMm;)
        {
            for (const Vector3d& p : points(current))
            {
                if (!path.empty())
                    total += (p - path.back()).norm();
                path.push_back(p);
            }
            int widest = -1;
            for (int child : children_[std::size_t(current)])
                if (widest < 0 || radius(child) > radius(widest))
                    widest = child;
            current = widest;
        }
        if (path.size() < 2)
            return Vector3d::Zero();
        const double from = total >= skipMm + 3.0 ? skipMm : 0.0;
        Vector3d a = path.front(), b = path.back();
        double s = 0.0;
        bool haveA = from == 0.0;
        for (std::size_t i = 1; i < path.size(); ++i)
        {
            s += (path[i] - path[i - 1]).norm();
            if (!haveA && s >= from)
                a = path[i], haveA = true;
            if (s >= from + lengthMm)
            {
                b = path[i];
                break;
            }
        }
        const Vector3d d = b - a;
        return d.norm() > 0 ? Vector3d(d.normalized()) : Vector3d::Zero();
    }

    /// The direction in which edge `e` arrives at its end (its last 15 mm).
    Vector3d directionAtEnd(int e) const
    {
        const std::vector<Vector3d> p = points(e);
        double s = 0.0;
        std::size_t i = p.size() - 1;
        while (i > 0 && s < kDirectionLengthMm)
            s += (p[i] - p[i - 1]).norm(), --i;
        const Vector3d d = p.back() - p[i];
        return d.norm() > 0 ? Vector3d(d.normalized()) : Vector3d::Zero();
    }

    /// The children of `e` that are vessels, widest first: a short edge between two junctions is read as part of
    /// the junction (its children taken instead; the bridge added to `bridges`); a free end that stays within the
    /// parent's lumen (ends within its radius + 2 mm of where it starts or within 5 mm of the aortic lumen, or is under 4 mm
    /// long) is a spur.
    std::vector<int> kids(int e, std::vector<int>& bridges) const
    {
        std::vector<int> result;
        const double parentRadius = radiusAtEnd(e);
        std::function<void(int)> collect = [&](int parent) {
            for (int c : children_[std::size_t(parent)])
            {
                const bool free = children_[std::size_t(c)].empty();
                const std::vector<Vector3d> p = points(c);
                if (!free && length(c) < std::max(3.0, 0.75 * radius(e)))
                {
                    bridges.push_back(c);
                    collect(c);
                }
                else if (!(free && (length(c) < 4.0 || (p.back() - p.front()).norm() < parentRadius + 2.0 ||
                                    outsideAorta(p.back()) < 5.0)))
                    result.push_back(c);
            }
        };
        collect(e);
        std::sort(result.begin(), result.end(), [&](int a, int b) { return radius(a) > radius(b); });
        return result;
    }

    /// Follows the vessel from `e` through its side branches (the widest child goes on) until `endsHere` says
    /// that its children are a division, or it ends.
    Division follow(int e, const std::function<bool(int, const std::vector<int>&)>& endsHere) const
    {
        Division walk;
        for (std::size_t guard = 0; guard <= g_.edges.size(); ++guard)
        {
            walk.edges.push_back(e);
            walk.last = e;
            std::vector<int> k = kids(e, walk.edges);
            if (k.empty())
                return walk;
            if (k.size() >= 2 && endsHere(e, k))
            {
                walk.kids = k;
                return walk;
            }
            e = k.front();
        }
        return walk;
    }

    /// A division: the second widest child reaches 15 mm or more and is at least `ratio` x as wide as the widest,
    /// or (the radii of small segmented vessels, under 2 mm, are a voxel or two: too coarse to compare) reaches
    /// 0.3 x as far.
    static std::function<bool(int, const std::vector<int>&)> divisionAt(const VesselTree& namer, double ratio)
    {
        return [&namer, ratio](int, const std::vector<int>& k) {
            if (namer.reach(k[1]) < 15.0)
                return false;
            return namer.radius(k[1]) >= ratio * namer.radius(k[0]) ||
                   (namer.radius(k[0]) < 2.0 && namer.reach(k[1]) >= 0.3 * namer.reach(k[0]));
        };
    }

    /// The path of tree edges from the root down to edge `e`, `e` included.
    std::vector<int> pathTo(int e) const
    {
        std::vector<int> path{e};
        while (parent_[std::size_t(path.back())] >= 0)
            path.push_back(parent_[std::size_t(path.back())]);
        std::reverse(path.begin(), path.end());
        return path;
    }

    /// Length of `path` from its edge `from` on (mm).
    double reachAlong(const std::vector<int>& path, std::size_t from) const
    {
        double total = 0.0;
        for (std::size_t i = from; i < path.size(); ++i)
            total += length(path[i]);
        return total;
    }

    const SkeletonGraph& g_;
    std::vector<int> start_;
    std::vector<int> parent_;
    std::vector<std::vector<int>> children_;
    std::vector<double> radius_;
    std::vector<std::pair<Vector3d, double>> aortic_; ///< the aorta's centerline points and lumen radii (mm)
    int rootEdge_ = -1;
};

} // namespace vsim::imaging::detail
