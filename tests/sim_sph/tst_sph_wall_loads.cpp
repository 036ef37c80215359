// The wall loads' estimate (WallShear.h, issue 18) on imposed velocity fields, no stepping: the walls' friction
// on a plane Couette flow against mu gamma, on Stokes' first problem's thin layer against its analytic wall shear,
// and on Poiseuille's profile in the sph-stenosis pipe's lattice-seeded
// straight part against 4 mu U / R0.

#include "vsim/sim/sph/FluidModel.h"
#include "vsim/sim/sph/NeighbourGrid.h"
#include "vsim/sim/sph/QuarticKernel.h"
#include "vsim/sim/sph/StenosisPipe.h"
#include "vsim/sim/sph/WallShear.h"

#include <QtTest>

#include <cmath>
#include <numbers>
#include <utility>

using namespace vsim;
using namespace vsim::sim::sph;

namespace {

constexpr int kPeriod = 12; // the flat wall's lattice along and across the flow (periodic)

FluidModel blood()
{
    FluidModel fluid;
    fluid.restDensity = 1060.0, fluid.viscosity = 3.5e-3, fluid.soundSpeed = 10.0;
    return fluid;
}

/// A flat wall of four lattice layers (spacing `s`, their depths below the no-slip plane y = 0) under `fluidLayers`
/// layers of fluid at rest, kPeriod x kPeriod spacings along and across.
ParticleState flatWall(double s, int fluidLayers, const FluidModel& fluid)
{
    ParticleState particles;
    for (int k = -4; k < fluidLayers; ++k)
        for (int i = 0; i < kPeriod; ++i)
            for (int j = 0; j < kPeriod; ++j)
            {
                const double y = (k + 0.5) * s;
                particles.add(Eigen::Vector3d((i + 0.5) * s, y, (j + 0.5) * s), fluid.restDensity,
                              fluid.restDensity * s * s * s, k < 0, k < 0 ? -y : -1.0);
                particles.id.back() = int(particles.size()) - 1;
            }
    return particles;
}

} // namespace

class SphWallLoads : public QObject
{
    Q_OBJECT
private slots:
    /// The wall shear stress as the walls' friction (WallShear.h) in a plane Couette flow u = gamma y over a flat
    /// wall of four lattice layers (their depths known, the no-slip plane at y = 0), periodic along and across the
    /// flow: mu gamma at wall points placed anywhere against the lattice, within 1 % (a model of the estimate
    /// other than the solver's: the shear is imposed, not stepped to). The wall pressure at rest density: 0.
    void wallFrictionReadsACouetteFlow()
    {
        const double s = 1e-4, gamma = 1000.0;
        const QuarticKernel kernel(2.0 * s);
        const FluidModel fluid = blood();
        ParticleState particles = flatWall(s, 12, fluid);
        for (std::size_t i = 0; i < particles.size(); ++i)
            if (!particles.wall[i])
                particles.velocity[i] = Eigen::Vector3d(gamma * particles.position[i].y(), 0.0, 0.0);
        NeighbourGrid grid(kernel.support(), Eigen::Vector3d(kPeriod * s, 0.0, kPeriod * s));
        grid.build(particles.position);
        const double expected = fluid.viscosity * gamma;
        double worst = 0.0;
        for (const auto& [x, z] : {std::pair{0.0, 0.0}, std::pair{0.3 * s, 0.7 * s}, std::pair{0.5 * s, 0.5 * s},
                                   std::pair{5.2 * s, 9.9 * s}})
        {
            const WallLoad load =
                wallLoad(particles, grid, kernel, fluid, s, {Eigen::Vector3d(x, 0.0, z), Eigen::Vector3d::UnitY()});
            QVERIFY(load.valid);
            qInfo("wall point at (%.1f, 0, %.1f) spacings: tau_w (%.5f, %.2g, %.2g) Pa against mu gamma %.4f Pa, "
                  "wall pressure %.3g Pa",
                  x / s, z / s, load.shearPa.x(), load.shearPa.y(), load.shearPa.z(), expected, load.pressurePa);
            worst = std::max(worst, std::abs(load.shearPa.x() / expected - 1.0));
            QVERIFY(std::abs(load.shearPa.y()) <= 1e-9 * expected && std::abs(load.shearPa.z()) <= 1e-6 * expected);
            QVERIFY(std::abs(load.pressurePa) <= 1e-9);
        }
        qInfo("worst relative error %.3g", worst);
        QVERIFY(worst <= 0.01);
    }

