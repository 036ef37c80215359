#pragma once

// The drug-delivery run of `vascusim-cli simulate network` and the workstation: the network downstream of the
// catheter tip, default outlet conditions, the steady split for the two-phase drug and for a pure liquid, the
// filling, control points, and tumour targeting with a ranking of tip positions. Geometry in mm, SI inside, the
// report's units (ml/min, mmHg, s) in the fields and metrics.
//
// Outlets without a condition drain into a terminal resistance by Murray's law (1926: a vessel's flow goes with the
// cube of its radius): all outlets together carry reference_inflow_ml_min at reference_pressure_drop_mmhg, each in
// proportion to its terminal segment's mean radius cubed, into outlet_pressure_mmhg. The resistances stand for the
// blood-filled vascular bed beyond the imaged tree, so they do not change with the injected fluid.
//
// Two models (parameter blood_flow): by default arterial blood enters at the root and carries the drug (issue 19,
// BloodFlow.h): the catheter lies from the root to its tip, the injection mixes with the blood there, and each
// segment's viscosity follows its injected fraction. With blood_flow 0 the injected drug flows alone, as the thesis
// models it (ch. 6).
//
// Two-phase against pure liquid (thesis ch. 6.4, "8-9 % lower"): the drug (liquid-phase) volume flow through a
// control point, (1 - v) c Q (c the injected fraction, 1 without blood), for the same injected mixture volume rate;
// the liquid run has v = 0. That drop is close to the void fraction by its definition. What the mixture does to
// the flow is the split shift: the change of the control point's whole volume flow between the two runs, which
// only the viscosity contrast moves. The injected-alone model also reports the drop at the same tip pressure.

#include "vsim/core/Parameters.h"
#include "vsim/core/Progress.h"
#include "vsim/core/RunStatus.h"
#include "vsim/core/VesselNetwork.h"
#include "vsim/sim/network/BloodFlow.h"
#include "vsim/sim/network/Filling.h"
#include "vsim/sim/network/FlowSolver.h"
#include "vsim/sim/network/Targeting.h"
#include "vsim/sim/network/Lesions.h"
#include "vsim/sim/network/Territories.h"
#include "vsim/sim/network/TwoPhaseFluid.h"
#include "vsim/sim/network/WorkingAngle.h"

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace vsim::sim::network {

/// Every parameter of the drug-delivery run.
std::vector<ParameterSpec> networkParameters();
/// The injected mixture of a parameter set.
TwoPhaseMixture networkMixture(const ParameterSet& parameters);

/// Adds Murray-law terminal resistances (see above) for every end node other than the root without a condition.
void addDefaultOutlets(VesselNetwork& network, const ParameterSet& parameters);

/// A label volume a setup shares (the liver's or the tumour's) and the value that marks the region (0: any).
struct SharedLabel
{
    std::shared_ptr<const LabelVolume> volume;
    int value = 0;
    LabelRegion region() const { return {volume.get(), value}; }
};

struct NetworkRunSetup
{
    VesselNetwork network;                      ///< validated; root set (or the largest end is taken)
    bool defaultOutlets = true;                 ///< false: every outlet needs a condition in the network
    /// Blood enters through this segment (Inlet.h: the tree beyond it is kept, its upper end the root); tipNode and
    /// the feeder edits are then in the kept tree's numbering, as the result reports its nodes and segments.
    std::optional<int> inletSegment;
    std::optional<int> tipNode;                 ///< the catheter tip as a node, or
    std::optional<Eigen::Vector3d> tipPointMm;  ///< as a point on the tree
    /// The tumour: inside(point mm); empty for none. TumourSphere::contains, or a label's voxels.
    std::function<bool(const Eigen::Vector3d&)> tumour;
    std::vector<Eigen::Vector3d> controlPointsMm; ///< empty: the two largest daughters of the first junction
    /// Pa: hold the tip at this pressure instead of injecting injection_rate_ml_min (both fluids at the same
    /// pressure: the control points then compare at the same tip pressure).
    std::optional<double> tipPressurePa;
    ParameterSet parameters{networkParameters()};
    bool rankTips = true;
    /// The liver (and the tumour as a label): perfusion territories, outlets from them (outlet_model 1), the tip's
    /// perfused territory, the lesions' coverage grade and feeders, tips ranked by coverage (Territories.h).
    std::optional<SharedLabel> liver, tumourLabel;
    FeederEdits feederEdits; ///< the user's corrections to the feeders found (segments of the result's network)
};

struct ControlPoint
{
    std::string name;                  ///< "A", "B", ...
    Eigen::Vector3d pointMm = Eigen::Vector3d::Zero();
    int segment = -1;
    double drugFlowTwoPhaseMlMin = 0.0; ///< (1 - v) |Q|, same injected rate
    double drugFlowLiquidMlMin = 0.0;   ///< |Q| with v = 0
    double dropPercent = 0.0;           ///< 100 (1 - two-phase / liquid)
    double dropAtSamePressurePercent = 0.0; ///< the same with the tip held at the liquid run's pressure (drug alone)
    double splitShiftPercent = 0.0;     ///< 100 (|Q two-phase| / |Q liquid| - 1) of the whole volume flow
};

struct NetworkRunResult
{
    VesselNetwork network;             ///< as solved (tip node inserted, outlet conditions), with segment fields
    int tipNode = -1;
    FlowSolution twoPhase, liquid;
    /// With blood flow: the two-phase run's blood, catheter and mixing figures (twoPhase is its flow).
    std::optional<BloodFlowSolution> blood;
    FillingTimes filling;
    std::vector<ControlPoint> controls;
    std::vector<int> tumourOutlets;
    std::vector<TipCandidate> ranking; ///< best first
    /// With a liver: the territories, the tip's perfused territory, the lesions, their coverage and feeders.
    std::shared_ptr<const LiverTerritories> territories;
    std::optional<PerfusedTerritory> perfused;
    std::vector<Lesion> lesions;
    std::optional<Coverage> coverage;
    std::vector<Feeder> feeders;
    /// The C-arm angle for the path from the root to the tip (working_angle 1 and a tip away from the root).
    std::optional<WorkingAngle> workingAngle;
    std::map<std::string, double> metrics;
    std::vector<std::string> warnings;
    /// The flow solves (direct): Kirchhoff's balance against kConservationTolerance; with blood flow also the
    /// fixed-point coupling of fractions and viscosities against its tolerance.
    RunStatus status;
};

/// A coverage grade as a metric: A 1, B 2, C 3 (0: no lesion).
double gradeNumber(char grade);
/// Lesions whose figures a run records as metrics (lesion_<k>_..., largest first).
inline constexpr std::size_t kLesionsReported = 5;

/// Largest relative imbalance of flow at a node that a flow solve may leave (a direct solve leaves ~1e-15).
inline constexpr double kConservationTolerance = 1e-9;

/// Runs the setup. Throws vsim::Error for bad input (tip off the tree or on a disconnected part, outlets without a
/// condition, a void fraction out of range, ...) naming the node or segment; nothing is returned then.
NetworkRunResult runNetwork(const NetworkRunSetup& setup, const Progress& progress = {});

} // namespace vsim::sim::network
