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

struct FlowSolution
{
    TipOrientation orientation;
    std::vector<double> segmentFlow;  ///< m^3/s along the segment's from -> to (0 where left out)
    std::vector<double> segmentResistance; ///< Pa s / m^3 (0 where left out)
    std::vector<double> nodePressure; ///< Pa (0 where left out)
    std::map<int, double> outletFlow; ///< m^3/s out of the network at each outlet node (negative: into it)
    double injectedFlow = 0.0;        ///< m^3/s into the tip
    double tipPressure = 0.0;         ///< Pa
    /// Largest |sum of flows| at a node downstream of the tip, relative to the injected flow (Kirchhoff's check).
    double conservationError = 0.0;
};

/// Resistance of segment `s` for a fluid of `viscosity` (Pa s): its explicit one, else the conical formula.
double segmentResistance(const VesselNetwork::Segment& segment, double viscosity);

/// Solves the flow. Every outlet downstream of the tip needs a condition in network.outlets. Throws vsim::Error
/// naming the node for an outlet without one, and for an injection that is neither a positive rate nor a finite
/// pressure.
FlowSolution solveFlow(const VesselNetwork& network, const Injection& injection, double viscosity);

} // namespace vsim::sim::network
