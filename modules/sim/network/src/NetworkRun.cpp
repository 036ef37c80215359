#include "vsim/sim/network/NetworkRun.h"

#include "vsim/core/Error.h"
#include "vsim/core/Localized.h"
#include "vsim/core/Parameters.h"
#include "vsim/core/StoredText.h"
#include "vsim/core/Units.h"
#include "vsim/sim/network/ConicalPipe.h"
#include "vsim/sim/network/Inlet.h"
#include "vsim/sim/network/NetworkBuild.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <set>

namespace vsim::sim::network {
namespace {

using Kind = ParameterSpec::Kind;

double meanRadiusMm(const VesselNetwork::Segment& segment) { return 0.5 * (segment.startRadiusMm + segment.endRadiusMm); }

/// The injected fluid's share of segment s's flow: its mixed fraction, or 1 where the injected fluid flows alone.
double injectateShare(const FlowSolution& flow, std::size_t s)
{
    return flow.injectateFraction.empty() ? 1.0 : flow.injectateFraction[s];
}

/// The control points of the thesis's figure when none are given: the two daughters of the first junction
/// downstream of the tip that carry the most flow, at their middles.
std::vector<Eigen::Vector3d> defaultControlPoints(const VesselNetwork& network, const FlowSolution& flow)
{
    const TipOrientation& o = flow.orientation;
    for (int node : o.order)
    {
        std::vector<int> children;
        for (std::size_t s = 0; s < network.segments.size(); ++s)
            if (o.upstreamNode[s] == node)
                children.push_back(int(s));
        if (children.size() < 2)
            continue;
        std::sort(children.begin(), children.end(), [&](int a, int b) {
            return std::abs(flow.segmentFlow[std::size_t(a)]) > std::abs(flow.segmentFlow[std::size_t(b)]);
        });
        return {segmentMiddle(network, children[0]), segmentMiddle(network, children[1])};
    }
    return {};
}

void setFields(NetworkRunResult& r, const TwoPhaseMixture& fluid, double bloodDensity)
{
    VesselNetwork& n = r.network;
    const std::size_t count = n.segments.size();
    auto field = [&](const char* name) -> std::vector<double>& { return n.segmentFields[name] = std::vector<double>(count, 0.0); };
    std::vector<double>& downstream = field("downstream");
    std::vector<double>& flow = field("flow_ml_min");
    std::vector<double>& drug = field("drug_flow_ml_min");
    std::vector<double>& liquid = field("liquid_flow_ml_min");
    std::vector<double>& injected = field("injected_percent");
    std::vector<double>& pFrom = field("pressure_from_mmhg");
    std::vector<double>& pTo = field("pressure_to_mmhg");
    std::vector<double>& velocity = field("velocity_mm_s");
    std::vector<double>& reynolds = field("reynolds");
    std::vector<double>& enter = field("fill_enter_s");
    std::vector<double>& leave = field("fill_leave_s");
    double maxReynolds = 0.0;
    for (std::size_t s = 0; s < count; ++s)
    {
        if (!r.twoPhase.orientation.active(int(s)))
        {
            enter[s] = leave[s] = -1.0;
            continue;
        }
        const auto& segment = n.segments[s];
        const double q = r.twoPhase.segmentFlow[s], radius = units::mmToM(meanRadiusMm(segment));
        const double u = std::abs(q) / (std::numbers::pi * radius * radius);
        downstream[s] = 1.0;
        flow[s] = units::m3PerSToMlPerMin(q);
        const double c = injectateShare(r.twoPhase, s);
        drug[s] = units::m3PerSToMlPerMin(fluid.liquidFraction() * c * std::abs(q));
        liquid[s] = units::m3PerSToMlPerMin(injectateShare(r.liquid, s) * std::abs(r.liquid.segmentFlow[s]));
        injected[s] = 100.0 * c;
        pFrom[s] = units::paToMmHg(r.twoPhase.nodePressure[std::size_t(segment.from)]);
        pTo[s] = units::paToMmHg(r.twoPhase.nodePressure[std::size_t(segment.to)]);
        velocity[s] = units::mToMm(u);
        const double density = r.blood ? (1.0 - c) * bloodDensity + c * fluid.density() : fluid.density();
        const double viscosity = r.blood ? r.blood->segmentViscosity[s] : fluid.viscosity();
        reynolds[s] = density * u * 2.0 * radius / viscosity;
        maxReynolds = std::max(maxReynolds, reynolds[s]);
        enter[s] = r.filling.enter[s] == kNever ? -1.0 : r.filling.enter[s];
        leave[s] = r.filling.leave[s] == kNever ? -1.0 : r.filling.leave[s];
    }
    r.metrics["max_reynolds"] = maxReynolds;
    if (maxReynolds > 2000.0)
        r.warnings.push_back(storedText(Pattern{"the Reynolds number reaches %1: the flow may not be laminar there, and "
                                                "Hagen-Poiseuille does not hold",
                                                {std::to_string(int(maxReynolds))}}));
}

/// The best of the ranking as metrics.
void recordBestTip(NetworkRunResult& r, const VesselNetwork& net)
{
    const TipCandidate& best = r.ranking.front();
    r.metrics["best_tip_node"] = best.node;
    r.metrics["best_tip_fraction"] = best.tumourFraction;
    r.metrics["best_tip_depth"] = best.depth;
    r.metrics["best_tip_x_mm"] = net.nodes[std::size_t(best.node)].positionMm.x();
    r.metrics["best_tip_y_mm"] = net.nodes[std::size_t(best.node)].positionMm.y();
    r.metrics["best_tip_z_mm"] = net.nodes[std::size_t(best.node)].positionMm.z();
    if (best.grade != '-')
    {
        r.metrics["best_tip_grade"] = gradeNumber(best.grade);
        r.metrics["best_tip_covered_percent"] = best.coveredPercent;
        r.metrics["best_tip_non_target_ml"] = best.nonTargetMl;
    }
}

/// With a liver: the tip's perfused territory, the drug's destinations, the lesions' coverage and feeders, and the
/// tips ranked by coverage.
void describeTerritory(NetworkRunResult& r, const VesselNetwork& net, const TipSolve& solveAt, bool rank,
                       const FeederEdits& edits, const Progress& progress)
{
    const auto started = std::chrono::steady_clock::now();
    const LiverTerritories& t = *r.territories;
    r.perfused = perfusedTerritory(t, r.twoPhase);
    r.coverage = tumourCoverage(r.lesions, *r.perfused);
    const std::vector<Feeder> found = findFeeders(net, t, r.lesions);
    r.feeders = editFeeders(found, net, r.lesions, edits);
    const PerfusedTerritory& p = *r.perfused;
    for (Feeder& f : r.feeders)
        f.reached = std::find(p.segments.begin(), p.segments.end(), f.segment) != p.segments.end();
    auto& m = r.metrics;
    m["territory_seconds"] += std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    m["liver_volume_ml"] = double(t.voxels.size()) * t.voxelMl;
    m["hepatic_outlets"] = double(t.outlets.size());
    m["extrahepatic_outlets"] = double(t.extrahepatic.size());
    m["perfused_volume_ml"] = p.volumeMl;
    m["perfused_tumour_ml"] = p.tumourVolumeMl;
    m["perfused_non_target_ml"] = p.volumeMl - p.tumourVolumeMl;
    m["tumour_fraction"] = p.drugToTumour;
    m["non_target_fraction"] = 1.0 - p.drugToTumour;
    m["drug_liver_percent"] = 100.0 * p.drugToLiver;
    m["drug_extrahepatic_percent"] = 100.0 * p.drugExtrahepatic;
    m["lesions"] = double(r.lesions.size());
    m["feeders"] = double(r.feeders.size());
    m["feeders_added_by_hand"] = double(std::count_if(r.feeders.begin(), r.feeders.end(), [](const Feeder& f) { return f.byHand; }));
    m["feeders_removed_by_hand"] = double(std::count_if(found.begin(), found.end(), [&](const Feeder& f) {
        return std::find(edits.removed.begin(), edits.removed.end(), f.segment) != edits.removed.end();
    }));
    m["feeders_reached"] = double(std::count_if(r.feeders.begin(), r.feeders.end(), [](const Feeder& f) { return f.reached; }));
    if (r.lesions.empty())
        return;
    m["coverage_grade"] = gradeNumber(r.coverage->grade);
    for (std::size_t l = 0; l < r.lesions.size() && l < kLesionsReported; ++l)
    {
        const Lesion& lesion = r.lesions[l];
        const LesionCoverage& c = r.coverage->lesions[l];
        const std::string key = "lesion_" + std::to_string(l + 1) + "_";
        m[key + "diameter_mm"] = lesion.diameterMm;
        m[key + "volume_ml"] = lesion.volumeMl;
        m[key + "margin_mm"] = lesion.marginMm;
        m[key + "covered_percent"] = c.coveredPercent;
        m[key + "margin_covered_percent"] = c.marginCoveredPercent;
        m[key + "grade"] = gradeNumber(c.grade);
    }
    if (r.coverage->grade == 'C')
        r.warnings.push_back(storedText("coverage grade C from this tip: part of a lesion is not perfused (see the feeders)"));
    if (rank)
    {
        const auto ranking = std::chrono::steady_clock::now();
        r.ranking = rankTipsByCoverage(net, t, r.lesions, solveAt, progress);
        recordBestTip(r, net);
        m["ranked_tips"] = double(r.ranking.size());
        m["ranking_seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - ranking).count();
    }
}

} // namespace

double gradeNumber(char grade) { return grade == 'A' ? 1.0 : grade == 'B' ? 2.0 : grade == 'C' ? 3.0 : 0.0; }

std::vector<ParameterSpec> networkParameters()
{
    std::vector<ParameterSpec> specs{
        {"injection_rate_ml_min", "Injection rate", "ml/min", 2.0, 0.01, 200.0, "Injection",
         "Volume rate of the injected drug mixture at the catheter tip."},
        {"catheter_outer_diameter_fr", "Catheter outer diameter", "Fr", 2.7, 0.0, 7.0, "Injection",
         "Outer diameter of the catheter lying from the tree's root to its tip, 1 Fr = 1/3 mm (microcatheters "
         "1.7-3.0 Fr); blood passes it through the annulus. 0 leaves it out of the flow."},
        {"tip_snap_mm", "Tip snap distance", "mm", 1.0, 0.0, 10.0, "Injection",
         "A tip or control point given as a point this near a node is put on the node."},
        {"tip_reach_mm", "Tip reach", "mm", 10.0, 0.5, 50.0, "Injection",
         "How far a tip or control point given as a point may lie from the vessel tree."},
        {"void_fraction", "Void fraction", "", 0.1, 0.0, 0.95, "Two-phase drug",
         "Gas volume fraction of the injected drug (thesis eq. 6.2, 6.3); the flow is bubbly up to about 0.25."},
        {"gas_absorption_ml_min", "Gas absorption rate", "ml/min", 10.0, 5.0, 20.0, "Two-phase drug",
         "Gas absorption rate of the bubbly regime (thesis ch. 6.1: 5-20 ml/min); with the bubble size it gives the "
         "bubble rate."},
        {"bubble_diameter_mm", "Bubble diameter", "mm", 1.5, 1.29, 2.05, "Two-phase drug",
         "Bubble diameter of the bubbly regime (thesis ch. 6.1: 1.29-2.05 mm)."},
        {"liquid_density", "Liquid density", "kg/m^3", 1060.0, 900.0, 1500.0, "Two-phase drug",
         "Density of the liquid phase (plasma: 1,060 kg/m^3)."},
        {"liquid_viscosity_mpa_s", "Liquid viscosity", "mPa s", 3.56, 0.5, 50.0, "Two-phase drug",
         "Dynamic viscosity of the liquid phase at 37 C (plasma: 3.56 mPa s)."},
        {"gas_density", "Gas density", "kg/m^3", 1.205, 0.1, 10.0, "Two-phase drug", "Density of the gas phase."},
        {"gas_viscosity_upa_s", "Gas viscosity", "uPa s", 18.6, 5.0, 50.0, "Two-phase drug",
         "Dynamic viscosity of the gas phase at 37 C."},
        {"blood_flow", "Blood carries the drug", "", 1.0, 0.0, 1.0, "Blood flow",
         "1: arterial blood enters at the tree's root and carries the injected drug; 0: the injected drug flows alone, "
         "as the thesis models it (ch. 6).", Kind::Integer},
        {"arterial_pressure_mmhg", "Arterial pressure at the root", "mmHg", 90.0, 40.0, 200.0, "Blood flow",
         "Mean pressure at the tree's root, held unless an inflow is given: the hepatic artery's mean pressure is close "
         "to the aorta's (normal mean arterial pressure 70-105 mmHg)."},
        {"arterial_inflow_ml_min", "Arterial inflow", "ml/min", 0.0, 0.0, 2000.0, "Blood flow",
         "Blood flow into the tree's root instead of a pressure; 0: the root is held at the arterial pressure. Hepatic "
         "arterial flow is about 25 % of the liver's 100 ml/min per 100 g (Lautt, Hepatic Circulation, 2009): "
         "100-400 ml/min."},
        {"blood_viscosity_mpa_s", "Blood viscosity", "mPa s", 3.5, 2.0, 10.0, "Blood flow",
         "Apparent viscosity of whole blood at arterial shear rates (about 3.5 mPa s at a haematocrit of 0.45), taken "
         "as Newtonian."},
        {"blood_density", "Blood density", "kg/m^3", 1060.0, 1000.0, 1100.0, "Blood flow",
         "Density of whole blood (for the Reynolds number)."},
        {"reference_inflow_ml_min", "Outlets' reference flow", "ml/min", 100.0, 1.0, 5000.0, "Outlets",
         "Flow that all outlets together drain at the reference pressure drop, split by Murray's law (hepatic artery "
         "flow is about 100-400 ml/min)."},
        {"reference_pressure_drop_mmhg", "Outlets' reference pressure drop", "mmHg", 60.0, 1.0, 200.0, "Outlets",
         "Pressure drop across the vascular bed beyond the outlets at the reference flow."},
        {"outlet_pressure_mmhg", "Pressure beyond the outlets", "mmHg", 10.0, 0.0, 100.0, "Outlets",
         "Pressure at the far end of the terminal resistances (venous side)."},
        {"tumour_resistance_factor", "Tumour bed resistance factor", "", 1.0, 0.05, 20.0, "Targeting",
         "Terminal resistance of the tumour's outlets times this (below 1 for a hypervascular tumour)."},
        {"filling_steps", "Filling steps", "", 1000.0, 10.0, 100000.0, "Filling",
         "Time steps from the start of the injection to the last outlet's arrival.", Kind::Integer},
        {"working_angle", "Working C-arm angle", "", 1.0, 0.0, 1.0, "Working angle",
         "1: the LAO/RAO and cranial/caudal angles that show the path from the root to the tip with the least "
         "foreshortening and overlap (WorkingAngle.h); 0: none.", Kind::Integer},
    };
    for (ParameterSpec& spec : territoryParameters())
        specs.push_back(spec);
    return specs;
}

TwoPhaseMixture networkMixture(const ParameterSet& p)
{
    TwoPhaseMixture fluid;
    fluid.voidFraction = p.get("void_fraction");
    fluid.phases.liquidDensity = p.get("liquid_density");
    fluid.phases.gasDensity = p.get("gas_density");
    fluid.phases.liquidViscosity = 1e-3 * p.get("liquid_viscosity_mpa_s");
    fluid.phases.gasViscosity = 1e-6 * p.get("gas_viscosity_upa_s");
    fluid.validate();
    return fluid;
}

void addDefaultOutlets(VesselNetwork& network, const ParameterSet& p)
{
    std::set<int> explicitNodes;
    for (const VesselNetwork::Outlet& outlet : network.outlets)
        explicitNodes.insert(outlet.node);
    const std::vector<std::vector<int>> incident = network.incidentSegments();
    std::vector<std::pair<int, double>> ends; // node, radius cubed (of the whole tree: independent of the tip)
    double total = 0.0;
    for (int node : network.endNodes())
        if (node != network.root)
        {
            const double r = meanRadiusMm(network.segments[std::size_t(incident[std::size_t(node)].front())]);
            ends.emplace_back(node, r * r * r);
            total += r * r * r;
        }
    const double inflow = units::mlPerMinToM3PerS(p.get("reference_inflow_ml_min"));
    const double drop = units::mmHgToPa(p.get("reference_pressure_drop_mmhg"));
    for (const auto& [node, cube] : ends)
        if (!explicitNodes.count(node))
            network.outlets.push_back({node, VesselNetwork::Outlet::Type::Resistance,
                                       units::mmHgToPa(p.get("outlet_pressure_mmhg")), drop / (inflow * cube / total)});
}

NetworkRunResult runNetwork(const NetworkRunSetup& setup, const Progress& progress)
{
    const auto started = std::chrono::steady_clock::now();
    const ParameterSet& p = setup.parameters;
    const TwoPhaseMixture fluid = networkMixture(p);
    NetworkRunResult r;
    r.network = setup.network;
    VesselNetwork& net = r.network;
    net.validate();
    if (net.root < 0)
        net.root = largestEnd(net);
    if (!setup.feederEdits.empty() && !setup.liver)
        throw Error("feeders are edited on a run with a liver label: give the liver (and the tumour) first");
    if (setup.inletSegment)
        net = treeBeyond(net, *setup.inletSegment);
    if (setup.tipNode)
        r.tipNode = *setup.tipNode;
    else if (setup.tipPointMm)
        r.tipNode = placeNode(net, *setup.tipPointMm, p.get("tip_snap_mm"), p.get("tip_reach_mm"));
    else
        r.tipNode = net.root;
    orientFromTip(net, r.tipNode); // a tip off the tree is refused before the territories' work
    const auto territoriesStarted = std::chrono::steady_clock::now();
    if (setup.liver)
    {
        const std::optional<LabelRegion> tumour =
            setup.tumourLabel ? std::optional<LabelRegion>(setup.tumourLabel->region()) : std::nullopt;
        r.territories = std::make_shared<const LiverTerritories>(
            liverTerritories(net, setup.liver->region(), tumour ? &*tumour : nullptr, p, progress.subRange(0.0, 0.1),
                             setup.tumour));
        r.lesions = findLesions(*r.territories);
    }
    const double territorySeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - territoriesStarted).count();
    const bool outletsByTissue = r.territories && p.get("outlet_model") > 0.5;
    if (outletsByTissue && setup.defaultOutlets)
        addTerritoryOutlets(net, *r.territories, p);
    if (setup.defaultOutlets)
        addDefaultOutlets(net, p);
    if (setup.tumour && !r.territories) // with a liver, the tumour is its lesions (Territories.h)
    {
        r.tumourOutlets = feedingOutlets(net, setup.tumour);
        const std::set<int> feeders(r.tumourOutlets.begin(), r.tumourOutlets.end());
        for (VesselNetwork::Outlet& outlet : net.outlets)
            if (!outletsByTissue && feeders.count(outlet.node) && outlet.type == VesselNetwork::Outlet::Type::Resistance)
                outlet.resistance *= p.get("tumour_resistance_factor");
        if (r.tumourOutlets.empty())
            r.warnings.push_back(storedText("no outlet of the tree ends inside the tumour: nothing feeds it"));
    }
    const bool withBlood = p.get("blood_flow") > 0.5;
    if (withBlood && setup.tipPressurePa)
        throw Error("a tip pressure drives the injected drug alone (blood_flow=0); with blood flow the injection is "
                    "a rate");
    const Injection injection = setup.tipPressurePa ? Injection{r.tipNode, 0.0, *setup.tipPressurePa}
                                                    : Injection{r.tipNode, units::mlPerMinToM3PerS(p.get("injection_rate_ml_min")), 0.0};
    BloodFlowSetup blood;
    blood.inletRate = units::mlPerMinToM3PerS(p.get("arterial_inflow_ml_min"));
    blood.inletHeldAtPressure = !(blood.inletRate > 0.0);
    blood.inletPressure = units::mmHgToPa(p.get("arterial_pressure_mmhg"));
    blood.injectionRate = injection.volumeRate;
    blood.catheterRadius = 0.5 * units::mmToM(p.get("catheter_outer_diameter_fr") / 3.0);
    blood.bloodViscosity = 1e-3 * p.get("blood_viscosity_mpa_s");
    auto withBloodAt = [&](int tip, double viscosity) {
        BloodFlowSetup at = blood;
        at.tipNode = tip;
        at.injectateViscosity = viscosity;
        return solveBloodFlow(net, at);
    };
    // The flow with the tip at a node: the run's model, the injected mixture's viscosity.
    const TipSolve solveAt = [&](int tip) {
        return withBlood ? withBloodAt(tip, fluid.viscosity()).flow
                         : solveFlow(net, {tip, injection.volumeRate, injection.pressure}, fluid.viscosity());
    };
    FlowSolution samePressure;
    if (withBlood)
    {
        r.blood = withBloodAt(r.tipNode, fluid.viscosity());
        const BloodFlowSolution liquid = withBloodAt(r.tipNode, fluid.phases.liquidViscosity);
        r.twoPhase = r.blood->flow;
        r.liquid = liquid.flow;
        for (const BloodFlowSolution* b : {static_cast<const BloodFlowSolution*>(&*r.blood), &liquid})
            r.status.recordSolve(b->iterations, b->residual, blood.tolerance, blood.maxIterations);
        if (r.blood->wedged)
            r.warnings.push_back(storedText(Pattern{
                "wedged catheter: %1; the injection refluxes or stops the blood flow at the tip", {r.blood->wedgedBecause}}));
        if (r.blood->refluxShare > 1e-9)
            r.warnings.push_back(storedText(Pattern{
                "%1 % of the injected drug refluxes past the catheter's tip (non-target delivery)",
                {std::to_string(int(std::lround(100.0 * r.blood->refluxShare)))}}));
    }
    else
    {
        r.twoPhase = solveFlow(net, injection, fluid.viscosity());
        r.liquid = solveFlow(net, injection, fluid.phases.liquidViscosity);
        samePressure = setup.tipPressurePa ? r.twoPhase
                                           : solveFlow(net, {r.tipNode, 0.0, r.liquid.tipPressure}, fluid.viscosity());
    }
    const double rate = r.twoPhase.injectedFlow;
    if (!(rate > 0.0))
        throw Error("the tip pressure does not drive any flow into the network (it is at or below the outlets')");
    r.filling = fillingTimes(net, r.twoPhase);
    progress.report(0.2, localized("vsim::Progress", "flow solved"));

