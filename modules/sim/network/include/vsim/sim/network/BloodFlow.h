#pragma once

// Blood carries the drug (issue 19): arterial blood enters the tree at its inlet (the common or proper hepatic
// artery; at a pressure or a volume rate), a catheter runs from the inlet to its tip, and the injection enters at
// the tip. Downstream of the tip every segment carries blood and injected fluid mixed (DrugMixing.h).
//
// What the catheter does: it lies in every segment from the inlet to its tip, so blood passes it through an
// annulus (ConicalPipe.h, annularResistance; concentric, the most resistive position); where it fills the lumen
// no blood passes (wedged).
//
// What the mixture does (the mechanism modelled): each segment's viscosity is the volume-weighted mean of blood's
// and the injected fluid's at the segment's fraction c, mu = (1 - c) mu_blood + c mu_injected (thesis eq. 6.3's
// rule, extended to the three components); the terminal beds beyond the outlets hold blood and keep their
// resistance. The flows set the fractions and the fractions the resistances, so the two are solved together by
// fixed-point (Picard) iteration to a stated tolerance on the fractions. Density is reported, not used: the
// network has no inertia and no gravity (the patient supine, the tree taken as level).
// Not modelled: the Fahraeus-Lindqvist effect (blood's apparent viscosity falls in vessels under 0.3 mm), pulsation
// (the flows are time-averaged), the catheter's own resistance to the injection (the injection is a volume rate).

#include "vsim/core/VesselNetwork.h"
#include "vsim/sim/network/DrugMixing.h"
#include "vsim/sim/network/FlowSolver.h"

#include <string>
#include <vector>

namespace vsim::sim::network {

struct BloodFlowSetup
{
    bool inletHeldAtPressure = true;
    double inletPressure = 0.0;      ///< Pa, when held at a pressure
    double inletRate = 0.0;          ///< m^3/s of blood, otherwise
    int tipNode = -1;                ///< the catheter's tip (the network's root is the inlet)
    double injectionRate = 0.0;      ///< m^3/s of the injected mixture at the tip
    double catheterRadius = 0.0;     ///< m, outer
    double bloodViscosity = 3.5e-3;  ///< Pa s
    double injectateViscosity = 3.5e-3; ///< Pa s (the two-phase mixture's, or the liquid's)
    double tolerance = 1e-12;        ///< largest change of a segment's injected fraction between iterations
    int maxIterations = 100;
};

/// The catheter fills "most of the lumen" at or above this share of the cross-section at its tip.
inline constexpr double kWedgeOcclusion = 0.5;

struct BloodFlowSolution
{
    /// Every segment's flow (blood and injected fluid), pressure, fraction; its orientation is the tip's (the
    /// part downstream of it) and injectedFlow the injection's rate.
    FlowSolution flow;
    InjectateBalance balance;
    std::vector<int> catheterSegments;   ///< from the inlet to the tip
    std::vector<double> segmentViscosity; ///< Pa s, as last solved
    double inletFlow = 0.0;      ///< m^3/s of blood entering at the inlet
    double ownFlow = 0.0;        ///< m^3/s reaching the tip through its vessel, catheter in place, no injection
    double tipInflow = 0.0;      ///< m^3/s reaching the tip through its vessel with the injection (< 0: reflux)
    double tipFraction = 0.0;    ///< injected fraction of the flow leaving the tip downstream
    double occlusion = 0.0;      ///< the catheter's share of the lumen's cross-section at the tip
    double refluxShare = 0.0;    ///< share of the injected fluid leaving anywhere but downstream of the tip
    bool wedged = false;
    std::string wedgedBecause;   ///< why, in words (empty when not wedged)
    int iterations = 0;
    double residual = 0.0;       ///< the last change of the fractions
    bool converged = false;
};

/// Solves the setup on `network` (validated, root set, every end other than the root with an outlet condition).
/// Throws vsim::Error for a tip that is not in the tree, a rate that is not positive, or a catheter that closes the
/// only way from a rate-driven inlet.
BloodFlowSolution solveBloodFlow(const VesselNetwork& network, const BloodFlowSetup& setup);

} // namespace vsim::sim::network
