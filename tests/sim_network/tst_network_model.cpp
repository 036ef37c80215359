// The drug network's pieces against closed forms: two-phase properties (eq. 6.2, 6.3), the filled length of a
// cone, plug filling of a chain, the part downstream of the tip, splitting a segment at a point, Murray-law
// outlets, the two-phase / liquid control-point comparison, tumour targeting, blood carrying the drug (the mixed
// fraction, the catheter, a wedged catheter's reflux); and bad input refused with a message naming the node or
// segment.

#include "vsim/core/Error.h"
#include "vsim/core/Units.h"
#include "vsim/sim/network/ConicalPipe.h"
#include "vsim/sim/network/Filling.h"
#include "vsim/sim/network/FillingSolver.h"
#include "vsim/sim/network/Inlet.h"
#include "vsim/sim/network/NetworkBuild.h"
#include "vsim/sim/network/NetworkRun.h"
#include "vsim/sim/network/Tracers.h"
#include "vsim/sim/network/WorkingAngle.h"

#include <QtTest>

#include <cmath>
#include <numbers>
#include <set>

using namespace vsim;
using namespace vsim::sim::network;

namespace {

/// A network of straight segments {from, to, r1, r2} between the given node positions (mm); lengths from them.
VesselNetwork makeNetwork(const std::vector<Eigen::Vector3d>& positions, const std::vector<std::array<double, 4>>& segments)
{
    VesselNetwork network;
    for (const Eigen::Vector3d& p : positions)
        network.nodes.push_back({p, {}});
    for (const auto& [from, to, r1, r2] : segments)
    {
        VesselNetwork::Segment s;
        s.from = int(from), s.to = int(to), s.startRadiusMm = r1, s.endRadiusMm = r2;
        s.lengthMm = (positions[std::size_t(from)] - positions[std::size_t(to)]).norm();
        network.segments.push_back(s);
    }
    network.root = 0;
    return network;
}

/// Root 0 -> junction 1 -> junctions 2 and 3 -> leaves 4, 5 (under 2) and 6, 7 (under 3).
VesselNetwork binaryTree()
{
    return makeNetwork({{0, 0, 0}, {0, 0, 20}, {-10, 0, 35}, {10, 0, 35}, {-15, 0, 45}, {-5, 0, 45}, {5, 0, 45}, {15, 0, 45}},
                       {{0, 1, 2.0, 1.8}, {1, 2, 1.4, 1.3}, {1, 3, 1.4, 1.3}, {2, 4, 1.0, 0.9}, {2, 5, 1.0, 0.9},
                        {3, 6, 1.0, 0.9}, {3, 7, 1.0, 0.9}});
}

template <typename F>
QString messageOf(F&& f)
{
    try
    {
        f();
    }
    catch (const Error& error)
    {
        return QString::fromStdString(error.message());
    }
    return {};
}

} // namespace

class NetworkModel : public QObject
{
    Q_OBJECT
private slots:
    void twoPhaseProperties()
    {
        TwoPhaseMixture fluid;
        fluid.voidFraction = 0.1;
        QCOMPARE(fluid.density(), 1060.0 * 0.9 + 1.205 * 0.1);
        QCOMPARE(fluid.viscosity(), 0.1 * 18.6e-6 + 0.9 * 3.56e-3);
        fluid.voidFraction = 0.0;
        QCOMPARE(fluid.density(), 1060.0);
        for (double bad : {-0.01, 1.0, std::nan("")})
        {
            fluid.voidFraction = bad;
            QVERIFY(messageOf([&] { fluid.validate(); }).contains("void fraction"));
        }
    }

    void filledLengthInvertsTheConeVolume()
    {
        const double r1 = 2e-3, r2 = 0.8e-3, length = 0.03;
        for (double x : {0.0, 1e-4, 0.007, 0.015, 0.0299, 0.03})
            QVERIFY(std::abs(filledLength(r1, r2, length, conicalVolume(r1, r2, length, x)) - x) <= 1e-12 * length);
        QCOMPARE(filledLength(r1, r2, length, -1.0), 0.0);
        QCOMPARE(filledLength(r1, r2, length, 1.0), length);
        // The resistance of two halves adds up to the whole (the integral of eq. 6.4 is additive).
        VesselNetwork n = makeNetwork({{0, 0, 0}, {0, 0, 30}}, {{0, 1, 2.0, 0.8}});
        const double whole = segmentResistance(n.segments[0], 3.56e-3);
        const int middle = placeNode(n, {0.2, 0, 15}, 0.5, 5.0);
        QCOMPARE(middle, 2);
        QCOMPARE(n.segments[0].endRadiusMm, 1.4);
        QCOMPARE(n.segments[1].startRadiusMm, 1.4);
        QVERIFY(std::abs(segmentResistance(n.segments[0], 3.56e-3) + segmentResistance(n.segments[1], 3.56e-3) - whole) <=
                1e-12 * whole);
    }

