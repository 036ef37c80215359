// The no-slip wall in a boundary layer a few spacings thin (issue 18: a stenosis throat's layer is about a spacing
// at 0.05 mm), stepped: Stokes' first problem. Fluid moving at U along a channel between two flat walls at rest 24 spacings apart (four
// lattice layers each, their depths known; periodic along and across the flow) from t = 0: next to each wall the
// layer u = U erf(y / (2 sqrt(nu t))) grows, the wall shear stress mu U / sqrt(pi nu t). At delta = sqrt(nu t) of
// 0.5, 1 and 2 spacings the particles' velocity per lattice layer against the analytic profile (how much the discrete
// no-slip slips next to the wall: Morris' extrapolated wall velocity is exact for a straight profile, and this one
// bends within the kernel), and the walls' friction (WallShear.h) against the analytic wall shear; at h = 2 spacings
// (the solver's default) and 1.5 (a shorter kernel bends less of the layer into the first particles' sums).
// Measured 2026-12-03 (RESULTS.md): at h = 2 the first layer runs 42 / 33 / 7 % fast and the friction reads
// +11 / +8 / -2.5 % at delta = 0.5 / 1 / 2 spacings; at h = 1.5, 32 / 20 / 6 % and +17 / +12 / -3.0 %.

#include "vsim/core/Error.h"
#include "vsim/sim/sph/SphSolver.h"
#include "vsim/sim/sph/WallShear.h"

#include <QtTest>

#include <cmath>
#include <numbers>
#include <string>

using namespace vsim;
using namespace vsim::sim::sph;

class SphStokesLayer : public QObject
{
    Q_OBJECT
private slots:
    void startedFlowAlongAWall_data()
    {
        QTest::addColumn<double>("ratio");            // h / spacing
        QTest::addColumn<double>("frictionTolerance"); // the friction against the analytic, every delta
        QTest::addColumn<double>("firstLayerSlip");    // the first layer's speed above erf's, every delta
        QTest::addColumn<double>("settledTolerance");  // at delta = 2 spacings: the friction and every layer
        QTest::newRow("h = 2 spacings") << 2.0 << 0.15 << 0.45 << 0.08;
        QTest::newRow("h = 1.5 spacings") << 1.5 << 0.20 << 0.35 << 0.07;
    }

