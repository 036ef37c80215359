// The SPH solver's particle machinery (issue 18): the quartic kernel's closed form at known points, the
// neighbour grid against a brute-force search on random particles (three seeds, clustered and spread), and
// the validation cases sph-kernel and sph-fpm with their stated tolerances, the mixture and the reference
// pressure, the walls' Lennard-Jones backstop against a fin one particle thick, the through-the-wall guard's
// depths on a lattice-seeded curved wall, and the stenosis pipe at a faster flow (particle shifting:
// tst_sph_shifting.cpp; density by summation and the fluid loss guard: tst_sph_density.cpp).

#include "vsim/core/Error.h"
#include "vsim/sim/sph/FluidModel.h"
#include "vsim/sim/sph/NeighbourGrid.h"
#include "vsim/sim/sph/OpenBoundary.h"
#include "vsim/sim/sph/QuarticKernel.h"
#include "vsim/sim/sph/SphRates.h"
#include "vsim/sim/sph/SphSolver.h"
#include "vsim/sim/sph/SphValidation.h"
#include "vsim/sim/sph/StenosisPipe.h"

#include <QtTest>

#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <set>

using namespace vsim;
using namespace vsim::sim::sph;

namespace
{
/// The fin case's push: a body force of 0.03 c0^2 per spacing (over the block's 4 spacings a pressure of 0.12
/// rho0 c0^2, the fluid 12 % compressed: four times the density guard's 3 %; at 0.05 the backstop lets 25 of
/// 100 through, at 0.02 the fin alone 9).
constexpr double kFinBodyForce = 0.03;
} // namespace

class SphParticles : public QObject
{
    Q_OBJECT
private slots:
    /// W(0) = 315 / (208 pi h^3) * 2/3; W(h) = 315 / (208 pi h^3) (2/3 - 9/8 + 19/24 - 5/32) by hand; zero
    /// beyond 2h.
    void kernelClosedForm()
    {
        const double h = 1.3e-3, norm = 315.0 / (208.0 * std::numbers::pi * h * h * h);
        const QuarticKernel kernel(h);
        QCOMPARE(kernel.value(0.0), norm * 2.0 / 3.0);
        QVERIFY(std::abs(kernel.value(h) - norm * (2.0 / 3.0 - 9.0 / 8.0 + 19.0 / 24.0 - 5.0 / 32.0)) <
                1e-12 * norm);
        QCOMPARE(kernel.value(2.5 * h), 0.0);
        QCOMPARE(kernel.derivative(0.0), 0.0);
        QVERIFY(kernel.derivative(h) < 0.0);
        // The gradient points from j to i scaled by dW/dr: towards j (W falls with distance).
        const Eigen::Vector3d g = kernel.gradient(Eigen::Vector3d(h, 0, 0));
        QVERIFY(g.x() < 0.0 && g.y() == 0.0 && g.z() == 0.0);
        QVERIFY_THROWS_EXCEPTION(Error, QuarticKernel(0.0));
    }