    // Plug filling of a chain of two cylinders: each fills in V / Q after the one before.
    void fillingOfAChain()
    {
        VesselNetwork n = makeNetwork({{0, 0, 0}, {0, 0, 10}, {0, 0, 30}}, {{0, 1, 1.0, 1.0}, {1, 2, 0.5, 0.5}});
        n.outlets = {{2, VesselNetwork::Outlet::Type::Pressure, 0.0, 0.0}};
        const double q = units::mlPerMinToM3PerS(2.0);
        const FlowSolution flow = solveFlow(n, {0, q, 0.0}, 3.56e-3);
        const FillingTimes times = fillingTimes(n, flow);
        const double v1 = std::numbers::pi * 1e-6 * 0.01, v2 = std::numbers::pi * 0.25e-6 * 0.02;
        QVERIFY(std::abs(times.leave[0] - v1 / q) <= 1e-12 * times.leave[0]);
        QVERIFY(std::abs(times.leave[1] - (v1 + v2) / q) <= 1e-12 * times.leave[1]);
        QCOMPARE(times.arrival.at(2), times.leave[1]);
        std::vector<double> lengths;
        filledLengths(n, flow, times, 0.5 * times.leave[0], lengths);
        QVERIFY(std::abs(lengths[0] - 5.0) <= 1e-9);
        QCOMPARE(lengths[1], 0.0);
        filledLengths(n, flow, times, times.leave[1] + 1.0, lengths);
        QCOMPARE(lengths[1], 20.0);
    }

    void downstreamOfTheTipOnly()
    {
        const VesselNetwork n = binaryTree();
        const TipOrientation o = orientFromTip(n, 2);
        QVERIFY(!o.active(0) && !o.active(1) && !o.active(2) && !o.active(5) && !o.active(6));
        QVERIFY(o.active(3) && o.active(4));
        QCOMPARE(o.outlets, (std::vector<int>{4, 5}));
        QVERIFY(messageOf([&] { orientFromTip(n, 6); }).contains("nothing is downstream"));
    }

    // Terminal resistances by Murray's law split the flow as the radius cubed when they dominate.
    void murrayOutlets()
    {
        VesselNetwork n = makeNetwork({{0, 0, 0}, {0, 0, 10}, {-5, 0, 20}, {5, 0, 20}},
                                      {{0, 1, 2.0, 2.0}, {1, 2, 1.0, 1.0}, {1, 3, 1.5, 1.5}});
        for (auto& s : n.segments)
            s.resistance = 1.0; // negligible against the terminal resistances
        ParameterSet p(networkParameters());
        addDefaultOutlets(n, p);
        QCOMPARE(n.outlets.size(), std::size_t(2));
        const FlowSolution flow = solveFlow(n, {0, 1e-8, 0.0}, 3.56e-3);
        qInfo("outlet flows %.6g / %.6g = %.8f (r^3 ratio %.8f)", flow.outletFlow.at(2), flow.outletFlow.at(3),
              flow.outletFlow.at(2) / flow.outletFlow.at(3), 1.0 / 3.375);
        QVERIFY(std::abs(flow.outletFlow.at(2) / flow.outletFlow.at(3) - 1.0 / 3.375) <= 1e-6);
    }

    // A terminal resistance of zero holds its outlet at the pressure, as a pressure condition does.
    void zeroTerminalResistanceIsAPressure()
    {
        VesselNetwork n = binaryTree();
        for (int node : {4, 5, 6, 7})
            n.outlets.push_back({node, VesselNetwork::Outlet::Type::Pressure, 100.0 * node, 0.0});
        const FlowSolution pressure = solveFlow(n, {0, 1e-8, 0.0}, 3.56e-3);
        for (auto& outlet : n.outlets)
            outlet.type = VesselNetwork::Outlet::Type::Resistance;
        const FlowSolution zero = solveFlow(n, {0, 1e-8, 0.0}, 3.56e-3);
        for (int node : {4, 5, 6, 7})
            QCOMPARE(zero.outletFlow.at(node), pressure.outletFlow.at(node));
        QCOMPARE(zero.nodePressure[4], 400.0);
    }

