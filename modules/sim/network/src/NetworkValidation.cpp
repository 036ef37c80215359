#include "vsim/sim/network/NetworkValidation.h"

#include "vsim/core/Error.h"
#include "vsim/sim/network/ConicalPipe.h"
#include "vsim/sim/network/FlowSolver.h"
#include "vsim/sim/network/NetworkBuild.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <random>

namespace vsim::sim::network {
namespace {

constexpr double kViscosity = 3.56e-3; // Pa s

/// A relative comparison as a figure: |measured / expected - 1| within `tolerance`.
ValidationFigure relative(const std::string& name, double measured, double expected, double tolerance)
{
    return {name, measured / expected - 1.0, 0.0, tolerance, "relative"};
}

/// A straight segment between two nodes of a network along x, with an explicit resistance or radii.
int addSegment(VesselNetwork& network, int from, int to, double resistance, double radiusMm = 1.0, double lengthMm = 10.0)
{
    VesselNetwork::Segment segment;
    segment.from = from, segment.to = to;
    segment.startRadiusMm = segment.endRadiusMm = radiusMm;
    segment.lengthMm = lengthMm;
    segment.resistance = resistance;
    network.segments.push_back(segment);
    return int(network.segments.size()) - 1;
}

VesselNetwork nodes(int count)
{
    VesselNetwork network;
    for (int i = 0; i < count; ++i)
        network.nodes.push_back({Eigen::Vector3d(10.0 * i, 0, 0), {}});
    return network;
}

ValidationResult cylinder()
{
    ValidationResult result{"network-cylinder", "conical resistance with R1 = R2 against 8 mu L / (pi R^4)", {}, 0.0};
    for (const auto& [radius, length] : {std::pair{3e-3, 0.04}, std::pair{1e-3, 0.01}, std::pair{0.35e-3, 0.005}})
    {
        const double poiseuille = 8.0 * kViscosity * length / (std::numbers::pi * std::pow(radius, 4));
        result.figures.push_back(relative("R = " + std::to_string(radius * 1e3).substr(0, 4) + " mm",
                                          conicalResistance(radius, radius, length, kViscosity), poiseuille, 1e-12));
    }
    return result;
}

ValidationResult cone()
{
    ValidationResult result{"network-cone", "eq. 6.6 against eq. 6.4 integrated (Gauss-Legendre, 64 x 8 points)", {}, 0.0};
    for (const auto& [r1, r2] : {std::pair{3e-3, 2.7e-3}, std::pair{1e-3, 0.5e-3}, std::pair{0.7e-3, 2.1e-3}})
        result.figures.push_back(relative("R1 " + std::to_string(r1 * 1e3).substr(0, 4) + " mm, R2 " +
                                              std::to_string(r2 * 1e3).substr(0, 4) + " mm",
                                          conicalResistance(r1, r2, 0.02, kViscosity),
                                          integratedResistance(r1, r2, 0.02, kViscosity, 64), 1e-9));
    return result;
}

ValidationResult conservation()
{
    ValidationResult result{"network-conservation", "Kirchhoff's law on a seeded random tree of 2,000 segments", {}, 0.0};
    VesselNetwork network = randomTree(2000, 20261122);
    std::mt19937 random(20261122);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    network.root = 0;
    for (int end : network.endNodes())
        if (end != 0)
            network.outlets.push_back({end, VesselNetwork::Outlet::Type::Resistance, 1000.0 * unit(random), 1e10 * (1.0 + unit(random))});
    network.validate();
    const FlowSolution flow = solveFlow(network, {0, 2e-6 / 60.0, 0.0}, kViscosity);
    double drained = 0.0;
    for (const auto& [node, q] : flow.outletFlow)
        drained += q;
    result.figures.push_back({"largest junction imbalance / injected", flow.conservationError, 0.0, 1e-12, ""});
    result.figures.push_back(relative("outlets / injected", drained, flow.injectedFlow, 1e-12));
    return result;
}

ValidationResult bifurcation()
{
    ValidationResult result{"network-bifurcation",
                            "tip -> junction -> two branches with terminal resistances into 1,000 and 2,000 Pa", {}, 0.0};
    VesselNetwork network = nodes(4);
    const double r0 = 2e9, r1 = 3e9, r2 = 5e9, t1 = 4e10, t2 = 2e10, p1 = 1000.0, p2 = 2000.0, q = 1e-7;
    addSegment(network, 0, 1, r0);
    const int a = addSegment(network, 1, 2, r1), b = addSegment(network, 1, 3, r2);
    network.root = 0;
    network.outlets = {{2, VesselNetwork::Outlet::Type::Resistance, p1, t1}, {3, VesselNetwork::Outlet::Type::Resistance, p2, t2}};
    const FlowSolution flow = solveFlow(network, {0, q, 0.0}, kViscosity);
    // q = (pJ - p1) / (r1 + t1) + (pJ - p2) / (r2 + t2)
    const double g1 = 1.0 / (r1 + t1), g2 = 1.0 / (r2 + t2), pJ = (q + g1 * p1 + g2 * p2) / (g1 + g2);
    result.figures.push_back(relative("branch 1 flow", flow.segmentFlow[std::size_t(a)], g1 * (pJ - p1), 1e-9));
    result.figures.push_back(relative("branch 2 flow", flow.segmentFlow[std::size_t(b)], g2 * (pJ - p2), 1e-9));
    result.figures.push_back(relative("junction pressure", flow.nodePressure[1], pJ, 1e-9));
    result.figures.push_back(relative("tip pressure", flow.tipPressure, pJ + r0 * q, 1e-9));
    return result;
}

ValidationResult confluence()
{
    ValidationResult result{"network-confluence",
                            "injected branch and a second inlet at 6,000 Pa joining before one outlet at 500 Pa", {}, 0.0};
    VesselNetwork network = nodes(4);
    const double ra = 4e9, rb = 6e9, ro = 3e9, pb = 6000.0, po = 500.0, q = 5e-7;
    addSegment(network, 0, 1, ra);
    const int b = addSegment(network, 2, 1, rb), o = addSegment(network, 1, 3, ro);
    network.root = 0;
    network.outlets = {{2, VesselNetwork::Outlet::Type::Pressure, pb, 0.0}, {3, VesselNetwork::Outlet::Type::Pressure, po, 0.0}};
    const FlowSolution flow = solveFlow(network, {0, q, 0.0}, kViscosity);
    // q + (pb - pJ) / rb = (pJ - po) / ro
    const double pJ = (q + pb / rb + po / ro) / (1.0 / rb + 1.0 / ro);
    result.figures.push_back(relative("second inlet's flow", flow.segmentFlow[std::size_t(b)], (pb - pJ) / rb, 1e-9));
    result.figures.push_back(relative("outlet flow", flow.segmentFlow[std::size_t(o)], (pJ - po) / ro, 1e-9));
    result.figures.push_back(relative("tip pressure", flow.tipPressure, pJ + ra * q, 1e-9));
    return result;
}

} // namespace

std::vector<std::string> networkValidationCases()
{
    return {"network-cylinder", "network-cone", "network-conservation", "network-bifurcation", "network-confluence"};
}

ValidationConfiguration networkValidationConfiguration()
{
    return {"cpu", 0, 0.0, "on the CPU with the direct (LDL^T) flow solve every run uses"};
}

ValidationResult runNetworkValidation(const std::string& name, const Progress& progress)
{
    const auto start = std::chrono::steady_clock::now();
    ValidationResult result;
    if (name == "network-cylinder")
        result = cylinder();
    else if (name == "network-cone")
        result = cone();
    else if (name == "network-conservation")
        result = conservation();
    else if (name == "network-bifurcation")
        result = bifurcation();
    else if (name == "network-confluence")
        result = confluence();
    else
        throw Error("unknown validation case '" + name +
                    "'; network cases: network-cylinder, network-cone, network-conservation, network-bifurcation, "
                    "network-confluence");
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    progress.report(1.0, name);
    return result;
}

} // namespace vsim::sim::network
