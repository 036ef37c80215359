#include "vsim/core/VesselNetwork.h"

#include "vsim/core/Error.h"

#include <cmath>
#include <numeric>

namespace vsim {
namespace {

std::string segmentName(std::size_t index) { return "segment " + std::to_string(index); }

/// Union-find root with path halving.
int findSet(std::vector<int>& parent, int x)
{
    while (parent[std::size_t(x)] != x)
        x = parent[std::size_t(x)] = parent[std::size_t(parent[std::size_t(x)])];
    return x;
}

} // namespace

std::vector<Eigen::Vector3d> VesselNetwork::segmentPath(std::size_t segment) const
{
    const Segment& s = segments.at(segment);
    if (s.pathMm.size() >= 2)
        return s.pathMm;
    return {nodes.at(std::size_t(s.from)).positionMm, nodes.at(std::size_t(s.to)).positionMm};
}

std::vector<std::vector<int>> VesselNetwork::incidentSegments() const
{
    std::vector<std::vector<int>> incident(nodes.size());
    for (std::size_t s = 0; s < segments.size(); ++s)
    {
        incident[std::size_t(segments[s].from)].push_back(int(s));
        incident[std::size_t(segments[s].to)].push_back(int(s));
    }
    return incident;
}

std::vector<int> VesselNetwork::endNodes() const
{
    std::vector<int> ends;
    const std::vector<std::vector<int>> incident = incidentSegments();
    for (std::size_t n = 0; n < nodes.size(); ++n)
        if (incident[n].size() == 1)
            ends.push_back(int(n));
    return ends;
}

void VesselNetwork::validate() const
{
    const int nodeCount = int(nodes.size());
    for (std::size_t n = 0; n < nodes.size(); ++n)
        if (!nodes[n].positionMm.allFinite())
            throw Error(Pattern{"node %1 has a position that is not a number",
                                {std::to_string(n)}}, {{"node", std::to_string(n)}});
    std::vector<int> parent(nodes.size());
    std::iota(parent.begin(), parent.end(), 0);
    for (std::size_t s = 0; s < segments.size(); ++s)
    {
        const Segment& segment = segments[s];
        const Error::Context where{{"segment", std::to_string(s)}};
        if (segment.from < 0 || segment.from >= nodeCount || segment.to < 0 || segment.to >= nodeCount)
            throw Error(Pattern{"%1 refers to a node that does not exist", {segmentName(s)}}, where);
        if (segment.from == segment.to)
            throw Error(Pattern{"%1 starts and ends at node %2",
                                {segmentName(s), std::to_string(segment.from)}}, where);
        if (!(segment.lengthMm > 0.0) || !std::isfinite(segment.lengthMm))
            throw Error(Pattern{"%1 has a length that is not positive", {segmentName(s)}}, where);
        if (!(segment.resistance >= 0.0) || !std::isfinite(segment.resistance))
            throw Error(Pattern{"%1 has a negative or invalid resistance", {segmentName(s)}}, where);
        if (!(segment.startRadiusMm > 0.0) || !(segment.endRadiusMm > 0.0) || !std::isfinite(segment.startRadiusMm) ||
            !std::isfinite(segment.endRadiusMm))
            throw Error(Pattern{"%1 has a radius that is zero or negative (%2, %3 mm)",
                                {segmentName(s), std::to_string(segment.startRadiusMm),
                                 std::to_string(segment.endRadiusMm)}},
                        where);
        const int a = findSet(parent, segment.from), b = findSet(parent, segment.to);
        if (a == b)
            throw Error(Pattern{"%1 (nodes %2 - %3) closes a cycle: the network must be a tree",
                                {segmentName(s), std::to_string(segment.from), std::to_string(segment.to)}},
                        where);
        parent[std::size_t(a)] = b;
    }
    for (const Outlet& outlet : outlets)
    {
        if (outlet.node < 0 || outlet.node >= nodeCount)
            throw Error(Pattern{"an outlet condition names node %1, which does not exist",
                                {std::to_string(outlet.node)}});
        const Error::Context where{{"node", std::to_string(outlet.node)}};
        if (!std::isfinite(outlet.pressurePa))
            throw Error(Pattern{"the outlet at node %1 has a pressure that is not a number",
                                {std::to_string(outlet.node)}}, where);
        if (outlet.type == Outlet::Type::Resistance && (!(outlet.resistance >= 0.0) || !std::isfinite(outlet.resistance)))
            throw Error(Pattern{"the outlet at node %1 has a negative or invalid resistance",
                                {std::to_string(outlet.node)}}, where);
    }
    if (root >= nodeCount || root < -1)
        throw Error(Pattern{"the network's root is node %1, which does not exist", {std::to_string(root)}});
    for (const auto& [name, values] : segmentFields)
        if (values.size() != segments.size())
            throw Error(Pattern{"segment field '%1' has %2 values for %3 segments",
                                {name, std::to_string(values.size()), std::to_string(segments.size())}});
}

} // namespace vsim