    // Two-phase against liquid at the same injected rate: the drug flow at A and B drops by about the void fraction.
    void controlPointComparison()
    {
        NetworkRunSetup setup;
        setup.network = binaryTree();
        setup.parameters.set("void_fraction", 0.1);
        const NetworkRunResult r = runNetwork(setup);
        QCOMPARE(r.controls.size(), std::size_t(2));
        for (const ControlPoint& c : r.controls)
        {
            qInfo("control %s: two-phase %.4f ml/min, liquid %.4f ml/min, drop %.2f %%, split shift %.2e %%",
                  c.name.c_str(), c.drugFlowTwoPhaseMlMin, c.drugFlowLiquidMlMin, c.dropPercent, c.splitShiftPercent);
            QVERIFY(c.dropPercent > 9.9 && c.dropPercent < 10.1);
            QVERIFY(std::abs(c.drugFlowLiquidMlMin - 1.0) <= 1e-9); // the symmetric tree halves 2 ml/min
        }
        QVERIFY(r.metrics.at("conservation_error") <= 1e-12);
        QVERIFY(r.metrics.at("last_arrival_s") > 0.0);
        QCOMPARE(r.network.segmentFields.at("flow_ml_min").size(), r.network.segments.size());
    }

    // The tumour fed by leaves 4 and 5: the root delivers half, junction 2 all; junction 2 ranks first.
    void targeting()
    {
        NetworkRunSetup setup;
        setup.network = binaryTree();
        setup.tumour = TumourSphere{Eigen::Vector3d(-10, 0, 45), 6.0}.region();
        const NetworkRunResult r = runNetwork(setup);
        QCOMPARE(r.tumourOutlets, (std::vector<int>{4, 5}));
        QVERIFY(std::abs(r.metrics.at("tumour_fraction") - 0.5) <= 1e-9);
        QCOMPARE(int(r.metrics.at("best_tip_node")), 2);
        QVERIFY(std::abs(r.metrics.at("best_tip_fraction") - 1.0) <= 1e-12);
        QCOMPARE(r.ranking.back().tumourFraction, 0.0); // junction 3 feeds the other side
    }

    // Tracers move with the plug flow: one released at 0 stands where the filling front stands; they go to the
    // outlets in proportion to the outlet flows; a trail starts at its head.
    void tracersFollowTheFront()
    {
        VesselNetwork n = makeNetwork({{0, 0, 0}, {0, 0, 10}, {0, 0, 30}}, {{0, 1, 1.0, 1.0}, {1, 2, 0.5, 0.5}});
        n.outlets = {{2, VesselNetwork::Outlet::Type::Pressure, 0.0, 0.0}};
        const FlowSolution flow = solveFlow(n, {0, units::mlPerMinToM3PerS(2.0), 0.0}, 3.56e-3);
        const FillingTimes times = fillingTimes(n, flow);
        std::vector<double> lengths;
        for (double t : {0.3 * times.leave[0], 0.5 * (times.leave[0] + times.leave[1])})
        {
            Eigen::Vector3d where;
            QVERIFY(tracerPosition(n, flow, 2, t, where));
            filledLengths(n, flow, times, t, lengths);
            const double front = t < times.leave[0] ? lengths[0] : 10.0 + lengths[1];
            QVERIFY(std::abs(where.z() - front) <= 1e-9);
        }
        Eigen::Vector3d gone;
        QVERIFY(!tracerPosition(n, flow, 2, times.leave[1] + 1.0, gone));

        const VesselNetwork tree = binaryTree();
        NetworkRunSetup setup;
        setup.network = tree;
        const NetworkRunResult r = runNetwork(setup);
        TracerSettings settings;
        settings.releaseEveryS = r.filling.lastArrival / 40.0;
        settings.trailSpacingS = r.filling.lastArrival / 200.0;
        const auto trails = tracerTrails(r.network, r.twoPhase, 0.5 * r.filling.lastArrival, settings);
        QVERIFY(trails.size() >= 10);
        for (const auto& trail : trails)
            QVERIFY(trail.size() >= 2 && trail.front().z() >= trail.back().z()); // the tree runs to +z: head first
    }

