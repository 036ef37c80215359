#include "vsim/sim/network/Targeting.h"

#include "vsim/core/Error.h"
#include "vsim/core/Localized.h"

#include <algorithm>
#include <cmath>

namespace vsim::sim::network {

std::function<bool(const Eigen::Vector3d&)> TumourSphere::region() const
{
    if (!(radiusMm > 0.0))
        throw Error("the tumour's radius must be positive");
    return [sphere = *this](const Eigen::Vector3d& p) { return sphere.contains(p); };
}

std::vector<int> feedingOutlets(const VesselNetwork& network, const std::function<bool(const Eigen::Vector3d&)>& inside)
{
    std::vector<int> feeders;
    for (int node : network.endNodes())
        if (node != network.root && inside(network.nodes[std::size_t(node)].positionMm))
            feeders.push_back(node);
    return feeders;
}

double deliveredFraction(const FlowSolution& flow, const std::vector<int>& outlets)
{
    double delivered = 0.0;
    for (int outlet : outlets)
    {
        const auto found = flow.outletInjectate.find(outlet);
        if (found != flow.outletInjectate.end() && found->second > 0.0)
            delivered += found->second;
    }
    return flow.injectedFlow > 0.0 ? delivered / flow.injectedFlow : 0.0;
}

std::vector<TipCandidate> tipCandidates(const VesselNetwork& network)
{
    const std::vector<std::vector<int>> incident = network.incidentSegments();
    std::vector<int> depth(network.nodes.size(), 0);
    if (network.root >= 0)
    {
        const TipOrientation fromRoot = orientFromTip(network, network.root);
        for (int node : fromRoot.order)
            if (node != network.root)
            {
                const int parent = fromRoot.upstreamNode[std::size_t(fromRoot.parentSegment[std::size_t(node)])];
                depth[std::size_t(node)] = depth[std::size_t(parent)] + 1;
            }
    }
    std::vector<TipCandidate> candidates;
    for (std::size_t n = 0; n < network.nodes.size(); ++n)
        if (incident[n].size() >= 2 || int(n) == network.root)
        {
            TipCandidate candidate;
            candidate.node = int(n);
            candidate.depth = depth[n];
            for (int s : incident[n])
            {
                const auto& segment = network.segments[std::size_t(s)];
                candidate.radiusMm = std::max(candidate.radiusMm, segment.from == int(n) ? segment.startRadiusMm : segment.endRadiusMm);
            }
            candidates.push_back(candidate);
        }
    return candidates;
}

std::vector<TipCandidate> rankTipPositions(const VesselNetwork& network, const std::vector<int>& feeders,
                                           const TipSolve& solve, const Progress& progress)
{
    std::vector<TipCandidate> ranking = tipCandidates(network);
    for (std::size_t i = 0; i < ranking.size(); ++i)
    {
        progress.throwIfCancelled();
        ranking[i].tumourFraction = deliveredFraction(solve(ranking[i].node), feeders);
        progress.report(double(i + 1) / double(ranking.size()), localized("vsim::Progress", "ranking catheter positions"));
    }
    std::stable_sort(ranking.begin(), ranking.end(), [](const TipCandidate& a, const TipCandidate& b) {
        if (std::abs(a.tumourFraction - b.tumourFraction) > 1e-9)
            return a.tumourFraction > b.tumourFraction;
        return a.depth < b.depth;
    });
    return ranking;
}

} // namespace vsim::sim::network