    const std::vector<Eigen::Vector3d> points =
        setup.controlPointsMm.empty() ? defaultControlPoints(net, r.twoPhase) : setup.controlPointsMm;
    for (std::size_t i = 0; i < points.size(); ++i)
    {
        ControlPoint c;
        c.name = std::string(1, char('A' + std::min<std::size_t>(i, 25)));
        c.pointMm = points[i];
        const auto [segment, distance] =
            nearestSegment(net, points[i], [&](int s) { return r.twoPhase.orientation.active(s); });
        if (segment < 0 || distance > p.get("tip_reach_mm"))
            throw Error(Pattern{"control point %1 is not on the tree downstream of the tip", {c.name}});
        c.segment = segment;
        const std::size_t s = std::size_t(segment);
        const double twoPhaseFlow = std::abs(r.twoPhase.segmentFlow[s]), liquidFlow = std::abs(r.liquid.segmentFlow[s]);
        const double twoPhase = fluid.liquidFraction() * injectateShare(r.twoPhase, s) * twoPhaseFlow;
        const double liquid = injectateShare(r.liquid, s) * liquidFlow;
        c.drugFlowTwoPhaseMlMin = units::m3PerSToMlPerMin(twoPhase);
        c.drugFlowLiquidMlMin = units::m3PerSToMlPerMin(liquid);
        c.dropPercent = liquid > 0.0 ? 100.0 * (1.0 - twoPhase / liquid) : 0.0;
        c.splitShiftPercent = liquidFlow > 0.0 ? 100.0 * (twoPhaseFlow / liquidFlow - 1.0) : 0.0;
        r.controls.push_back(c);
        const std::string key = "control_" + c.name + "_";
        r.metrics[key + "drug_flow_two_phase_ml_min"] = c.drugFlowTwoPhaseMlMin;
        r.metrics[key + "drug_flow_liquid_ml_min"] = c.drugFlowLiquidMlMin;
        r.metrics[key + "drop_percent"] = c.dropPercent;
        r.metrics[key + "split_shift_percent"] = c.splitShiftPercent;
        if (!withBlood)
        {
            const double pressureDriven = fluid.liquidFraction() * std::abs(samePressure.segmentFlow[s]);
            c.dropAtSamePressurePercent = liquid > 0.0 ? 100.0 * (1.0 - pressureDriven / liquid) : 0.0;
            r.metrics[key + "drop_same_pressure_percent"] = c.dropAtSamePressurePercent;
        }
    }
    if (r.territories)
    {
        r.metrics["territory_seconds"] = territorySeconds;
        describeTerritory(r, net, solveAt, setup.rankTips, setup.feederEdits, progress.subRange(0.2, 0.95));
    }
    else if (setup.tumour)
    {
        r.metrics["tumour_outlets"] = double(r.tumourOutlets.size());
        r.metrics["tumour_fraction"] = deliveredFraction(r.twoPhase, r.tumourOutlets);
        r.metrics["non_target_fraction"] = 1.0 - r.metrics["tumour_fraction"];
        if (setup.rankTips && !r.tumourOutlets.empty())
        {
            r.ranking = rankTipPositions(net, r.tumourOutlets, solveAt, progress.subRange(0.2, 0.95));
            recordBestTip(r, net);
        }
    }
    if (p.get("working_angle") > 0.5 && r.tipNode != net.root)
    {
        const auto started = std::chrono::steady_clock::now();
        const WorkingAngle& w = *(r.workingAngle = workingAngle(net, r.tipNode, progress.subRange(0.95, 0.99)));
        r.metrics["working_lao_deg"] = w.angles.laoDeg;
        r.metrics["working_cranial_deg"] = w.angles.cranialDeg;
        r.metrics["working_foreshortening_percent"] = 100.0 * w.quality.foreshortening;
        r.metrics["working_overlap_percent"] = 100.0 * w.quality.overlap;
        r.metrics["frontal_foreshortening_percent"] = 100.0 * w.frontal.foreshortening;
        r.metrics["frontal_overlap_percent"] = 100.0 * w.frontal.overlap;
        r.metrics["working_angle_views"] = w.evaluated;
        r.metrics["working_path_start_node"] = w.pathStart;
        r.metrics["working_angle_seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    }
    setFields(r, fluid, p.get("blood_density"));
    if (fluid.voidFraction > kBubblyVoidFractionLimit)
        r.warnings.push_back(storedText(Pattern{"a void fraction of %1 is past bubbly flow (about 0.25): the "
                                                "homogeneous model and the thesis's experiment do not cover it",
                                                {numberText(fluid.voidFraction)}}));
    double downstream = 0.0;
    for (std::size_t s = 0; s < net.segments.size(); ++s)
        downstream += r.twoPhase.orientation.active(int(s)) ? 1.0 : 0.0;
    const double bubbleVolume = std::numbers::pi / 6.0 * std::pow(units::mmToM(p.get("bubble_diameter_mm")), 3.0);
    r.metrics["injection_rate_ml_min"] = units::m3PerSToMlPerMin(rate);
    r.metrics["injection_mass_rate_g_min"] = units::m3PerSToMlPerMin(rate) * fluid.density() * 1e-3; // ml/min * g/ml
    r.metrics["void_fraction"] = fluid.voidFraction;
    r.metrics["mixture_density_kg_m3"] = fluid.density();
    r.metrics["mixture_viscosity_mpa_s"] = 1e3 * fluid.viscosity();
    r.metrics["bubble_rate_per_s"] = units::mlPerMinToM3PerS(p.get("gas_absorption_ml_min")) / bubbleVolume;
    r.metrics["tip_node"] = r.tipNode;
    r.metrics["tip_pressure_mmhg"] = units::paToMmHg(r.twoPhase.tipPressure);
    r.metrics["tip_pressure_liquid_mmhg"] = units::paToMmHg(r.liquid.tipPressure);
    r.metrics["downstream_segments"] = downstream;
    r.metrics["outlets"] = double(r.twoPhase.orientation.outlets.size());
    r.metrics["conservation_error"] = r.twoPhase.conservationError;
    r.metrics["blood_flow"] = withBlood ? 1.0 : 0.0;
    if (r.blood)
    {
        const BloodFlowSolution& b = *r.blood;
        r.metrics["arterial_inflow_ml_min"] = units::m3PerSToMlPerMin(b.inletFlow);
        r.metrics["root_pressure_mmhg"] = units::paToMmHg(b.flow.nodePressure[std::size_t(net.root)]);
        r.metrics["tip_own_flow_ml_min"] = units::m3PerSToMlPerMin(b.ownFlow);
        r.metrics["tip_blood_inflow_ml_min"] = units::m3PerSToMlPerMin(b.tipInflow);
        r.metrics["tip_injected_percent"] = 100.0 * b.tipFraction;
        r.metrics["tip_drug_percent"] = 100.0 * b.tipFraction * fluid.liquidFraction();
        r.metrics["catheter_occlusion_percent"] = 100.0 * b.occlusion;
        r.metrics["catheter_segments"] = double(b.catheterSegments.size());
        r.metrics["wedged"] = b.wedged ? 1.0 : 0.0;
        r.metrics["reflux_percent"] = 100.0 * b.refluxShare;
        r.metrics["injected_balance_error"] = b.balance.relativeError();
        r.metrics["coupling_iterations"] = b.iterations;
        r.metrics["coupling_residual"] = b.residual;
    }
    // The direct (LDL^T) solves: Kirchhoff's balance at every node is the residual, relative to the injected flow.
    for (const FlowSolution* solution : {&r.twoPhase, &r.liquid})
        r.status.recordSolve(0, solution->conservationError, kConservationTolerance, 0);
    for (const auto& [key, value] : r.status.metrics())
        r.metrics[key] = value;
    r.metrics["last_arrival_s"] = r.filling.lastArrival;
    double first = kNever;
    for (const auto& [node, time] : r.filling.arrival)
        first = std::min(first, time);
    r.metrics["first_arrival_s"] = first == kNever ? -1.0 : first;
    progress.report(1.0, localized("vsim::Progress", "done"));
    r.metrics["wall_clock_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return r;
}

} // namespace vsim::sim::network