    // Issue 17: the filling on the run driver: 101 frames in equal times to the last arrival, each frame's
    // filled_length_mm the closed-form filled lengths at its time, empty at 0 and every segment on the way to an
    // outlet full at the end; the status is the steady solves'.
    void fillingRunOnTheDriver()
    {
        NetworkRunSetup setup;
        setup.network = binaryTree();
        const NetworkRunResult r = runNetwork(setup);
        const SolverRun run = fillingRun(r, 100);
        QCOMPARE(run.frames.size(), std::size_t(101));
        QCOMPARE(run.status.stoppedBy, RunStatus::StoppedBy::End);
        QCOMPARE(run.status.solves, r.status.solves);
        QVERIFY(run.status.converged());
        QCOMPARE(run.axis.target, r.filling.lastArrival);
        std::vector<double> expected;
        for (const RunFrame& frame : run.frames)
        {
            QVERIFY(std::abs(frame.position - frame.step * r.filling.lastArrival / 100.0) <= 1e-12 * r.filling.lastArrival);
            filledLengths(r.network, r.twoPhase, r.filling, frame.position, expected);
            const VesselNetwork& n = std::get<VesselNetwork>(frame.data);
            QCOMPARE(n.segmentFields.at("filled_length_mm"), expected);
            QCOMPARE(n.segmentFields.at("flow_ml_min"), r.network.segmentFields.at("flow_ml_min"));
        }
        for (double length : std::get<VesselNetwork>(run.frames.front().data).segmentFields.at("filled_length_mm"))
            QCOMPARE(length, 0.0);
        for (double fraction : std::get<VesselNetwork>(run.frames.back().data).segmentFields.at("filled_fraction"))
            QCOMPARE(fraction, 1.0);
    }

    // Blood carries the drug: with the tip at junction 2, the blood reaching it and the injection mix there; every
    // segment below carries the same fraction q / (blood + q), the rest of the tree none; the drug leaves only
    // through 4 and 5, and all of it does. The catheter's annulus lowers the vessel's own flow at the tip.
    void bloodCarriesTheDrug()
    {
        NetworkRunSetup setup;
        setup.network = binaryTree();
        setup.tipNode = 2;
        const NetworkRunResult r = runNetwork(setup);
        QVERIFY(r.blood);
        const BloodFlowSolution& b = *r.blood;
        const double q = units::mlPerMinToM3PerS(2.0);
        const double below = q / (b.tipInflow + q);
        qInfo("inflow %.2f ml/min at 90 mmHg; own flow at the tip %.3f ml/min, with the injection %.3f ml/min; "
              "fraction below the tip %.6f; %d fixed-point iterations, residual %.1e",
              units::m3PerSToMlPerMin(b.inletFlow), units::m3PerSToMlPerMin(b.ownFlow),
              units::m3PerSToMlPerMin(b.tipInflow), below, b.iterations, b.residual);
        QVERIFY(b.converged && b.iterations >= 2);
        QVERIFY(b.tipInflow > 0.0 && b.tipInflow < b.ownFlow); // the injection raises the tip's pressure
        QCOMPARE(b.catheterSegments, (std::vector<int>{0, 1}));
        for (int s : {3, 4})
            QVERIFY(std::abs(r.twoPhase.injectateFraction[std::size_t(s)] / below - 1.0) <= 1e-12);
        for (int s : {0, 1, 2, 5, 6})
            QCOMPARE(r.twoPhase.injectateFraction[std::size_t(s)], 0.0);
        QVERIFY(std::abs(r.twoPhase.outletInjectate.at(4) + r.twoPhase.outletInjectate.at(5) - q) <= 1e-12 * q);
        QCOMPARE(r.twoPhase.outletInjectate.at(6), 0.0);
        QVERIFY(b.balance.relativeError() <= 1e-12);
        QVERIFY(!b.wedged && b.refluxShare == 0.0);
        QVERIFY(r.status.converged());

        // The catheter: none, 2.7 Fr, 4 Fr in the same vessels; the own flow falls as it fills more of the lumen.
        double previous = 1e300;
        for (double french : {0.0, 2.7, 4.0})
        {
            setup.parameters.set("catheter_outer_diameter_fr", french);
            const double own = runNetwork(setup).blood->ownFlow;
            QVERIFY(own < previous);
            previous = own;
        }
    }

