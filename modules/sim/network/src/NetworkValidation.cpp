#include "vsim/sim/network/NetworkValidation.h"

#include "vsim/core/Error.h"
#include "vsim/core/StoredText.h"
#include "vsim/core/Units.h"
#include "vsim/sim/network/BloodFlow.h"
#include "vsim/sim/network/ConicalPipe.h"
#include "vsim/sim/network/FlowSolver.h"
#include "vsim/sim/network/NetworkBuild.h"
#include "vsim/sim/network/TwoPhaseFluid.h"

#include <Eigen/LU>

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
    ValidationResult result{"network-cylinder", storedText("conical resistance with R1 = R2 against 8 mu L / (pi R^4)"), {}, 0.0};
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
    ValidationResult result{"network-cone", storedText("eq. 6.6 against eq. 6.4 integrated (Gauss-Legendre, 64 x 8 points)"), {}, 0.0};
    for (const auto& [r1, r2] : {std::pair{3e-3, 2.7e-3}, std::pair{1e-3, 0.5e-3}, std::pair{0.7e-3, 2.1e-3}})
        result.figures.push_back(relative("R1 " + std::to_string(r1 * 1e3).substr(0, 4) + " mm, R2 " +
                                              std::to_string(r2 * 1e3).substr(0, 4) + " mm",
                                          conicalResistance(r1, r2, 0.02, kViscosity),
                                          integratedResistance(r1, r2, 0.02, kViscosity, 64), 1e-9));
    return result;
}

ValidationResult conservation()
{
    ValidationResult result{"network-conservation", storedText("Kirchhoff's law on a seeded random tree of 2,000 segments"), {}, 0.0};
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
                            storedText("tip -> junction -> two branches with terminal resistances into 1,000 and 2,000 Pa"), {}, 0.0};
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
                            storedText("injected branch and a second inlet at 6,000 Pa joining before one outlet at 500 Pa"), {}, 0.0};
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

/// The annulus's conductance factor R^4 - a^4 - (R^2 - a^2)^2 / ln(R / a) of a straight pipe (White, eq. 3-49).
double annulusFactor(double R, double a)
{
    return std::pow(R, 4) - std::pow(a, 4) - std::pow(R * R - a * a, 2) / std::log(R / a);
}

ValidationResult annulus()
{
    ValidationResult result{"network-annulus", storedText("a catheter in a pipe: the annulus's Hagen-Poiseuille resistance"), {}, 0.0};
    for (const auto& [R, a] : {std::pair{1e-3, 0.45e-3}, std::pair{0.6e-3, 0.45e-3}, std::pair{3e-3, 0.3e-3}})
        result.figures.push_back(relative("cylinder R " + std::to_string(R * 1e3).substr(0, 4) + " mm, catheter " +
                                              std::to_string(a * 1e3).substr(0, 4) + " mm",
                                          annularResistance(R, R, a, 0.02, kViscosity),
                                          8.0 * kViscosity * 0.02 / (std::numbers::pi * annulusFactor(R, a)), 1e-12));
    // A cone: the panel count's convergence. (A vanishing catheter nears the open cone only as 1 / ln(R / a).)
    result.figures.push_back(relative("cone 1.2 -> 0.7 mm, catheter 0.45 mm, 64 against 512 panels",
                                      annularResistance(1.2e-3, 0.7e-3, 0.45e-3, 0.03, kViscosity, 64),
                                      annularResistance(1.2e-3, 0.7e-3, 0.45e-3, 0.03, kViscosity, 512), 1e-9));
    const bool wedged = std::isinf(annularResistance(1.2e-3, 0.7e-3, 0.8e-3, 0.03, kViscosity));
    result.figures.push_back({"a catheter wider than the lumen leaves it open (0: closed, infinite resistance)", wedged ? 0.0 : 1.0, 0.0, 0.0, ""});
    return result;
}

/// A straight geometric segment of radius `radiusMm` (the viscosity then scales its resistance).
int addPipe(VesselNetwork& network, int from, int to, double radiusMm, double lengthMm)
{
    return addSegment(network, from, to, 0.0, radiusMm, lengthMm);
}

