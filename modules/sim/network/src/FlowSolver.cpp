#include "vsim/sim/network/FlowSolver.h"

#include "vsim/core/Error.h"
#include "vsim/core/Units.h"
#include "vsim/sim/network/ConicalPipe.h"

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <string>

namespace vsim::sim::network {

namespace {

/// Long double throughout the nodal system: the conductances of a vessel tree span ten orders of magnitude (a wide
/// artery in series with a terminal bed), and in double the bed's conductance added to a node's diagonal keeps only
/// a few digits, which left outlet splits off by 1e-5 and Kirchhoff's law unbalanced by 1e-11 of the flow.
using Real = long double;

} // namespace

double segmentResistance(const VesselNetwork::Segment& segment, double viscosity)
{
    if (segment.resistance > 0.0)
        return segment.resistance;
    return conicalResistance(units::mmToM(segment.startRadiusMm), units::mmToM(segment.endRadiusMm),
                             units::mmToM(segment.lengthMm), viscosity);
}

FlowSolution solveNodalFlow(const VesselNetwork& network, const TipOrientation& o, const std::vector<double>& resistance,
                            const std::vector<NodeSource>& sources)
{
    FlowSolution solution;
    solution.orientation = o;
    auto open = [&](std::size_t s) { return o.active(int(s)) && resistance[s] > 0.0 && std::isfinite(resistance[s]); };

    // Unknowns: the pressures of the reached nodes that are not held at a pressure and have an open segment.
    std::vector<const VesselNetwork::Outlet*> conditions(network.nodes.size(), nullptr);
    for (const VesselNetwork::Outlet& outlet : network.outlets)
        conditions[std::size_t(outlet.node)] = &outlet;
    for (int outlet : o.outlets)
        if (!conditions[std::size_t(outlet)])
            throw Error(Pattern{"outlet node %1 has no boundary condition (a pressure or a terminal resistance)",
                                {std::to_string(outlet)}},
                        {{"node", std::to_string(outlet)}});
    std::vector<char> isSource(network.nodes.size(), 0), connected(network.nodes.size(), 0);
    std::vector<double> fixedPressure(network.nodes.size(), std::nan(""));
    for (const NodeSource& source : sources)
    {
        isSource[std::size_t(source.node)] = 1;
        if (source.heldAtPressure)
            fixedPressure[std::size_t(source.node)] = source.pressure;
    }
    for (int node : o.order) // a pressure, or a terminal resistance of zero, holds the node at the pressure
        if (const VesselNetwork::Outlet* c = conditions[std::size_t(node)];
            !isSource[std::size_t(node)] && c &&
            (c->type == VesselNetwork::Outlet::Type::Pressure || !(c->resistance > 0.0)))
            fixedPressure[std::size_t(node)] = c->pressurePa;
    for (std::size_t s = 0; s < network.segments.size(); ++s)
        if (open(s))
            connected[std::size_t(network.segments[s].from)] = connected[std::size_t(network.segments[s].to)] = 1;
    for (const NodeSource& source : sources)
        if (!connected[std::size_t(source.node)])
            throw Error(Pattern{"node %1 takes in flow but no open vessel leaves it", {std::to_string(source.node)}},
                        {{"node", std::to_string(source.node)}});
    // Unknowns numbered children before parents: eliminating a tree from its leaves up creates no fill, so the
    // natural order needs no reordering and the factor has the matrix's pattern.
    std::vector<int> unknown(network.nodes.size(), -1);
    int unknowns = 0;
    for (auto node = o.order.rbegin(); node != o.order.rend(); ++node)
        if (std::isnan(fixedPressure[std::size_t(*node)]) && connected[std::size_t(*node)])
            unknown[std::size_t(*node)] = unknowns++;

    solution.segmentResistance.assign(network.segments.size(), 0.0);
    std::vector<Eigen::Triplet<Real>> entries;
    Eigen::Matrix<Real, Eigen::Dynamic, 1> rhs = Eigen::Matrix<Real, Eigen::Dynamic, 1>::Zero(unknowns);
    auto couple = [&](int a, int b, Real conductance) { // a conductance between two nodes
        const int ia = unknown[std::size_t(a)], ib = unknown[std::size_t(b)];
        if (ia >= 0)
            entries.emplace_back(ia, ia, conductance);
        if (ib >= 0)
            entries.emplace_back(ib, ib, conductance);
        if (ia >= 0 && ib >= 0)
            entries.emplace_back(ia, ib, -conductance), entries.emplace_back(ib, ia, -conductance);
        if (ia >= 0 && ib < 0)
            rhs[ia] += conductance * fixedPressure[std::size_t(b)];
        if (ib >= 0 && ia < 0)
            rhs[ib] += conductance * fixedPressure[std::size_t(a)];
    };
    for (std::size_t s = 0; s < network.segments.size(); ++s)
        if (open(s))
        {
            solution.segmentResistance[s] = resistance[s];
            couple(network.segments[s].from, network.segments[s].to, 1.0L / resistance[s]);
        }
    for (int node : o.order)
    {
        const int i = unknown[std::size_t(node)];
        if (i < 0 || isSource[std::size_t(node)] || !conditions[std::size_t(node)])
            continue;
        const VesselNetwork::Outlet& outlet = *conditions[std::size_t(node)];
        if (outlet.type == VesselNetwork::Outlet::Type::Resistance) // (a zero one is held above)
        {
            entries.emplace_back(i, i, 1.0L / outlet.resistance);
            rhs[i] += Real(outlet.pressurePa) / outlet.resistance;
        }
    }
    for (const NodeSource& source : sources)
        if (!source.heldAtPressure && unknown[std::size_t(source.node)] >= 0)
            rhs[unknown[std::size_t(source.node)]] += source.volumeRate;

    Eigen::SparseMatrix<Real> system(unknowns, unknowns);
    system.setFromTriplets(entries.begin(), entries.end());
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<Real>, Eigen::Lower, Eigen::NaturalOrdering<int>> solver(system);
    if (solver.info() != Eigen::Success)
        throw Error("the flow system is singular: the part downstream of the tip has no outlet pressure to refer to");
    const Eigen::Matrix<Real, Eigen::Dynamic, 1> pressures = solver.solve(rhs);

    std::vector<Real> pressure(network.nodes.size(), 0.0L);
    solution.nodePressure.assign(network.nodes.size(), 0.0);
    for (int node : o.order)
    {
        const int i = unknown[std::size_t(node)];
        if (i < 0 && std::isnan(fixedPressure[std::size_t(node)]))
            continue; // stagnant
        pressure[std::size_t(node)] = i >= 0 ? pressures[i] : Real(fixedPressure[std::size_t(node)]);
        solution.nodePressure[std::size_t(node)] = double(pressure[std::size_t(node)]);
    }
    solution.segmentFlow.assign(network.segments.size(), 0.0);
    std::vector<double> netOut(network.nodes.size(), 0.0); // flow leaving each node through its segments
    for (std::size_t s = 0; s < network.segments.size(); ++s)
        if (open(s))
        {
            const auto& segment = network.segments[s];
            const double q = double((pressure[std::size_t(segment.from)] - pressure[std::size_t(segment.to)]) /
                                    resistance[s]);
            solution.segmentFlow[s] = q;
            netOut[std::size_t(segment.from)] += q;
            netOut[std::size_t(segment.to)] -= q;
        }
    // What enters at each source node, shared among the sources there by their rates (a held node takes it all).
    double entering = 0.0;
    for (const NodeSource& source : sources)
    {
        double rates = 0.0;
        bool held = false;
        for (const NodeSource& other : sources)
            if (other.node == source.node)
                rates += other.volumeRate, held = held || other.heldAtPressure;
        const double total = netOut[std::size_t(source.node)];
        solution.sourceFlow.push_back(held ? (source.heldAtPressure ? total - (rates - source.volumeRate) : source.volumeRate)
                                           : total * (rates > 0.0 ? source.volumeRate / rates : 0.0));
        entering += std::abs(solution.sourceFlow.back());
    }
    for (int outlet : o.outlets)
        solution.outletFlow[outlet] = -netOut[std::size_t(outlet)];
    // Kirchhoff's check at the interior nodes (the sources and outlets exchange flow with the outside).
    double worst = 0.0;
    for (int node : o.order)
        if (!isSource[std::size_t(node)] && !solution.outletFlow.count(node))
            worst = std::max(worst, std::abs(netOut[std::size_t(node)]));
    solution.conservationError = entering > 0.0 ? worst / entering : worst;
    return solution;
}

FlowSolution solveFlow(const VesselNetwork& network, const Injection& injection, double viscosity)
{
    const bool byRate = injection.volumeRate != 0.0;
    if (byRate && !(injection.volumeRate > 0.0 && std::isfinite(injection.volumeRate)))
        throw Error("the injection rate must be positive");
    if (!byRate && !std::isfinite(injection.pressure))
        throw Error("the injection needs a positive rate or a tip pressure");
    const TipOrientation o = orientFromTip(network, injection.tipNode);
    std::vector<double> resistance(network.segments.size(), 0.0);
    for (std::size_t s = 0; s < network.segments.size(); ++s)
        if (o.active(int(s)))
            resistance[s] = segmentResistance(network.segments[s], viscosity);
    FlowSolution solution = solveNodalFlow(network, o, resistance, {{o.tip, injection.volumeRate, !byRate, injection.pressure}});
    solution.tipPressure = solution.nodePressure[std::size_t(o.tip)];
    solution.injectedFlow = solution.sourceFlow.front();
    for (const auto& [outlet, q] : solution.outletFlow) // the injected fluid flows alone
        solution.outletInjectate[outlet] = q;
    return solution;
}

} // namespace vsim::sim::network