    // A wedged catheter: an injection above the vessel's own flow refluxes into the sibling branches (the drug
    // reaches outlets 6 and 7, not downstream of the tip), and a catheter filling most of the lumen is flagged.
    void wedgedCatheterRefluxes()
    {
        NetworkRunSetup setup;
        setup.network = binaryTree();
        setup.tipNode = 2;
        setup.parameters.set("catheter_outer_diameter_fr", 2.0);
        const double own = units::m3PerSToMlPerMin(runNetwork(setup).blood->ownFlow);
        setup.parameters.set("injection_rate_ml_min", 1.5 * own);
        const NetworkRunResult r = runNetwork(setup);
        const BloodFlowSolution& b = *r.blood;
        qInfo("own flow %.2f ml/min, injecting %.2f: blood at the tip %.3f ml/min, reflux %.1f %% of the drug",
              own, 1.5 * own, units::m3PerSToMlPerMin(b.tipInflow), 100.0 * b.refluxShare);
        QVERIFY(b.wedged && b.tipInflow < 0.0);
        QVERIFY(b.refluxShare > 0.01 && r.twoPhase.outletInjectate.at(6) > 0.0);
        QVERIFY(std::abs(b.refluxShare - (r.twoPhase.outletInjectate.at(6) + r.twoPhase.outletInjectate.at(7)) /
                                             b.balance.injected) <= 1e-9);
        QVERIFY(b.balance.relativeError() <= 1e-12);
        QVERIFY(std::any_of(r.warnings.begin(), r.warnings.end(), [](const std::string& w) { return w.find("refluxes") != std::string::npos; }));

        setup.parameters.set("injection_rate_ml_min", 2.0);
        setup.parameters.set("catheter_outer_diameter_fr", 6.5); // 2.17 mm in a 1.3 mm lumen (radius) at the tip
        const BloodFlowSolution occluded = *runNetwork(setup).blood;
        QVERIFY(occluded.wedged && occluded.occlusion >= kWedgeOcclusion);
        QVERIFY(QString::fromStdString(occluded.wedgedBecause).contains("of the lumen at the tip"));
    }

    // Blood entering through a chosen segment (Inlet.h): the tree beyond it is kept and renumbered, its upper end the
    // root held at the arterial pressure; the tip is a node of the kept tree, as the result numbers them; a node it
    // lacks, an unknown name and a point far from the tree are refused with what the tree offers.
    void inletSegmentCutsTheTree()
    {
        VesselNetwork tree = binaryTree();
        tree.segments[1].name = "Common hepatic artery";
        tree.segments[2].name = "splenic artery";
        QCOMPARE(inletSegment(tree, "common HEPATIC artery"), 1);
        QCOMPARE(inletSegment(tree, "2"), 2);
        QVERIFY(messageOf([&] { inletSegment(tree, "celiac trunk"); }).contains("Common hepatic artery, splenic artery"));
        QVERIFY(messageOf([&] { inletSegment(tree, "9"); }).contains("does not exist"));
        std::vector<int> map;
        const VesselNetwork kept = treeBeyond(tree, 1, &map);
        QCOMPARE(kept.segments.size(), std::size_t(3));
        QCOMPARE(map, (std::vector<int>{-1, 0, 1, -1, 2, 3, -1, -1}));
        QCOMPARE(kept.root, 0);
        QCOMPARE(kept.segments[0].name, std::string("Common hepatic artery"));

        NetworkRunSetup setup;
        setup.network = tree;
        setup.inletSegment = 1;
        setup.tipNode = 1; // the whole tree's node 2
        const NetworkRunResult r = runNetwork(setup);
        QCOMPARE(r.tipNode, 1);
        QCOMPARE(r.network.segments.size(), std::size_t(3));
        QVERIFY(std::abs(r.metrics.at("root_pressure_mmhg") - 90.0) <= 1e-9);
        QCOMPARE(r.blood->catheterSegments, (std::vector<int>{0}));
        QVERIFY(r.blood->balance.relativeError() <= 1e-12 && r.status.converged());
        // Held at 90 mmHg one junction further down, the hepatic branch takes more than it did behind the trunk.
        NetworkRunSetup whole;
        whole.network = tree;
        whole.tipNode = 2;
        QVERIFY(r.blood->inletFlow > runNetwork(whole).twoPhase.segmentFlow[1]);
        setup.tipNode = 4; // the kept tree has four nodes
        QVERIFY(messageOf([&] { runNetwork(setup); }).contains("not in the network"));
        QCOMPARE(inletSegment(tree, "-4, 0, 28"), 1); // a point beside the hepatic branch
        QVERIFY(messageOf([&] { inletSegment(tree, "-40, 0, 28"); }).contains("from the nearest vessel"));
    }