    void neighbourGridMatchesBruteForce()
    {
        for (unsigned seed : {1u, 2u, 3u})
        {
            std::mt19937 random(seed);
            std::uniform_real_distribution<double> spread(-0.01, 0.01), cluster(-0.002, 0.002);
            std::vector<Eigen::Vector3d> positions;
            for (int i = 0; i < 600; ++i)
                positions.push_back(
                    i % 2 ? Eigen::Vector3d(spread(random), spread(random), spread(random))
                          : Eigen::Vector3d(cluster(random), cluster(random), 0.004 + cluster(random)));
            const double reach = 2.6e-3;
            NeighbourGrid grid(reach);
            grid.build(positions);
            const std::vector<int>& order = grid.order();
            QCOMPARE(std::set<int>(order.begin(), order.end()).size(), positions.size()); // a permutation
            for (int i = 0; i < int(positions.size()); ++i)
            {
                std::set<int> found;
                grid.forEachNeighbour(positions, i,
                                      [&](int j, const Eigen::Vector3d& rij, double r)
                                      {
                                          QVERIFY(std::abs(rij.norm() - r) < 1e-15);
                                          found.insert(j);
                                      });
                std::set<int> expected;
                for (int j = 0; j < int(positions.size()); ++j)
                    if (j != i && (positions[std::size_t(j)] - positions[std::size_t(i)]).norm() < reach)
                        expected.insert(j);
                QCOMPARE(found, expected);
            }
            // Reordered by cell (as the solver does now and then) and built again: the same neighbours.
            std::vector<Eigen::Vector3d> sorted = positions;
            grid.reorder(sorted);
            const std::vector<int> sortedToOriginal = order;
            grid.build(sorted);
            for (int i = 0; i < int(sorted.size()); i += 7)
            {
                std::set<int> found, expected;
                grid.forEachNeighbour(sorted, i,
                                      [&](int j, const Eigen::Vector3d&, double)
                                      { found.insert(sortedToOriginal[std::size_t(j)]); });
                const int original = sortedToOriginal[std::size_t(i)];
                for (int j = 0; j < int(positions.size()); ++j)
                    if (j != original &&
                        (positions[std::size_t(j)] - positions[std::size_t(original)]).norm() < reach)
                        expected.insert(j);
                QCOMPARE(found, expected);
            }
        }
        NeighbourGrid grid(1e-3);
        QVERIFY_THROWS_EXCEPTION(Error, grid.build({Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(NAN, 0, 0)}));
        QVERIFY_THROWS_EXCEPTION(Error,
                                 grid.build({Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1e3, 1e3, 1e3)}));
    }

    /// The two-phase mixture of thesis Table 5.1 (blood plasma and air at void fraction s) and Tait about its rest
    /// density: rho0(0.2) = 0.8 x 1060 + 0.2 x 1.205 = 848.241 kg/m^3, mu(0.2) = 0.8 x 3.56e-3 + 0.2 x 1.86e-5 Pa s.
    void mixtureProperties()
    {
        FluidModel fluid;
        fluid.viscosity = 3.56e-3;
        QVERIFY(std::abs(fluid.mixtureDensity(0.2) - 848.241) < 1e-9);
        QVERIFY(std::abs(fluid.mixtureViscosity(0.2) - 2.85172e-3) < 1e-12);
        QCOMPARE(fluid.mixtureDensity(0.0), 1060.0);
        QCOMPARE(fluid.pressure(fluid.mixtureDensity(0.2), 0.2), 0.0);
        for (double s : {0.0, 0.1, 0.16, 0.2})
            QVERIFY(std::abs(fluid.pressure(fluid.densityAt(5332.0, s), s) - 5332.0) < 1e-8); // 40 mmHg
        // The same density is a higher pressure in the lighter mixture.
        QVERIFY(fluid.pressure(900.0, 0.2) > 0.0 && fluid.pressure(900.0, 0.0) < 0.0);
    }

    /// The reference pressure (the outlets' gauge level, 50 mmHg here): the fluid at its rest density reports it, the
    /// equation of state works above it, and a boundary prescribed at 50 mmHg + 100 Pa imposes 100 Pa above it (a
    /// waveform scales the gauge pressure, not the one above the reference).
    void referencePressureIsTheGaugeLevel()
    {
        FluidModel fluid;
        fluid.referencePressurePa = 6666.0;
        QCOMPARE(fluid.reportedPressure(fluid.mixtureDensity(0.16), 0.16), 6666.0);
        QCOMPARE(fluid.pressure(fluid.mixtureDensity(0.16), 0.16), 0.0);
        QVERIFY(std::abs(fluid.reportedPressure(fluid.densityAt(100.0)) - 6766.0) < 1e-8);
        OpenBoundary outlet;
        outlet.name = "outlet", outlet.normal = Eigen::Vector3d::UnitX(), outlet.radiusM = 1e-3;
        outlet.prescribed = OpenBoundary::Prescribed::Pressure, outlet.pressurePa = 6766.0;
        outlet.waveform.points = {{0.0, 1.0}, {0.5, 0.5}, {1.0, 1.0}};
        OpenBoundaries boundaries({outlet});
        boundaries.setReferencePressure(6666.0);
        QVERIFY(std::abs(boundaries.prescribedPressure(0, 0.0, 0.0) - 100.0) < 1e-9);
        QVERIFY(std::abs(boundaries.prescribedPressure(0, 0.5, 0.0) - (0.5 * 6766.0 - 6666.0)) < 1e-9);
    }

    /// Without tension (SphSolver's fluid_tension 0: a liquid that breaks up) the density is held at the rest
    /// density or above, the pressure is never below 0 and the density guard reads compression only; with it (the
    /// default) no floor, Tait's negative pressure and |change|.
    void fluidWithoutTension()
    {
        FluidModel fluid;
        const double rho0 = fluid.mixtureDensity(0.2);
        QVERIFY(fluid.pressure(0.97 * rho0, 0.2) < -0.1 * fluid.stiffness(0.2));
        QVERIFY(std::abs(fluid.densityVariation(0.97 * rho0, 0.2) - 0.03) < 1e-12);
        QCOMPARE(fluid.densityFloor(0.2), 0.0);
        fluid.tension = false;
        QCOMPARE(fluid.densityFloor(0.2), rho0);
        QCOMPARE(fluid.pressure(0.97 * rho0, 0.2), 0.0);
        QCOMPARE(fluid.densityVariation(0.5 * rho0, 0.2), 0.0);
        QVERIFY(std::abs(fluid.densityVariation(1.02 * rho0, 0.2) - 0.02) < 1e-12);
        QVERIFY(std::abs(fluid.pressure(1.02 * rho0, 0.2) - fluid.stiffness(0.2) * (std::pow(1.02, 7.0) - 1.0)) < 1e-9);
    }

    /// The through-the-wall guard on sph-stenosis's lattice (0.1 mm), where the GPU's jets at a throat Re of 97 and
    /// 200 stopped on 2026-11-30 (0.2 mm past the throat, in the diverging wall's staircase). Its depths never
    /// exceed the wall depths. At 4,000 random points near the diverging wall (seed 7): none whose nearest lattice
    /// site was seeded fluid reads as through the wall (by the wall depths some did: the notches between the
    /// smooth surface and the wall particles), and every one whose nearest site is a wall particle a layer or
    /// more below the first (its lattice depth over a spacing) does.
    void guardDepthsFollowTheLattice()
    {
        const StenosisPipe pipe;
        SimulationInput input;
        input.data["particles"] = stenosisPipeParticles(pipe);
        SphSolver solver;
        configureStenosisPipe(pipe, solver);
        solver.initialize(input, stenosisPipeParameters(pipe));
        const ParticleState& p = solver.particles(); // still on the lattice
        const double dx = 1e-3 * pipe.spacingMm;
        std::map<std::array<long, 3>, std::size_t> sites;
        const auto siteOf = [dx](const Eigen::Vector3d& xM)
        {
            return std::array<long, 3>{std::lround(xM.x() / dx - 0.5), std::lround(xM.y() / dx - 0.5),
                                       std::lround(xM.z() / dx - 0.5)};
        };
        std::vector<std::size_t> walls;
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            sites[siteOf(p.position[i])] = i;
            if (!p.wall[i] || p.wallDepth[i] < 0.0)
                continue;
            QVERIFY(p.guardDepth[i] >= 0.0 && p.guardDepth[i] <= p.wallDepth[i]);
            if (p.backstop[i] && std::abs(1e3 * p.position[i].x() - 2.8) < 1.2) // the points and a support
                walls.push_back(i);
        }
        // The guard's reading at a point: min over the walls with the backstop of |x - x_j| - depth_j (SphRates.h).
        const auto reading = [&](const Eigen::Vector3d& xM, const std::vector<double>& depth)
        {
            double least = INFINITY;
            for (std::size_t j : walls)
                least = std::min(least, (xM - p.position[j]).norm() - depth[j]);
            return least;
        };
        std::mt19937 random(7);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        int fluidSites = 0, firedBefore = 0, firedNow = 0, deepSites = 0, deepCaught = 0;
        for (int n = 0; n < 4000; ++n)
        {
            const double xMm = 2.4 + 0.8 * unit(random), angle = 2.0 * std::numbers::pi * unit(random);
            const double rMm = pipe.radiusAtMm(xMm) + pipe.spacingMm * (3.0 * unit(random) - 1.0);
            const Eigen::Vector3d point = 1e-3 * Eigen::Vector3d(xMm, rMm * std::cos(angle), rMm * std::sin(angle));
            const auto site = sites.find(siteOf(point));
            if (site == sites.end())
                continue;
            const std::size_t s = site->second;
            if (!p.wall[s])
            {
                ++fluidSites;
                firedBefore += reading(point, p.wallDepth) < -0.5 * dx;
                firedNow += reading(point, p.guardDepth) < -0.5 * dx;
            }
            else if (p.guardDepth[s] > dx)
            {
                ++deepSites;
                deepCaught += reading(point, p.guardDepth) < -0.5 * dx;
            }
        }
        qInfo("%zu wall particles near the diverging side; of the points whose nearest site is fluid %d, the "
              "wall depths read %d as through the wall, the guard depths %d; of those at a site a layer or more "
              "below the first %d, caught %d",
              walls.size(), fluidSites, firedBefore, firedNow, deepSites, deepCaught);
        QVERIFY(fluidSites > 500 && deepSites > 100);
        QVERIFY(firedBefore > 0); // the notches the old guard read as inside the wall
        QCOMPARE(firedNow, 0);
        QCOMPARE(deepCaught, deepSites);
    }

    /// StenosisPipe::atFlow: a faster jet gets the Courant number scaled by the throats' Re and the walls'
    /// backstop; the same flow keeps the sph-stenosis settings.
    void stenosisPipeAtFlow()
    {
        const StenosisPipe pipe;
        QVERIFY(std::abs(pipe.throatReynolds() - 1060.0 * 4.0 * 0.05 * 0.8e-3 / 3.5e-3) < 1e-9);
        const StenosisPipe fast = pipe.atFlow(0.207, 8.0);
        QVERIFY(std::abs(fast.throatReynolds() / pipe.throatReynolds() - 0.207 / 0.05) < 1e-12);
        QVERIFY(std::abs(fast.cfl - pipe.cfl * 0.05 / 0.207) < 1e-12);
        QCOMPARE(fast.wallRepulsion, 0.01);
        QCOMPARE(stenosisPipeParameters(fast).get("wall_repulsion"), 0.01);
        QVERIFY(std::abs(fast.soundSpeedMS - pipe.soundSpeedMS * 0.207 / 0.05) < 1e-12);
        // The upper end, upstream Re 500 (throat 1000): its Courant number is one the solver takes.
        const StenosisPipe re500 = pipe.atFlow(1.032, 8.0);
        QVERIFY(std::abs(re500.throatReynolds() / 2.0 - 500.0) < 1.0);
        QVERIFY(re500.cfl < 0.01);
        QCOMPARE(stenosisPipeParameters(re500).get("cfl"), re500.cfl);
        const StenosisPipe same = pipe.atFlow(0.05, 5.6);
        QCOMPARE(same.cfl, pipe.cfl);
        QCOMPARE(same.wallRepulsion, 0.0);
        QCOMPARE(stenosisPipeParameters(pipe).get("wall_repulsion"), 0.0);
    }

    /// An open end's buffer is a kernel support deep: the imposed inflow divides the buffer's volume by that depth,
    /// so a buffer seeded for another smoothing ratio would scale it (the stenosis pipe's four spacings under h =
    /// 1.5 spacings let in 0.77 of its flow, 2026-12-03). The pipe seeded for its own ratio starts; seeded for 2
    /// and run at 1.5, or at 2.5, it is refused with the depths.
    void openEndsAreASupportDeep()
    {
        StenosisPipe pipe;
        pipe.spacingMm = 0.2, pipe.lengthMm = 5.6;
        for (const double ratio : {1.5, 2.0, 2.5})
        {
            StenosisPipe seeded = pipe;
            seeded.smoothingRatio = ratio;
            SimulationInput input;
            input.data["particles"] = stenosisPipeParticles(seeded);
            SphSolver solver;
            configureStenosisPipe(seeded, solver);
            solver.initialize(input, stenosisPipeParameters(seeded)); // its own ratio: taken
            if (ratio == 2.0)
                continue;
            input.data["particles"] = stenosisPipeParticles(pipe); // seeded for 2
            SphSolver other;
            configureStenosisPipe(seeded, other);
            try
            {
                other.initialize(input, stenosisPipeParameters(seeded));
                QFAIL("buffers seeded for another smoothing ratio were taken");
            }
            catch (const Error& error)
            {
                qInfo("ratio %.1f on buffers for 2: %s", ratio, error.what());
                QVERIFY(std::string(error.what()).find("support") != std::string::npos);
            }
        }
    }

    /// Periodic along x (a channel's flow direction): neighbours across the seam found as nearest images.
    void periodicNeighbours()
    {
        const double reach = 1e-3;
        // Three seeds, each with its period: roomy, the shortest allowed (five cells of half the reach), between.
        for (const auto [seed, period] : {std::pair{4u, 4.5e-3}, std::pair{5u, 2.5e-3}, std::pair{6u, 3.3e-3}})
        {
            NeighbourGrid grid(reach, Eigen::Vector3d(period, 0.0, 0.0));
            std::mt19937 random(seed);
            std::uniform_real_distribution<double> along(0.0, period), across(-2e-3, 2e-3);
            std::vector<Eigen::Vector3d> positions;
            for (int i = 0; i < 400; ++i)
                positions.push_back(Eigen::Vector3d(along(random), across(random), across(random)));
            grid.build(positions);
            int acrossTheSeam = 0;
            for (int i = 0; i < int(positions.size()); ++i)
            {
                std::set<int> found, expected;
                grid.forEachNeighbour(positions, i, [&](int j, const Eigen::Vector3d& rij, double) {
                    QVERIFY(std::abs(rij.x()) <= 0.5 * period);
                    found.insert(j);
                });
                for (int j = 0; j < int(positions.size()); ++j)
                {
                    Eigen::Vector3d d = positions[std::size_t(i)] - positions[std::size_t(j)];
                    const double direct = std::abs(d.x());
                    d.x() -= period * std::round(d.x() / period);
                    if (j != i && d.norm() < reach)
                    {
                        expected.insert(j);
                        acrossTheSeam += std::abs(d.x()) < direct;
                    }
                }
                QCOMPARE(found, expected);
            }
            QVERIFY(acrossTheSeam > 0);
        }
        QCOMPARE(NeighbourGrid(reach, Eigen::Vector3d(4.5e-3, 0.0, 0.0)).wrap(Eigen::Vector3d(-0.5e-3, 7.0, 0.0)).x(), 4.0e-3);
        QVERIFY_THROWS_EXCEPTION(Error, NeighbourGrid(reach, Eigen::Vector3d(2.4e-3, 0.0, 0.0)));
    }

    /// A waveform: linear between its points, repeating over its last time.
    void waveform()
    {
        const Waveform beat{{{0.0, 1.0}, {0.2, 3.0}, {0.8, 1.0}}};
        QCOMPARE(beat.factorAt(0.1), 2.0);
        QCOMPARE(beat.factorAt(0.5), 2.0);
        QVERIFY(std::abs(beat.factorAt(0.8 + 0.1) - 2.0) < 1e-12);
        QVERIFY(std::abs(beat.factorAt(-0.7) - 2.0) < 1e-12);
        QCOMPARE(Waveform().factorAt(3.0), 1.0);
    }

    /// One column of an inlet's buffer and an outlet's: a buffer particle that crosses into the domain becomes fluid
    /// and a copy of it refills the buffer a depth behind; a fluid particle through the outlet's disk joins its buffer,
    /// one beside the disk does not; a fluid particle back through the inlet leaves; the deepest outlet buffer
    /// particle leaves. The ledger counts each crossing once; the imposed plug flux is the prescribed flow rate.
    void openBoundaryExchange()
    {
        const double dx = 1e-3, depth = 4e-3, rho = 1000.0, m = rho * dx * dx * dx;
        OpenBoundary inlet, outlet;
        inlet.name = "inlet", inlet.normal = Eigen::Vector3d::UnitX(), inlet.radiusM = 2e-3;
        inlet.prescribed = OpenBoundary::Prescribed::Velocity, inlet.flowRateM3S = 1e-6, inlet.parabolic = false;
        outlet.name = "outlet", outlet.centreM = {0.02, 0.0, 0.0}, outlet.normal = -Eigen::Vector3d::UnitX();
        outlet.radiusM = 2e-3;
        ParticleState p;
        auto add = [&](double x, double y, int boundary)
        {
            p.add({x, y, 0.0}, rho, m, false);
            p.boundary.back() = std::uint8_t(boundary);
        };
        add(0.0002, 0.0, 1);   // 0: an inlet buffer particle that crossed the plane
        add(-0.0015, 0.0, 1);  // 1: stays in the buffer
        add(0.0203, 0.0, 0);   // 2: fluid through the outlet's disk
        add(0.0203, 0.005, 0); // 3: fluid past the outlet plane beside its disk
        add(0.0245, 0.0, 2);   // 4: deeper than the outlet's buffer
        add(-0.0003, 0.0, 0);  // 5: fluid back through the inlet
        OpenBoundaries boundaries({inlet, outlet});
        boundaries.initialize(p, depth, dx);
        MassLedger ledger;
        ledger.inflowKg.assign(2, 0.0), ledger.outflowKg.assign(2, 0.0);
        int nextId = 6;
        boundaries.exchange(p, nextId, ledger);
        std::map<int, int> boundaryOf;
        std::map<int, double> xOf;
        for (std::size_t i = 0; i < p.size(); ++i)
            boundaryOf[p.id[i]] = p.boundary[i], xOf[p.id[i]] = p.position[i].x();
        QCOMPARE(boundaryOf, (std::map<int, int>{{0, 0}, {1, 1}, {2, 2}, {3, 0}, {6, 1}}));
        QVERIFY(std::abs(xOf[6] - (0.0002 - depth)) < 1e-15);
        QCOMPARE(double(ledger.inflowKg[0]), m);
        QCOMPARE(double(ledger.outflowKg[0]), m);
        QCOMPARE(double(ledger.outflowKg[1]), m);
        QCOMPARE(nextId, 7);

        // Plug flow: each inlet buffer particle moves at Q / C, C = its buffer's volume / depth, and the flux the
        // buffer reports is Q; the outlet's buffer particle takes the outlet's pressure (0 Pa: the rest density).
        NeighbourGrid grid(2.0 * dx);
        grid.build(p.position);
        FluidModel fluid;
        fluid.restDensity = rho;
        boundaries.impose(p, grid, QuarticKernel(dx), fluid, 1.0);
        for (std::size_t i = 0; i < p.size(); ++i)
            if (p.boundary[i] == 1)
                QVERIFY(std::abs(p.velocity[i].x() - 1e-6 / (2.0 * m / rho / depth)) < 1e-12);
            else if (p.boundary[i] == 2)
                QCOMPARE(p.density[i], rho);
        QVERIFY(std::abs(boundaries.flowRate(0) - 1e-6) < 1e-15);
        QVERIFY_THROWS_EXCEPTION(Error, OpenBoundaries({inlet, outlet, outlet}).initialize(p, depth, dx));
    }

    /// The walls' backstop (thesis ch. 5.4, Monaghan 1994; FluidModel.h): its factor is zero at and beyond
    /// the spacing r0, D ((r0/r)^12 - (r0/r)^4) / r^2 inside it down to 0.8 r0 and a plateau of that
    /// acceleration below; a block of fluid driven by a body force against a fin one wall particle thick (the
    /// segmentation's one-voxel fingers: no kernel's worth of wall behind it, so the walls' extrapolated
    /// pressure holds it only weakly) passes through without the backstop and stays in front of it with it.
    /// Three offsets of the block against the fin's particles.
    void wallRepulsionHoldsAThinFin()
    {
        FluidModel model;
        model.wallRepulsion = 2.0, model.wallRepulsionRange = 1e-4;
        QCOMPARE(model.wallRepulsionFactor(1e-4), 0.0);
        QCOMPARE(model.wallRepulsionFactor(2e-4), 0.0);
        const double q = 1.0 / 0.8, atPlateau = 2.0 * (std::pow(q, 12) - std::pow(q, 4)) / 0.8e-4; // m/s^2
        QVERIFY(std::abs(model.wallRepulsionFactor(0.9e-4) * 0.9e-4 /
                             (2.0 * (std::pow(0.9, -12) - std::pow(0.9, -4)) / 0.9e-4) -
                         1.0) < 1e-12);
        for (const double r : {0.8e-4, 0.5e-4, 1e-7})
            QVERIFY(std::abs(model.wallRepulsionFactor(r) * r / atPlateau - 1.0) < 1e-12);
        const double spacingMm = 0.1, c0 = 1.0;
        for (const Eigen::Vector2d offset :
             {Eigen::Vector2d(0.5, 0.5), Eigen::Vector2d(0.3, 0.6), Eigen::Vector2d(0.0, 0.0)})
            for (const double repulsion : {0.0, 0.01})
            {
                ParticleSet set;
                auto& wall = set.fields["wall"];
                for (int j = -6; j <= 6; ++j) // the fin: the plane x = 0
                    for (int k = -6; k <= 6; ++k)
                        set.positionsMm.push_back(spacingMm * Eigen::Vector3d(0.0, j, k)),
                            wall.push_back(1.0);
                for (int i = 1; i <= 4; ++i) // the block: 4 x 5 x 5 particles, a spacing in front of it
                    for (int j = -2; j <= 2; ++j)
                        for (int k = -2; k <= 2; ++k)
                            set.positionsMm.push_back(
                                spacingMm * Eigen::Vector3d(-double(i), j + offset.x(), k + offset.y())),
                                wall.push_back(0.0);
                ParameterSet parameters{sphParameters()};
                parameters.set("spacing_mm", spacingMm);
                parameters.set("sound_speed_m_s", c0);
                parameters.set("wall_repulsion", repulsion);
                parameters.set("body_force_x_m_s2", kFinBodyForce * c0 * c0 / (spacingMm * 1e-3));
                parameters.set("density_guard", 1.0);
                parameters.set("end_time_s", 10.0 * spacingMm * 1e-3 / c0);
                SimulationInput input;
                input.data["particles"] = set;
                SphSolver solver;
                solver.initialize(input, parameters);
                RunStatus status;
                while (solver.position() < parameters.get("end_time_s") &&
                       solver.step(status, {}).kind == sim::StepOutcome::Kind::Continue)
                {
                }
                const ParticleState& p = solver.particles();
                int through = 0;
                for (std::size_t i = 0; i < p.size(); ++i)
                    through += !p.wall[i] && p.position[i].x() > 0.0;
                qInfo("offset (%.1f, %.1f), wall_repulsion %.2f: %d of 100 fluid particles past the fin at "
                      "%.3g s",
                      offset.x(), offset.y(), repulsion, through, solver.position());
                QVERIFY(repulsion > 0.0 ? through == 0 : through > 10);
            }
    }

    /// The particle machinery's analytic cases (the flow cases run in tst_sph_flow_validation).
    void kernelAndFpmCases()
    {
        for (const std::string name : {"sph-kernel", "sph-fpm"})
        {
            const ValidationResult result = runSphValidation(name);
            for (const ValidationFigure& figure : result.figures)
                qInfo("%s: %s = %.3g (expected %.3g +- %.3g)", name.c_str(), figure.name.c_str(), figure.measured,
                      figure.expected, figure.tolerance);
            QVERIFY2(result.passed(), name.c_str());
        }
        QVERIFY_THROWS_EXCEPTION(Error, runSphValidation("sph-nothing"));
    }
};

QTEST_APPLESS_MAIN(SphParticles)
#include "tst_sph_particles.moc"
