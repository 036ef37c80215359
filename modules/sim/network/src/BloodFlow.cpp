#include "vsim/sim/network/BloodFlow.h"

#include "vsim/core/Error.h"
#include "vsim/core/StoredText.h"
#include "vsim/core/Units.h"
#include "vsim/sim/network/ConicalPipe.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vsim::sim::network {
namespace {

/// Flow (m^3/s) through the tip's own vessel towards the tip: the segment from the tip towards the inlet.
double flowTowardsTip(const VesselNetwork& network, const TipOrientation& fromRoot, const FlowSolution& flow, int tip)
{
    const int s = fromRoot.parentSegment[std::size_t(tip)];
    const double q = flow.segmentFlow[std::size_t(s)];
    return network.segments[std::size_t(s)].to == tip ? q : -q;
}

/// Resistance of a segment for a fluid of `viscosity`, around a catheter of radius `catheter` (m; 0: none). An
/// explicit resistance is scaled by the annulus's share of the open cone's.
double resistanceAround(const VesselNetwork::Segment& segment, double viscosity, double catheter)
{
    if (!(catheter > 0.0))
        return segmentResistance(segment, viscosity);
    const double r1 = units::mmToM(segment.startRadiusMm), r2 = units::mmToM(segment.endRadiusMm);
    const double length = units::mmToM(segment.lengthMm);
    const double annulus = annularResistance(r1, r2, catheter, length, viscosity);
    return segment.resistance > 0.0 ? segment.resistance * annulus / conicalResistance(r1, r2, length, viscosity) : annulus;
}

} // namespace

BloodFlowSolution solveBloodFlow(const VesselNetwork& network, const BloodFlowSetup& setup)
{
    if (!(setup.injectionRate > 0.0 && std::isfinite(setup.injectionRate)))
        throw Error("the injection rate must be positive");
    if (!setup.inletHeldAtPressure && !(setup.inletRate > 0.0 && std::isfinite(setup.inletRate)))
        throw Error("the arterial inflow must be positive");
    if (!(setup.catheterRadius >= 0.0) || !(setup.bloodViscosity > 0.0) || !(setup.injectateViscosity > 0.0))
        throw Error("the catheter's radius and the viscosities must be positive");
    const TipOrientation fromRoot = orientFromTip(network, network.root);
    const TipOrientation fromTip = orientFromTip(network, setup.tipNode); // refuses a tip off the tree
    const int tip = setup.tipNode, root = network.root;

    BloodFlowSolution result;
    std::vector<double> catheter(network.segments.size(), 0.0); // m, the catheter's radius in each segment
    for (int node = tip; node != root;)
    {
        const int s = fromRoot.parentSegment[std::size_t(node)];
        result.catheterSegments.insert(result.catheterSegments.begin(), s);
        catheter[std::size_t(s)] = setup.catheterRadius;
        node = fromRoot.upstreamNode[std::size_t(s)];
    }
    const NodeSource inlet{root, setup.inletRate, setup.inletHeldAtPressure, setup.inletPressure};
    auto resistances = [&](const std::vector<double>& fraction) {
        std::vector<double> r(network.segments.size());
        result.segmentViscosity.resize(network.segments.size());
        for (std::size_t s = 0; s < network.segments.size(); ++s)
        {
            result.segmentViscosity[s] = setup.bloodViscosity + fraction[s] * (setup.injectateViscosity - setup.bloodViscosity);
            r[s] = resistanceAround(network.segments[s], result.segmentViscosity[s], catheter[s]);
        }
        return r;
    };

    // The vessel's own flow at the tip: blood alone, the catheter in place.
    const std::vector<double> blood(network.segments.size(), 0.0);
    const FlowSolution own = solveNodalFlow(network, fromRoot, resistances(blood), {inlet});
    result.ownFlow = tip == root ? own.sourceFlow.front() : flowTowardsTip(network, fromRoot, own, tip);

    const std::vector<NodeSource> sources{inlet, {tip, setup.injectionRate, false, 0.0}};
    std::vector<double> fraction = blood;
    for (result.iterations = 1; result.iterations <= setup.maxIterations; ++result.iterations)
    {
        result.flow = solveNodalFlow(network, fromRoot, resistances(fraction), sources);
        result.balance = mixInjectate(network, result.flow, sources, 1);
        result.residual = 0.0;
        for (std::size_t s = 0; s < fraction.size(); ++s)
            result.residual = std::max(result.residual, std::abs(result.flow.injectateFraction[s] - fraction[s]));
        fraction = result.flow.injectateFraction;
        if (result.residual <= setup.tolerance)
        {
            result.converged = true;
            break;
        }
    }
    result.iterations = std::min(result.iterations, setup.maxIterations);

    FlowSolution& flow = result.flow;
    result.inletFlow = flow.sourceFlow.front();
    result.tipInflow = tip == root ? result.inletFlow : flowTowardsTip(network, fromRoot, flow, tip);
    flow.orientation = fromTip;
    flow.injectedFlow = flow.sourceFlow.back();
    flow.tipPressure = flow.nodePressure[std::size_t(tip)];
    for (std::size_t s = 0; s < network.segments.size(); ++s)
        if (fromTip.upstreamNode[s] == tip)
            result.tipFraction = std::max(result.tipFraction, flow.injectateFraction[s]);
    double downstream = 0.0;
    for (int outlet : fromTip.outlets)
        downstream += flow.outletInjectate[outlet];
    result.refluxShare = result.balance.injected > 0.0 ? std::max(0.0, 1.0 - downstream / result.balance.injected) : 0.0;

    // The lumen at the tip: the tip's own vessel at its end there (at the inlet: the first vessel).
    const int tipVessel = tip == root ? network.incidentSegments()[std::size_t(root)].front()
                                      : fromRoot.parentSegment[std::size_t(tip)];
    const auto& vessel = network.segments[std::size_t(tipVessel)];
    const double lumen = units::mmToM(vessel.to == tip ? vessel.endRadiusMm : vessel.startRadiusMm);
    result.occlusion = std::min(1.0, std::pow(setup.catheterRadius / lumen, 2));
    auto mlMin = [](double q) { return std::to_string(units::m3PerSToMlPerMin(q)).substr(0, 6); };
    if (setup.injectionRate >= result.ownFlow)
        result.wedgedBecause = storedText(Pattern{"the injection (%1 ml/min) is at least the vessel's own flow at the "
                                                  "tip (%2 ml/min)",
                                                  {mlMin(setup.injectionRate), mlMin(result.ownFlow)}});
    if (result.occlusion >= kWedgeOcclusion)
        result.wedgedBecause += std::string(result.wedgedBecause.empty() ? "" : "; ") +
                                storedText(Pattern{"the catheter fills %1 % of the lumen at the tip",
                                                   {std::to_string(int(std::lround(100.0 * result.occlusion)))}});
    result.wedged = !result.wedgedBecause.empty();
    return result;
}

} // namespace vsim::sim::network