    // The working angle's path starts at the common hepatic artery where the tree names it (the guiding catheter
    // sits there, and a selective injection opacifies only what lies beyond it), else at the root.
    void workingPathFromTheCommonHepatic()
    {
        VesselNetwork tree = binaryTree();
        auto segmentsOf = [](const std::vector<AngleScene::Piece>& pieces) {
            std::set<int> segments;
            for (const auto& piece : pieces)
                segments.insert(piece.segment);
            return segments;
        };
        const AngleScene fromRoot = angleScene(tree, 2);
        QCOMPARE(fromRoot.start, 0);
        QCOMPARE(segmentsOf(fromRoot.path), (std::set<int>{0, 1}));
        QCOMPARE(segmentsOf(fromRoot.others), (std::set<int>{2, 3, 4, 5, 6}));
        tree.segments[1].name = "Common Hepatic Artery";
        const AngleScene scene = angleScene(tree, 2);
        QCOMPARE(scene.start, 1);
        QCOMPARE(segmentsOf(scene.path), (std::set<int>{1}));
        QCOMPARE(segmentsOf(scene.others), (std::set<int>{3, 4})); // not the trunk, nor the sibling branch (2, 5, 6)
        NetworkRunSetup setup;
        setup.network = tree;
        setup.tipNode = 2;
        QCOMPARE(runNetwork(setup).metrics.at("working_path_start_node"), 1.0);
    }

    // The injected-alone model (the thesis's) is still there, and the tip pressure belongs to it.
    void injectedAloneModel()
    {
        NetworkRunSetup setup;
        setup.network = binaryTree();
        setup.tipPressurePa = units::mmHgToPa(30.0);
        QVERIFY(messageOf([&] { runNetwork(setup); }).contains("with blood flow the injection is a rate"));
        setup.parameters.set("blood_flow", 0);
        const NetworkRunResult r = runNetwork(setup);
        QVERIFY(!r.blood && std::abs(units::paToMmHg(r.twoPhase.tipPressure) - 30.0) <= 1e-9);
        QVERIFY(r.twoPhase.injectateFraction.empty());
    }

    void badInputIsNamed()
    {
        VesselNetwork n = binaryTree();
        NetworkRunSetup setup;
        setup.network = n;
        setup.tipPointMm = Eigen::Vector3d(100, 100, 100);
        QVERIFY(messageOf([&] { runNetwork(setup); }).contains("from the vessel tree"));

        VesselNetwork zero = n;
        zero.segments[3].endRadiusMm = 0.0;
        QVERIFY(messageOf([&] { zero.validate(); }).contains("segment 3 has a radius that is zero"));

        VesselNetwork cycle = n;
        cycle.segments.push_back(cycle.segments[1]);
        cycle.segments.back().from = 4, cycle.segments.back().to = 5;
        QVERIFY(messageOf([&] { cycle.validate(); }).contains("segment 7 (nodes 4 - 5) closes a cycle"));

        VesselNetwork apart = n;
        apart.nodes.push_back({{50, 0, 0}, {}});
        apart.nodes.push_back({{60, 0, 0}, {}});
        apart.segments.push_back(apart.segments[0]);
        apart.segments.back().from = 8, apart.segments.back().to = 9;
        QVERIFY(messageOf([&] { orientFromTip(apart, 8); }).contains("not connected to its root"));

        setup.tipPointMm.reset();
        setup.defaultOutlets = false;
        QVERIFY(messageOf([&] { runNetwork(setup); }).contains("outlet node 4 has no boundary condition"));

        setup.defaultOutlets = true;
        QVERIFY(messageOf([&] { setup.parameters.set("void_fraction", 1.0); }).contains("void_fraction"));
    }
};

QTEST_APPLESS_MAIN(NetworkModel)
#include "tst_network_model.moc"
