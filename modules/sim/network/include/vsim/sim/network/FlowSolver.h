#pragma once

// Steady flow through the part of a vessel tree downstream of the catheter tip (thesis ch. 6.2): every segment a
// conical Hagen-Poiseuille resistance (or its explicit one), the drug injected at the tip at a volume rate or a
// pressure, every outlet at a pressure or through a terminal resistance to one; the node pressures from
// Kirchhoff's current law as one sparse symmetric positive definite system (Eigen's simplicial LDL^T). SI units.

#include "vsim/core/VesselNetwork.h"
#include "vsim/sim/network/TipOrientation.h"

#include <map>
#include <vector>

namespace vsim::sim::network {

struct Injection
{
    int tipNode = -1;
    double volumeRate = 0.0; ///< m^3/s of the injected mixture; when 0 the tip is held at `pressure`
    double pressure = 0.0;   ///< Pa, the tip's pressure for a pressure-driven injection
};

/// A node where flow enters the network from outside: at a volume rate, or held at a pressure (then it takes in
/// whatever the network draws). Several sources may share a node: their rates add; a pressure holds it.
struct NodeSource
{
    int node = -1;
    double volumeRate = 0.0; ///< m^3/s into the node (when not held at a pressure)
    bool heldAtPressure = false;
    double pressure = 0.0;   ///< Pa, when held at a pressure
};

struct FlowSolution
{
    TipOrientation orientation;
    std::vector<double> segmentFlow;  ///< m^3/s along the segment's from -> to (0 where left out)
    std::vector<double> segmentResistance; ///< Pa s / m^3 (0 where left out)
    std::vector<double> nodePressure; ///< Pa (0 where left out)
    std::map<int, double> outletFlow; ///< m^3/s out of the network at each outlet node (negative: into it)
    double injectedFlow = 0.0;        ///< m^3/s into the tip
    double tipPressure = 0.0;         ///< Pa
    std::vector<double> sourceFlow;   ///< m^3/s into the network at each NodeSource (solveNodalFlow's order)
    /// Volume fraction of the injected fluid in each segment's flow (DrugMixing.h); empty when the injected fluid
    /// flows alone (solveFlow: 1 downstream of the tip).
    std::vector<double> injectateFraction;
    /// m^3/s of the injected fluid leaving at each outlet (with injectateFraction; solveFlow: the outlet's flow).
    std::map<int, double> outletInjectate;
    /// Largest |sum of flows| at a node downstream of the tip, relative to the injected flow (Kirchhoff's check).
    double conservationError = 0.0;
};

/// Resistance of segment `s` for a fluid of `viscosity` (Pa s): its explicit one, else the conical formula.
double segmentResistance(const VesselNetwork::Segment& segment, double viscosity);

/// Kirchhoff's law over the nodes of `order` (a tree orientation: parents before children) and the segments it
/// holds active whose `resistance` (Pa s / m^3, per segment) is finite and positive; outlets at the conditions of
/// network.outlets, flow entering at `sources`. A node left with no open segment and no condition is stagnant (its
/// pressure reads 0). Throws vsim::Error for an outlet without a condition, a source on a stagnant node, or a
/// system without a pressure to refer to. conservationError is relative to the flow entering at the sources.
FlowSolution solveNodalFlow(const VesselNetwork& network, const TipOrientation& order,
                            const std::vector<double>& resistance, const std::vector<NodeSource>& sources);

/// Solves the flow. Every outlet downstream of the tip needs a condition in network.outlets. Throws vsim::Error
/// naming the node for an outlet without one, and for an injection that is neither a positive rate nor a finite
/// pressure.
FlowSolution solveFlow(const VesselNetwork& network, const Injection& injection, double viscosity);

} // namespace vsim::sim::network