ValidationResult mixing()
{
    ValidationResult result{"network-mixing",
                            storedText("blood from the root and an injection at a tip, mixed at a confluence with a second inlet"),
                            {}, 0.0};
    // 0 -> 1 (junction) -> 2 (the tip) -> 3 (confluence) -> 6 (outlet); 1 -> 4 (outlet); 5 (inlet at a pressure) -> 3.
    VesselNetwork network = nodes(7);
    const double r0 = 1e9, r1 = 3e9, r2 = 2e9, r3 = 4e9, r5 = 5e9, r6 = 1e9;
    const double t4 = 3e10, t6 = 2e10, p4 = 1300.0, p5 = 9000.0, p6 = 1300.0, qb = 2e-7, q = 2e-8;
    addSegment(network, 0, 1, r0);
    const int s12 = addSegment(network, 1, 2, r1), s23 = addSegment(network, 2, 3, r2), s14 = addSegment(network, 1, 4, r3);
    const int s53 = addSegment(network, 5, 3, r5), s36 = addSegment(network, 3, 6, r6);
    network.root = 0;
    network.outlets = {{4, VesselNetwork::Outlet::Type::Resistance, p4, t4},
                       {5, VesselNetwork::Outlet::Type::Pressure, p5, 0.0},
                       {6, VesselNetwork::Outlet::Type::Resistance, p6, t6}};
    BloodFlowSetup setup;
    setup.inletHeldAtPressure = false;
    setup.inletRate = qb;
    setup.tipNode = 2;
    setup.injectionRate = q;
    const BloodFlowSolution blood = solveBloodFlow(network, setup); // explicit resistances: no viscosity coupling
    // Nodal balances at 1, 2, 3 by hand (a 3 x 3 system), then the mixing by hand.
    Eigen::Matrix3d a;
    Eigen::Vector3d b;
    const double g1 = 1 / r1, g2 = 1 / r2, g4 = 1 / (r3 + t4), g5 = 1 / r5, g6 = 1 / (r6 + t6);
    a << g1 + g4, -g1, 0, -g1, g1 + g2, -g2, 0, -g2, g2 + g5 + g6;
    b << qb + g4 * p4, q, g5 * p5 + g6 * p6;
    const Eigen::Vector3d pressure = a.fullPivLu().solve(b);
    const double q12 = g1 * (pressure[0] - pressure[1]), q23 = g2 * (pressure[1] - pressure[2]);
    const double q53 = g5 * (p5 - pressure[2]);
    const double c23 = q / (q12 + q), c36 = c23 * q23 / (q23 + q53);
    const FlowSolution& f = blood.flow;
    result.figures.push_back(relative("blood reaching the tip", f.segmentFlow[std::size_t(s12)], q12, 1e-9));
    result.figures.push_back(relative("second inlet's flow (into the confluence: " + std::to_string(q53 * 6e7).substr(0, 5) +
                                          " ml/min)", f.segmentFlow[std::size_t(s53)], q53, 1e-9));
    result.figures.push_back(relative("injected fraction below the tip", f.injectateFraction[std::size_t(s23)], c23, 1e-9));
    result.figures.push_back(relative("injected fraction below the confluence", f.injectateFraction[std::size_t(s36)], c36, 1e-9));
    result.figures.push_back({"injected fraction in the sibling branch", f.injectateFraction[std::size_t(s14)], 0.0, 1e-12, ""});
    result.figures.push_back(relative("injected fluid leaving at the outlet", f.outletInjectate.at(6), q, 1e-9));
    result.figures.push_back({"injected fluid's balance", blood.balance.relativeError(), 0.0, 1e-12, ""});
    return result;
}

