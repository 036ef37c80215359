#include "vsim/sim/network/DrugMixing.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace vsim::sim::network {

double InjectateBalance::relativeError() const
{
    return injected > 0.0 ? std::abs(injected - leftAtOutlets - leftAtSources) / injected : 0.0;
}

InjectateBalance mixInjectate(const VesselNetwork& network, FlowSolution& flow, const std::vector<NodeSource>& sources,
                              std::size_t injection)
{
    const std::size_t nodeCount = network.nodes.size();
    std::vector<double> inflow(nodeCount, 0.0), injected(nodeCount, 0.0); // m^3/s entering from outside; of it injected
    std::vector<double> drawnOut(nodeCount, 0.0); // m^3/s leaving a source node back through its source
    InjectateBalance balance;
    for (std::size_t i = 0; i < sources.size(); ++i)
    {
        const double q = flow.sourceFlow[i];
        const std::size_t node = std::size_t(sources[i].node);
        if (q > 0.0)
        {
            inflow[node] += q;
            if (i == injection)
                injected[node] += q, balance.injected = q;
        }
        else
            drawnOut[node] -= q;
    }
    for (const auto& [outlet, q] : flow.outletFlow)
        if (q < 0.0)
            inflow[std::size_t(outlet)] -= q; // blood entering through an outlet held above the tree's pressure

    std::vector<std::vector<int>> entering(nodeCount), leaving(nodeCount); // segments by the direction of their flow
    for (std::size_t s = 0; s < network.segments.size(); ++s)
    {
        const double q = flow.segmentFlow[s];
        if (q == 0.0)
            continue;
        const auto& segment = network.segments[s];
        entering[std::size_t(q > 0.0 ? segment.to : segment.from)].push_back(int(s));
        leaving[std::size_t(q > 0.0 ? segment.from : segment.to)].push_back(int(s));
    }
    std::vector<int> byPressure(nodeCount);
    std::iota(byPressure.begin(), byPressure.end(), 0);
    std::stable_sort(byPressure.begin(), byPressure.end(), [&](int a, int b) {
        return flow.nodePressure[std::size_t(a)] > flow.nodePressure[std::size_t(b)];
    });
    flow.injectateFraction.assign(network.segments.size(), 0.0);
    flow.outletInjectate.clear();
    for (int node : byPressure)
    {
        const std::size_t n = std::size_t(node);
        double in = inflow[n], carried = injected[n];
        for (int s : entering[n])
        {
            const double q = std::abs(flow.segmentFlow[std::size_t(s)]);
            in += q;
            carried += q * flow.injectateFraction[std::size_t(s)];
        }
        const double fraction = in > 0.0 ? std::min(1.0, carried / in) : 0.0;
        for (int s : leaving[n])
            flow.injectateFraction[std::size_t(s)] = fraction;
        balance.leftAtSources += fraction * drawnOut[n];
        if (const auto outlet = flow.outletFlow.find(node); outlet != flow.outletFlow.end())
        {
            flow.outletInjectate[node] = fraction * std::max(0.0, outlet->second);
            balance.leftAtOutlets += flow.outletInjectate[node];
        }
    }
    return balance;
}

} // namespace vsim::sim::network
