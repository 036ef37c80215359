#pragma once

// A liver with an arterial tree grown down to terminals far below CT resolution: the truth that perfusion
// territories, feeders and coverage are judged against (issue 19). Not the estimator's rule: the estimator sees
// only the visible tree and gives each voxel to the nearest visible terminal; here every hidden terminal perfuses
// its own small region (the voxels nearest it), and a visible branch perfuses the union of its hidden
// descendants' regions, wherever the growth took them, also those that leave from the middle of a visible vessel.
//
// Growth (a greedy form of constructive optimisation, Schreiner & Buxbaum 1993, with the nearest vessel in place of
// the least-volume connection): terminal points drawn uniformly in an ellipsoidal liver (three times as dense in
// the tumour: hypervascular), each joined in turn by a straight branch to the nearest point of the tree grown so
// far. Radii by Murray's law with equal terminal flows, r = r_root (n / N)^(1/3) for n terminals downstream; a
// vessel is visible from `visibleRadiusMm` up (chains of visible pieces merged into one segment with a path).

#include "vsim/core/ImageVolume.h"
#include "NearestPoint.h"
#include "vsim/core/VesselNetwork.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace vsim::test {

struct GrownTree
{
    LabelVolume liver;           ///< 1 in the liver (the tumour included)
    LabelVolume tumour;          ///< 1 in the tumour
    VesselNetwork visible;       ///< what CT shows: merged visible segments, the root outside the liver
    std::vector<Eigen::Vector3d> terminals; ///< every (hidden) terminal
    std::vector<int> ancestor;   ///< per terminal: the visible segment its branch leaves from
    std::vector<int> inTumour;   ///< per terminal: 1 when it lies in the tumour
    Eigen::Vector3d tumourCentreMm = Eigen::Vector3d::Zero();
    double tumourRadiusMm = 0.0;

    /// The visible segments downstream of a visible node (the segments of its subtree).
    std::vector<char> downstreamOf(int node) const
    {
        std::vector<char> down(visible.segments.size(), 0);
        std::vector<int> stack{node};
        while (!stack.empty())
        {
            const int n = stack.back();
            stack.pop_back();
            for (std::size_t s = 0; s < visible.segments.size(); ++s)
                if (visible.segments[s].from == n && !down[s])
                    down[s] = 1, stack.push_back(visible.segments[s].to);
        }
        return down;
    }
};

struct GrowthOptions
{
    unsigned seed = 1;
    int terminals = 20000;
    double rootRadiusMm = 3.0;
    double visibleRadiusMm = 0.75;
    Eigen::Vector3d semiAxesMm{80.0, 60.0, 50.0};
    double voxelMm = 1.0;
    /// A grid of these voxels (spacing `spacingMm`) centred on the liver instead of one fitted around it at voxelMm.
    std::array<int, 3> dims{0, 0, 0};
    Eigen::Vector3d spacingMm{1.0, 1.0, 1.0};
    double tumourRadiusMm = 10.0;
    Eigen::Vector3d tumourOffset{0.45, -0.3, 0.2}; ///< tumour centre in units of the semi-axes
};