ValidationResult twoPhaseSplit()
{
    ValidationResult result{"network-two-phase-split",
                            storedText("the injected mixture's viscosity shifts the split between the tip's branch and its sibling"),
                            {}, 0.0};
    // 0 -> 1 (junction); 1 -> 2 (the tip) -> 3 (outlet, bed t); 1 -> 4 (outlet, bed t). Straight pipes; a catheter
    // of radius a from 0 to 2. Rate-driven root. With X the flow below the tip and c = q / X its injected fraction,
    // the viscosity below the tip is mu_b + c (mu_i - mu_b), so X R_23 = k (mu_b X + q (mu_i - mu_b)) with
    // k = 8 L / (pi r^4), and the pressure at 1 gives (X - q) R_12 + X (R_23 + t) = (Qb + q - X) (R_14 + t):
    //   X = [(Qb + q) (R_14 + t) + q R_12 - k q (mu_i - mu_b)] / (R_12 + k mu_b + t + R_14 + t).
    VesselNetwork network = nodes(5);
    const double ra = 2.0, rt = 1.0, rb = 1.2, la = 20.0, lt = 30.0, lb = 30.0; // mm
    const double t = 2e9, qb = units::mlPerMinToM3PerS(100.0), q = units::mlPerMinToM3PerS(10.0), catheter = 0.45e-3;
    const double muBlood = 3.5e-3;
    addPipe(network, 0, 1, ra, la);
    addPipe(network, 1, 2, ra, la);
    const int s23 = addPipe(network, 2, 3, rt, lt), s14 = addPipe(network, 1, 4, rb, lb);
    network.root = 0;
    network.outlets = {{3, VesselNetwork::Outlet::Type::Resistance, 1300.0, t}, {4, VesselNetwork::Outlet::Type::Resistance, 1300.0, t}};
    auto pipe = [](double radiusMm, double lengthMm) { return 8.0 * lengthMm * 1e-3 / (std::numbers::pi * std::pow(radiusMm * 1e-3, 4)); };
    const double r12 = 8.0 * muBlood * la * 1e-3 / (std::numbers::pi * annulusFactor(ra * 1e-3, catheter));
    const double k = pipe(rt, lt), r14 = muBlood * pipe(rb, lb);
    double solved[2] = {0.0, 0.0}, closedForm[2] = {0.0, 0.0}; // the sibling's flow, two-phase and liquid
    const TwoPhaseMixture mixture{0.3, {}};
    const std::pair<const char*, double> injected[2] = {{"two-phase (v 0.3)", mixture.viscosity()},
                                                        {"liquid", mixture.phases.liquidViscosity}};
    for (int i = 0; i < 2; ++i)
    {
        const auto& [name, muInjected] = injected[i];
        BloodFlowSetup setup;
        setup.inletHeldAtPressure = false;
        setup.inletRate = qb;
        setup.tipNode = 2;
        setup.injectionRate = q;
        setup.catheterRadius = catheter;
        setup.bloodViscosity = muBlood;
        setup.injectateViscosity = muInjected;
        const BloodFlowSolution blood = solveBloodFlow(network, setup);
        const double x = ((qb + q) * (r14 + t) + q * r12 - k * q * (muInjected - muBlood)) / (r12 + k * muBlood + t + r14 + t);
        solved[i] = blood.flow.segmentFlow[std::size_t(s14)];
        closedForm[i] = qb + q - x;
        result.figures.push_back(relative(std::string(name) + ": flow below the tip", blood.flow.segmentFlow[std::size_t(s23)], x, 1e-9));
        result.figures.push_back(relative(std::string(name) + ": sibling's flow", solved[i], closedForm[i], 1e-9));
        result.figures.push_back({std::string(name) + ": fixed point left unconverged (0: converged to 1e-12)", blood.converged ? 0.0 : 1.0, 0.0, 0.0, ""});
    }
    // The shift itself (percent of the sibling's flow), against the closed form's: a non-zero effect of the mixture.
    const double shiftSolved = 100.0 * (solved[0] / solved[1] - 1.0), shiftTruth = 100.0 * (closedForm[0] / closedForm[1] - 1.0);
    result.figures.push_back({"sibling's split shift, two-phase against liquid (%; closed form " +
                                  std::to_string(shiftTruth).substr(0, 7) + ")",
                              shiftSolved - shiftTruth, 0.0, 1e-7, "% points"});
    return result;
}

} // namespace

std::vector<std::string> networkValidationCases()
{
    return {"network-cylinder",   "network-cone",   "network-conservation",   "network-bifurcation",
            "network-confluence", "network-annulus", "network-mixing", "network-two-phase-split"};
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
    else if (name == "network-annulus")
        result = annulus();
    else if (name == "network-mixing")
        result = mixing();
    else if (name == "network-two-phase-split")
        result = twoPhaseSplit();
    else
        throw Error(Pattern{"unknown validation case '%1'; network cases: network-cylinder, network-cone, "
                            "network-conservation, network-bifurcation, network-confluence, network-annulus, "
                            "network-mixing, network-two-phase-split",
                            {name}});
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    progress.report(1.0, name);
    return result;
}

} // namespace vsim::sim::network
