#include "vsim/sim/network/Inlet.h"

#include "vsim/core/Error.h"
#include "vsim/sim/network/NetworkBuild.h"
#include "vsim/sim/network/TipOrientation.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>
#include <sstream>

namespace vsim::sim::network
{
namespace
{

std::string lowered(std::string text)
{
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return text;
}

/// Nodes from the root to the segment's upper end: how far a segment lies from the root (in junctions).
int depthOf(const TipOrientation& fromRoot, int segment)
{
    int depth = 0;
    for (int n = fromRoot.upstreamNode[std::size_t(segment)]; n != fromRoot.tip;
         n = fromRoot.upstreamNode[std::size_t(fromRoot.parentSegment[std::size_t(n)])])
        ++depth;
    return depth;
}

} // namespace

VesselNetwork treeBeyond(const VesselNetwork& network, int segment, std::vector<int>* nodeMap)
{
    if (segment < 0 || std::size_t(segment) >= network.segments.size())
        throw Error(Pattern{"the inlet segment %1 does not exist (the tree has %2 segments)",
                            {std::to_string(segment), std::to_string(network.segments.size())}});
    const int root = network.root >= 0 ? network.root : largestEnd(network);
    const TipOrientation fromRoot = orientFromTip(network, root);
    const int upper = fromRoot.upstreamNode[std::size_t(segment)];
    const VesselNetwork::Segment& inlet = network.segments[std::size_t(segment)];
    const int lower = inlet.from == upper ? inlet.to : inlet.from;
    // The nodes beyond: the lower end and everything downstream of it.
    std::vector<char> keepNode(network.nodes.size(), 0);
    keepNode[std::size_t(upper)] = keepNode[std::size_t(lower)] = 1;
    std::vector<char> keepSegment(network.segments.size(), 0);
    keepSegment[std::size_t(segment)] = 1;
    for (int node : fromRoot.order) // parents before children
        if (node != root && node != lower)
        {
            const int parent = fromRoot.parentSegment[std::size_t(node)];
            if (keepNode[std::size_t(fromRoot.upstreamNode[std::size_t(parent)])] &&
                fromRoot.upstreamNode[std::size_t(parent)] != upper)
                keepNode[std::size_t(node)] = 1, keepSegment[std::size_t(parent)] = 1;
        }
    VesselNetwork out;
    std::vector<int> map(network.nodes.size(), -1);
    for (std::size_t n = 0; n < network.nodes.size(); ++n)
        if (keepNode[n])
            map[n] = int(out.nodes.size()), out.nodes.push_back(network.nodes[n]);
    std::vector<std::size_t> kept;
    for (std::size_t s = 0; s < network.segments.size(); ++s)
        if (keepSegment[s])
        {
            VesselNetwork::Segment copy = network.segments[s];
            copy.from = map[std::size_t(copy.from)];
            copy.to = map[std::size_t(copy.to)];
            out.segments.push_back(copy);
            kept.push_back(s);
        }
    for (const auto& [name, values] : network.segmentFields)
    {
        std::vector<double>& field = out.segmentFields[name];
        for (std::size_t s : kept)
            field.push_back(values[s]);
    }
    for (const VesselNetwork::Outlet& outlet : network.outlets)
        if (map[std::size_t(outlet.node)] >= 0 && outlet.node != upper)
        {
            VesselNetwork::Outlet copy = outlet;
            copy.node = map[std::size_t(outlet.node)];
            out.outlets.push_back(copy);
        }
    out.root = map[std::size_t(upper)];
    out.validate();
    if (nodeMap)
        *nodeMap = std::move(map);
    return out;
}

int inletSegment(const VesselNetwork& network, const std::string& text)
{
    if (std::count(text.begin(), text.end(), ',') == 2) // a point on the vessel
    {
        Eigen::Vector3d point;
        std::stringstream stream(text);
        std::string item;
        for (int a = 0; a < 3; ++a)
        {
            std::getline(stream, item, ',');
            try
            {
                point[a] = std::stod(item);
            }
            catch (const std::exception&)
            {
                throw Error(Pattern{"the inlet '%1' is not a point x,y,z (mm)", {text}});
            }
        }
        const auto [segment, distance] = nearestSegment(network, point);
        if (segment < 0 || distance > kInletReachMm)
            throw Error(Pattern{"the inlet point %1 lies %2 mm from the nearest vessel (at most %3 mm)",
                                {text, std::to_string(int(std::lround(distance))),
                                 std::to_string(int(kInletReachMm))}});
        return segment;
    }
    if (!text.empty() &&
        std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isdigit(c); }))
    {
        const int segment = std::stoi(text);
        if (std::size_t(segment) >= network.segments.size())
            throw Error(Pattern{"the inlet segment %1 does not exist (the tree has %2 segments)",
                                {text, std::to_string(network.segments.size())}});
        return segment;
    }
    const TipOrientation fromRoot =
        orientFromTip(network, network.root >= 0 ? network.root : largestEnd(network));
    int best = -1, bestDepth = 0;
    std::set<std::string> names;
    for (std::size_t s = 0; s < network.segments.size(); ++s)
    {
        const std::string& name = network.segments[s].name;
        if (name.empty())
            continue;
        names.insert(name);
        if (lowered(name) != lowered(text) || !fromRoot.active(int(s)))
            continue;
        if (const int depth = depthOf(fromRoot, int(s)); best < 0 || depth < bestDepth)
            best = int(s), bestDepth = depth;
    }
    if (best >= 0)
        return best;
    std::string known;
    for (const std::string& name : names)
        known += (known.empty() ? "" : ", ") + name;
    throw Error(Pattern{"no segment of the tree is named '%1'%2",
                        {text, (known.empty() ? std::string(" (the tree has no named segments: give a segment number)")
                               : " (its named segments: " + known + ")")}});
}

} // namespace vsim::sim::network