    void startedFlowAlongAWall()
    {
        QFETCH(double, ratio);
        QFETCH(double, frictionTolerance);
        QFETCH(double, firstLayerSlip);
        QFETCH(double, settledTolerance);
        const int period = 11, across = 24, layers = 4;
        const double spacingMm = 0.1, s = 1e-3 * spacingMm, speed = 0.1, density = 1060.0, viscosity = 3.5e-3;
        const double nu = viscosity / density;
        ParticleSet set;
        auto &wall = set.fields["wall"], &depth = set.fields["wall_depth_mm"], &vx = set.fields["velocity_x_m_s"],
             &vy = set.fields["velocity_y_m_s"], &vz = set.fields["velocity_z_m_s"];
        for (int k = 0; k < period; ++k)
            for (int j = -layers; j < across + layers; ++j)
                for (int i = 0; i < period; ++i)
                {
                    const bool isWall = j < 0 || j >= across;
                    set.positionsMm.push_back(spacingMm * Eigen::Vector3d(i + 0.5, j + 0.5, k + 0.5));
                    wall.push_back(isWall ? 1.0 : 0.0);
                    depth.push_back(spacingMm * (j < 0 ? -j - 0.5 : j >= across ? j - across + 0.5 : 0.0));
                    vx.push_back(isWall ? 0.0 : speed), vy.push_back(0.0), vz.push_back(0.0);
                }
        ParameterSet parameters(sphParameters());
        parameters.set("spacing_mm", spacingMm);
        parameters.set("density_kg_m3", density);
        parameters.set("viscosity_pa_s", viscosity);
        parameters.set("sound_speed_m_s", 10.0 * speed);
        parameters.set("periodic_x_mm", period * spacingMm);
        parameters.set("periodic_z_mm", period * spacingMm);
        parameters.set("end_time_s", 1.0);
        parameters.set("smoothing_ratio", ratio);
        SimulationInput input;
        input.data["particles"] = set;
        SphSolver solver;
        solver.initialize(input, parameters);
        const QuarticKernel& kernel = solver.kernel();
        for (const double deltaSpacings : {0.5, 1.0, 2.0})
        {
            const double delta = deltaSpacings * s, untilS = delta * delta / nu;
            while (solver.position() < untilS)
            {
                RunStatus status;
                QVERIFY(solver.step(status, {}).kind != sim::StepOutcome::Kind::Guard);
            }
            const double t = solver.position(), d = std::sqrt(nu * t);
            const ParticleState& p = solver.particles();
            // The lower wall's layer: the fluid's speed per lattice layer against erf at its centre.
            QString profile;
            double firstLayer = 0.0, worstLayer = 0.0;
            for (int j = 0; j < 6; ++j)
            {
                double sum = 0.0;
                int count = 0;
                for (std::size_t i = 0; i < p.size(); ++i)
                    if (!p.wall[i] && std::abs(p.position[i].y() - (j + 0.5) * s) < 0.5 * s)
                        sum += p.velocity[i].x(), ++count;
                const double exact = speed * std::erf((j + 0.5) * s / (2.0 * d)), off = sum / count / exact - 1.0;
                profile += QString(" %1: %2 %").arg(j + 0.5).arg(100.0 * off, 0, 'f', 1);
                firstLayer = j == 0 ? off : firstLayer, worstLayer = std::max(worstLayer, std::abs(off));
            }
            NeighbourGrid grid(kernel.support(), Eigen::Vector3d(period * s, 0.0, period * s));
            grid.build(p.position);
            double friction = 0.0;
            const int points = 4;
            for (int k = 0; k < points; ++k)
                friction += wallLoad(p, grid, kernel, solver.fluid(), s,
                                     {Eigen::Vector3d((3 * k + 0.3) * s, 0.0, (3 * k + 0.7) * s), Eigen::Vector3d::UnitY()})
                                .shearPa.x() /
                            points;
            const double exactShear = viscosity * speed / std::sqrt(std::numbers::pi * nu * t);
            qInfo("h %.1f spacings, delta %.2f spacings (t %.3f ms, %ld steps): friction %.4f Pa against %.4f (%.1f %%); "
                  "layers' speed against erf:%s",
                  ratio, d / s, 1e3 * t, long(solver.metrics().at("steps")), friction, exactShear,
                  100.0 * (friction / exactShear - 1.0), qPrintable(profile));
            QVERIFY(std::abs(friction / exactShear - 1.0) <= frictionTolerance);
            QVERIFY(firstLayer > 0.0 && firstLayer <= firstLayerSlip); // the first layer slips, this much at most
            if (deltaSpacings >= 2.0)
                QVERIFY(std::abs(friction / exactShear - 1.0) <= settledTolerance && worstLayer <= settledTolerance);
        }
    }

    /// A given velocity is all three components or none: an input with only velocity_x_m_s (as this case's flow
    /// would be written by hand) is refused with what to give, not started from rest.
    void aVelocityOfOneComponentIsRefused()
    {
        ParticleSet set;
        set.positionsMm = {Eigen::Vector3d(0.05, 0.05, 0.05), Eigen::Vector3d(0.15, 0.05, 0.05)};
        set.fields["wall"] = {0.0, 0.0};
        set.fields["velocity_x_m_s"] = {0.1, 0.1};
        ParameterSet parameters(sphParameters());
        parameters.set("spacing_mm", 0.1);
        SimulationInput input;
        input.data["particles"] = set;
        SphSolver solver;
        try
        {
            solver.initialize(input, parameters);
            QFAIL("an input with one velocity component was taken");
        }
        catch (const Error& error)
        {
            QVERIFY(std::string(error.what()).find("velocity_z_m_s") != std::string::npos);
        }
    }
};

QTEST_APPLESS_MAIN(SphStokesLayer)
#include "tst_sph_stokes_layer.moc"