inline GrownTree growTree(const GrowthOptions& o)
{
    GrownTree g;
    std::mt19937 random(o.seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    VolumeGeometry geometry;
    Eigen::Vector3d half = o.semiAxesMm + Eigen::Vector3d::Constant(15.0);
    if (o.dims[0] > 0)
    {
        geometry.dims = o.dims;
        geometry.spacing = o.spacingMm;
        for (int a = 0; a < 3; ++a)
            half[a] = 0.5 * (o.dims[std::size_t(a)] - 1) * o.spacingMm[a];
    }
    else
    {
        for (int a = 0; a < 3; ++a)
            geometry.dims[std::size_t(a)] = int(std::ceil(2.0 * half[a] / o.voxelMm)) + 1;
        geometry.spacing = Eigen::Vector3d::Constant(o.voxelMm);
    }
    geometry.origin = -half;
    g.liver = LabelVolume(geometry);
    g.tumour = LabelVolume(geometry);
    g.tumourCentreMm = o.tumourOffset.cwiseProduct(o.semiAxesMm);
    g.tumourRadiusMm = o.tumourRadiusMm;
    auto inLiver = [&](const Eigen::Vector3d& p) { return p.cwiseQuotient(o.semiAxesMm).squaredNorm() <= 1.0; };
    auto inTumour = [&](const Eigen::Vector3d& p) { return (p - g.tumourCentreMm).norm() <= o.tumourRadiusMm; };
    for (int k = 0; k < geometry.dims[2]; ++k)
        for (int j = 0; j < geometry.dims[1]; ++j)
            for (int i = 0; i < geometry.dims[0]; ++i)
            {
                const Eigen::Vector3d p = geometry.indexToPatient(Eigen::Vector3d(i, j, k));
                g.liver.at(i, j, k) = inLiver(p) ? 1 : 0;
                g.tumour.at(i, j, k) = inLiver(p) && inTumour(p) ? 1 : 0;
            }

    // Terminal points: uniform in the liver, the tumour's accepted three times as often.
    while (int(g.terminals.size()) < o.terminals)
    {
        const Eigen::Vector3d p = Eigen::Vector3d(unit(random), unit(random), unit(random)).cwiseProduct(o.semiAxesMm);
        if (!inLiver(p))
            continue;
        const int copies = inTumour(p) ? 3 : 1;
        for (int c = 0; c < copies && int(g.terminals.size()) < o.terminals; ++c)
            g.terminals.push_back(c == 0 ? p : p + Eigen::Vector3d(unit(random), unit(random), unit(random)) * 0.5 * o.voxelMm);
    }

    // Growth: nodes, segments (from -> to, parent before child), the terminal each segment ends at (-1: a junction).
    std::vector<Eigen::Vector3d> node{Eigen::Vector3d(0.0, o.semiAxesMm.y() + 10.0, 0.0)}; // the hilum, outside
    std::vector<std::array<int, 2>> segment;
    std::vector<int> endsAt;
    // Segments binned by the cells (5 mm) their bounding boxes overlap; a split segment keeps its old cells (a
    // stale entry costs a distance, never a miss).
    const double cell = 5.0;
    const Eigen::Vector3d lowest = -half;
    const Eigen::Vector3i cells = ((2.0 * half) / cell).array().ceil().cast<int>().matrix() + Eigen::Vector3i::Ones();
    std::vector<std::vector<int>> binned(std::size_t(cells.prod()));
    auto cellOf = [&](const Eigen::Vector3d& p) {
        return ((p - lowest) / cell).array().floor().cast<int>().max(0).min(cells.array() - 1).matrix().eval();
    };
    auto bin = [&](int s, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
        const Eigen::Vector3i lo = cellOf(a.cwiseMin(b)), hi = cellOf(a.cwiseMax(b));
        for (int z = lo.z(); z <= hi.z(); ++z)
            for (int y = lo.y(); y <= hi.y(); ++y)
                for (int x = lo.x(); x <= hi.x(); ++x)
                    binned[std::size_t(x + cells.x() * (y + cells.y() * z))].push_back(s);
    };
    for (std::size_t t = 0; t < g.terminals.size(); ++t)
    {
        const Eigen::Vector3d& p = g.terminals[t];
        node.push_back(p);
        const int tip = int(node.size()) - 1;
        if (segment.empty())
        {
            segment.push_back({0, tip}), endsAt.push_back(int(t));
            bin(0, node[0], p);
            continue;
        }
        int best = -1;
        double bestDistance = 1e300, bestAt = 0.0;
        const Eigen::Vector3i centre = cellOf(p);
        for (int shell = 0; shell <= cells.maxCoeff() && !(best >= 0 && bestDistance <= (shell - 1) * cell); ++shell)
            for (int z = centre.z() - shell; z <= centre.z() + shell; ++z)
                for (int y = centre.y() - shell; y <= centre.y() + shell; ++y)
                    for (int x = centre.x() - shell; x <= centre.x() + shell; ++x)
                    {
                        if (std::max({std::abs(x - centre.x()), std::abs(y - centre.y()), std::abs(z - centre.z())}) != shell ||
                            x < 0 || y < 0 || z < 0 || x >= cells.x() || y >= cells.y() || z >= cells.z())
                            continue;
                        for (int s : binned[std::size_t(x + cells.x() * (y + cells.y() * z))])
                        {
                            const Eigen::Vector3d a = node[std::size_t(segment[std::size_t(s)][0])];
                            const Eigen::Vector3d b = node[std::size_t(segment[std::size_t(s)][1])];
                            const double at = std::clamp((p - a).dot(b - a) / std::max(1e-12, (b - a).squaredNorm()), 0.1, 0.9);
                            const double d = (a + at * (b - a) - p).norm();
                            if (d < bestDistance || (d == bestDistance && s < best))
                                bestDistance = d, best = s, bestAt = at;
                        }
                    }
        const auto [a, b] = segment[std::size_t(best)];
        node.push_back(node[std::size_t(a)] + bestAt * (node[std::size_t(b)] - node[std::size_t(a)]));
        const int joint = int(node.size()) - 1;
        segment[std::size_t(best)] = {a, joint};
        const int oldEnd = endsAt[std::size_t(best)];
        endsAt[std::size_t(best)] = -1;
        segment.push_back({joint, b}), endsAt.push_back(oldEnd);
        bin(int(segment.size()) - 1, node[std::size_t(joint)], node[std::size_t(b)]);
        segment.push_back({joint, tip}), endsAt.push_back(int(t));
        bin(int(segment.size()) - 1, node[std::size_t(joint)], p);
    }
    // Terminals downstream of each segment, and each node's parent segment.
    std::vector<int> parentOf(node.size(), -1);
    std::vector<std::vector<int>> children(node.size());
    for (std::size_t s = 0; s < segment.size(); ++s)
        parentOf[std::size_t(segment[s][1])] = int(s), children[std::size_t(segment[s][0])].push_back(int(s));
    std::vector<int> count(segment.size(), 0);
    std::vector<int> order; // segments, parents before children
    std::vector<int> stack{children[0].front()};
    while (!stack.empty())
    {
        const int s = stack.back();
        stack.pop_back();
        order.push_back(s);
        for (int c : children[std::size_t(segment[std::size_t(s)][1])])
            stack.push_back(c);
    }
    for (auto s = order.rbegin(); s != order.rend(); ++s)
    {
        count[std::size_t(*s)] += endsAt[std::size_t(*s)] >= 0 ? 1 : 0;
        for (int c : children[std::size_t(segment[std::size_t(*s)][1])])
            count[std::size_t(*s)] += count[std::size_t(c)];
    }
    auto radius = [&](int s) { return o.rootRadiusMm * std::cbrt(double(count[std::size_t(s)]) / double(o.terminals)); };
    auto visible = [&](int s) { return radius(s) >= o.visibleRadiusMm; };

    // Visible chains merged: from the root and every visible junction along single visible children.
    std::vector<int> merged(segment.size(), -1), visibleNode(node.size(), -1);
    auto networkNode = [&](int n) {
        if (visibleNode[std::size_t(n)] < 0)
        {
            visibleNode[std::size_t(n)] = int(g.visible.nodes.size());
            g.visible.nodes.push_back({node[std::size_t(n)], {}});
        }
        return visibleNode[std::size_t(n)];
    };
    std::vector<int> starts{children[0].front()};
    while (!starts.empty())
    {
        int s = starts.back();
        starts.pop_back();
        VesselNetwork::Segment v;
        v.from = networkNode(segment[std::size_t(s)][0]);
        v.startRadiusMm = radius(s);
        v.pathMm.push_back(node[std::size_t(segment[std::size_t(s)][0])]);
        const int id = int(g.visible.segments.size());
        while (true)
        {
            merged[std::size_t(s)] = id;
            const int end = segment[std::size_t(s)][1];
            v.pathMm.push_back(node[std::size_t(end)]);
            v.endRadiusMm = radius(s);
            std::vector<int> next;
            for (int c : children[std::size_t(end)])
                if (visible(c))
                    next.push_back(c);
            if (next.size() == 1)
            {
                s = next.front();
                continue;
            }
            v.to = networkNode(end);
            for (int c : next)
                starts.push_back(c);
            break;
        }
        for (std::size_t p = 0; p + 1 < v.pathMm.size(); ++p)
            v.lengthMm += (v.pathMm[p + 1] - v.pathMm[p]).norm();
        g.visible.segments.push_back(v);
    }
    g.visible.root = visibleNode[0];
    // Each terminal's visible ancestor: up from its segment to the first visible one.
    g.ancestor.assign(g.terminals.size(), -1);
    g.inTumour.assign(g.terminals.size(), 0);
    for (std::size_t s = 0; s < segment.size(); ++s)
        if (endsAt[s] >= 0)
        {
            int up = int(s);
            while (merged[std::size_t(up)] < 0)
                up = parentOf[std::size_t(segment[std::size_t(up)][0])];
            g.ancestor[std::size_t(endsAt[s])] = merged[std::size_t(up)];
            g.inTumour[std::size_t(endsAt[s])] = inTumour(g.terminals[std::size_t(endsAt[s])]) ? 1 : 0;
        }
    g.visible.validate();
    return g;
}

/// Per liver voxel (the order of LiverTerritories::voxels: ascending linear index), the visible segment whose
/// hidden terminals perfuse it: the voxel's nearest terminal's ancestor.
inline std::vector<int> truthFeedingSegment(const GrownTree& g, const std::vector<std::size_t>& voxels)
{
    const NearestPoint nearest(g.terminals, 2.0);
    const VolumeGeometry& geometry = g.liver.geometry();
    const std::size_t nx = std::size_t(geometry.dims[0]), ny = std::size_t(geometry.dims[1]);
    std::vector<int> feeding(voxels.size());
    for (std::size_t v = 0; v < voxels.size(); ++v)
    {
        const std::size_t l = voxels[v];
        const Eigen::Vector3d p = geometry.indexToPatient(Eigen::Vector3d(double(l % nx), double((l / nx) % ny), double(l / (nx * ny))));
        feeding[v] = g.ancestor[std::size_t(nearest.nearest(p))];
    }
    return feeding;
}

} // namespace vsim::test