    /// A boundary layer as thin as a stenosis throat's (about a spacing at 0.05 mm, Re 97): Stokes' first problem's
    /// profile u = U erf(y / (2 delta)), delta = sqrt(nu t), imposed on the Couette test's flat wall, read by the
    /// walls' friction against its wall shear stress mu U / (sqrt(pi) delta), for delta from 0.5 to 8 spacings. The
    /// friction extrapolates each particle's own velocity linearly to the wall, so a profile that bends within the
    /// kernel's reach reads low: the estimate's own share of a thin layer's error (the flow's slip next to the wall
    /// is the other; RESULTS.md, 2026-12-03).
    void wallFrictionReadsAThinBoundaryLayerLow()
    {
        const double s = 1e-4, speed = 0.1;
        const QuarticKernel kernel(2.0 * s);
        const FluidModel fluid = blood();
        ParticleState particles = flatWall(s, 40, fluid);
        NeighbourGrid grid(kernel.support(), Eigen::Vector3d(kPeriod * s, 0.0, kPeriod * s));
        grid.build(particles.position);
        double previous = 0.0;
        for (const double spacings : {0.5, 1.0, 2.0, 4.0, 8.0})
        {
            const double delta = spacings * s;
            for (std::size_t i = 0; i < particles.size(); ++i)
                if (!particles.wall[i])
                    particles.velocity[i] =
                        Eigen::Vector3d(speed * std::erf(particles.position[i].y() / (2 * delta)), 0, 0);
            const double expected = fluid.viscosity * speed / (std::sqrt(std::numbers::pi) * delta);
            const WallLoad load = wallLoad(particles, grid, kernel, fluid, s,
                                           {Eigen::Vector3d(0.3 * s, 0.0, 0.7 * s), Eigen::Vector3d::UnitY()});
            const double ratio = load.shearPa.x() / expected;
            qInfo("delta %.1f spacings: the walls' friction %.4f Pa against mu U / (sqrt(pi) delta) %.4f Pa: %.4f",
                  spacings, load.shearPa.x(), expected, ratio);
            // Low, less so as the layer thickens, and by at most 0.1 / delta^1.5 (delta in spacings; measured
            // 2026-12-03: 20.4 / 7.4 / 2.1 / 0.52 / 0.11 % low at 0.5 / 1 / 2 / 4 / 8 spacings).
            QVERIFY(load.valid && ratio < 1.0 && ratio > previous);
            QVERIFY(1.0 - ratio <= 0.1 / std::pow(spacings, 1.5));
            previous = ratio;
        }
    }

    /// The same in the sph-stenosis pipe's straight part (R0 0.8 mm, lattice-seeded at 0.1 and 0.05 mm: a
    /// staircase wall with the depths below the smooth surface), the fluid given Poiseuille's profile
    /// u = 2 U (1 - r^2 / R0^2): 4 mu U / R0 on every ring between 0.8 and 1.2 mm, each the mean of 8 points,
    /// within 6 %. The friction reads a curved profile low: Morris' no-slip velocity extrapolates each particle's
    /// own velocity linearly to the wall (2026-12-01: 1.1-3.9 % low at 0.1 mm, 3.8-5.3 % at 0.05 mm; on a flat
    /// wall with a parabola of the same half-width 5.4 %, with a straight profile 0.03 %). In a run the flow
    /// settles so that this friction balances what drives it (sph-poiseuille: 0.9975).
    void wallFrictionReadsPoiseuilleInThePipe()
    {
        for (const double spacing : {0.1, 0.05})
        {
            StenosisPipe pipe;
            pipe.spacingMm = spacing;
            const ParticleSet set = stenosisPipeParticles(pipe);
            const QuarticKernel kernel(2.0 * spacing * 1e-3);
            FluidModel fluid;
            fluid.restDensity = pipe.densityKgM3, fluid.viscosity = pipe.viscosityPaS, fluid.soundSpeed = 4.0;
            ParticleState particles;
            const double r0 = 1e-3 * pipe.radiusMm, volume = std::pow(1e-3 * spacing, 3);
            for (std::size_t i = 0; i < set.size(); ++i)
            {
                const Eigen::Vector3d x = 1e-3 * set.positionsMm[i];
                const bool wall = set.fields.at("wall")[i] > 0.5;
                particles.add(x, fluid.restDensity, fluid.restDensity * volume, wall,
                              wall ? 1e-3 * set.fields.at("wall_depth_mm")[i] : -1.0);
                particles.id.back() = int(i);
                const double r2 = x.y() * x.y() + x.z() * x.z();
                if (!wall)
                    particles.velocity.back() = Eigen::Vector3d(2.0 * pipe.meanSpeedMS * (1.0 - r2 / (r0 * r0)), 0, 0);
            }
            NeighbourGrid grid(kernel.support());
            grid.build(particles.position);
            const double expected = 4.0 * fluid.viscosity * pipe.meanSpeedMS / r0;
            double worst = 0.0;
            int rings = 0;
            const std::vector<WallPoint> points = pipe.wallPoints(0.05, 8);
            for (std::size_t first = 0; first < points.size(); first += 8)
            {
                const double xMm = 1e3 * points[first].positionM.x();
                if (xMm < 0.8 - 1e-9 || xMm > 1.2 + 1e-9)
                    continue;
                double shear = 0.0;
                for (std::size_t k = first; k < first + 8; ++k)
                    shear += wallLoad(particles, grid, kernel, fluid, 1e-3 * spacing, points[k]).shearPa.x() / 8;
                worst = std::max(worst, std::abs(shear / expected - 1.0));
                ++rings;
            }
            qInfo("pipe at %.2f mm: %d rings, worst ring %.3g from 4 mu U / R0 = %.4f Pa", spacing, rings, worst,
                  expected);
            QVERIFY(rings >= 8 && worst <= 0.06);
        }
    }
};

QTEST_APPLESS_MAIN(SphWallLoads)
#include "tst_sph_wall_loads.moc"
