#include "vsim/sim/network/TipOrientation.h"

#include "vsim/core/Error.h"

#include <string>

namespace vsim::sim::network {
namespace {

/// The segment at `from` on the path to `to` (breadth-first over the tree), -1 when they are not connected.
int firstSegmentTowards(const VesselNetwork& network, const std::vector<std::vector<int>>& incident, int from, int to)
{
    if (from == to)
        return -1;
    std::vector<int> via(network.nodes.size(), -2); // segment by which a node was reached from `to`
    std::vector<int> queue{to};
    via[std::size_t(to)] = -1;
    for (std::size_t head = 0; head < queue.size(); ++head)
    {
        const int node = queue[head];
        for (int s : incident[std::size_t(node)])
        {
            const auto& segment = network.segments[std::size_t(s)];
            const int other = segment.from == node ? segment.to : segment.from;
            if (via[std::size_t(other)] != -2)
                continue;
            via[std::size_t(other)] = s;
            if (other == from)
                return s; // the segment by which `from` is reached from `to` leads from `from` towards `to`
            queue.push_back(other);
        }
    }
    return -2;
}

} // namespace

TipOrientation orientFromTip(const VesselNetwork& network, int tip)
{
    if (tip < 0 || tip >= int(network.nodes.size()))
        throw Error(Pattern{"the catheter tip is node %1, which is not in the network", {std::to_string(tip)}});
    const std::vector<std::vector<int>> incident = network.incidentSegments();
    int excluded = -1;
    if (network.root >= 0 && network.root != tip)
    {
        excluded = firstSegmentTowards(network, incident, tip, network.root);
        if (excluded == -2)
            throw Error(Pattern{"the catheter tip (node %1) is on a part of the network that is not connected to its "
                                "root",
                                {std::to_string(tip)}},
                        {{"node", std::to_string(tip)}});
    }
    TipOrientation o;
    o.tip = tip;
    o.parentSegment.assign(network.nodes.size(), -1);
    o.upstreamNode.assign(network.segments.size(), -1);
    std::vector<char> seen(network.nodes.size(), 0);
    seen[std::size_t(tip)] = 1;
    o.order.push_back(tip);
    for (std::size_t head = 0; head < o.order.size(); ++head)
    {
        const int node = o.order[head];
        int children = 0;
        for (int s : incident[std::size_t(node)])
        {
            if (s == excluded)
                continue;
            const auto& segment = network.segments[std::size_t(s)];
            const int other = segment.from == node ? segment.to : segment.from;
            if (seen[std::size_t(other)])
                continue;
            seen[std::size_t(other)] = 1;
            o.upstreamNode[std::size_t(s)] = node;
            o.parentSegment[std::size_t(other)] = s;
            o.order.push_back(other);
            ++children;
        }
        if (children == 0 && node != tip)
            o.outlets.push_back(node);
    }
    if (o.order.size() == 1)
        throw Error(Pattern{"nothing is downstream of the catheter tip (node %1 is an end of the tree): place it "
                            "nearer the root (node %2)",
                            {std::to_string(tip), std::to_string(network.root)}},
                    {{"node", std::to_string(tip)}});
    return o;
}

int largestEnd(const VesselNetwork& network)
{
    int best = -1;
    double largest = -1.0;
    const std::vector<std::vector<int>> incident = network.incidentSegments();
    for (std::size_t n = 0; n < network.nodes.size(); ++n)
    {
        if (incident[n].size() != 1)
            continue;
        const auto& segment = network.segments[std::size_t(incident[n].front())];
        const double radius = segment.from == int(n) ? segment.startRadiusMm : segment.endRadiusMm;
        if (radius > largest)
            largest = radius, best = int(n);
    }
    return best;
}

} // namespace vsim::sim::network
