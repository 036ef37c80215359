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
            throw Error("node " + std::to_string(n) + " has a position that is not a number", {{"node", std::to_string(n)}});
    std::vector<int> parent(nodes.size());
    std::iota(parent.begin(), parent.end(), 0);
    for (std::size_t s = 0; s < segments.size(); ++s)
    {
        const Segment& segment = segments[s];
        const Error::Context where{{"segment", std::to_string(s)}};
        if (segment.from < 0 || segment.from >= nodeCount || segment.to < 0 || segment.to >= nodeCount)
            throw Error(segmentName(s) + " refers to a node that does not exist", where);
        if (segment.from == segment.to)
            throw Error(segmentName(s) + " starts and ends at node " + std::to_string(segment.from), where);
        if (!(segment.lengthMm > 0.0) || !std::isfinite(segment.lengthMm))
            throw Error(segmentName(s) + " has a length that is not positive", where);
        if (!(segment.resistance >= 0.0) || !std::isfinite(segment.resistance))
            throw Error(segmentName(s) + " has a negative or invalid resistance", where);
        if (!(segment.startRadiusMm > 0.0) || !(segment.endRadiusMm > 0.0) || !std::isfinite(segment.startRadiusMm) ||
            !std::isfinite(segment.endRadiusMm))
            throw Error(segmentName(s) + " has a radius that is zero or negative (" + std::to_string(segment.startRadiusMm) +
                            ", " + std::to_string(segment.endRadiusMm) + " mm)",
                        where);
        const int a = findSet(parent, segment.from), b = findSet(parent, segment.to);
        if (a == b)
            throw Error(segmentName(s) + " (nodes " + std::to_string(segment.from) + " - " + std::to_string(segment.to) +
                            ") closes a cycle: the network must be a tree",
                        where);
        parent[std::size_t(a)] = b;
    }
    for (const Outlet& outlet : outlets)
    {
        if (outlet.node < 0 || outlet.node >= nodeCount)
            throw Error("an outlet condition names node " + std::to_string(outlet.node) + ", which does not exist");
        const Error::Context where{{"node", std::to_string(outlet.node)}};
        if (!std::isfinite(outlet.pressurePa))
            throw Error("the outlet at node " + std::to_string(outlet.node) + " has a pressure that is not a number", where);
        if (outlet.type == Outlet::Type::Resistance && (!(outlet.resistance >= 0.0) || !std::isfinite(outlet.resistance)))
            throw Error("the outlet at node " + std::to_string(outlet.node) + " has a negative or invalid resistance", where);
    }
    if (root >= nodeCount || root < -1)
        throw Error("the network's root is node " + std::to_string(root) + ", which does not exist");
    for (const auto& [name, values] : segmentFields)
        if (values.size() != segments.size())
            throw Error("segment field '" + name + "' has " + std::to_string(values.size()) + " values for " +
                        std::to_string(segments.size()) + " segments");
}

} // namespace vsim
