// The SPH solver's density options and guards (issue 18; SphRates.h): density by summation and the continuity
// density's relaxation towards it against lattices of known spacing, and the fluid loss guard on a vessel that
// empties through its outlet.

#include "JitteredLattice.h"
#include "SphRefusal.h"

#include "vsim/sim/sph/FluidModel.h"
#include "vsim/sim/sph/NeighbourGrid.h"
#include "vsim/sim/sph/QuarticKernel.h"
#include "vsim/sim/sph/SphRates.h"
#include "vsim/sim/sph/SphSolver.h"
#include "vsim/sim/sph/StenosisPipe.h"

#include <QtTest>

#include <cmath>
#include <map>
#include <memory>
#include <string>

using namespace vsim;
using namespace vsim::sim::sph;

class SphDensity : public QObject
{
    Q_OBJECT
private slots:
    /// Density by summation (SphRates.h) reads the particles' spacing: a periodic lattice at the seeding spacing reads
    /// the rest density to rounding; the same particles spread to 1.05 and 0.97 spacings read rho0 / 1.05^3 and
    /// rho0 / 0.97^3 within 0.3 % (the kernel's discretisation on a lattice other than the seeding one); the lattice
    /// jittered by up to 0.15 spacings (three seeds) reads rho0 on average within 0.3 % (1.001) with an RMS
    /// below 2 % (1.1-1.3 %). The continuity density's relaxation towards it has the rate (rho_sum - rho) / tau. The
    /// solver refuses summation with a free surface, without tension, with FPM and with the relaxation, each with the
    /// reason.
    void summationDensityReadsTheSpacing()
    {
        const double spacing = 1e-4, rho0 = 1060.0;
        const QuarticKernel kernel(2.0 * spacing);
        FluidModel fluid;
        fluid.densitySummation = true;
        fluid.summationScale = 1.0 / (spacing * spacing * spacing * kernel.latticeSum(spacing));
        QVERIFY(std::abs(kernel.latticeSum(spacing) * spacing * spacing * spacing - 1.0) < 2e-3);
        constexpr int kSide = 12;
        auto lattice = [&](double stretch, unsigned seed, double jitter)
        {
            ParticleState particles;
            const Eigen::Vector3i counts = Eigen::Vector3i::Constant(kSide);
            for (const Eigen::Vector3d& at : test::jitteredLattice(counts, stretch * spacing, jitter, seed))
                particles.add(at, 0.0, rho0 * spacing * spacing * spacing, false, -1.0, 0.0);
            NeighbourGrid grid(kernel.support(), Eigen::Vector3d::Constant(stretch * spacing * kSide));
            for (Eigen::Vector3d& x : particles.position)
                x = grid.wrap(x);
            grid.build(particles.position);
            summationDensity(particles, grid, kernel, fluid);
            return particles.density;
        };
        for (const double density : lattice(1.0, 1, 0.0))
            QVERIFY(std::abs(density / rho0 - 1.0) < 1e-12);
        for (const double stretch : {1.05, 0.97})
            for (const double density : lattice(stretch, 1, 0.0))
                QVERIFY2(std::abs(density * std::pow(stretch, 3) / rho0 - 1.0) < 3e-3, std::to_string(density).c_str());
        for (const unsigned seed : {3u, 4u, 5u})
        {
            const std::vector<double> density = lattice(1.0, seed, 0.15);
            double mean = 0.0, squares = 0.0;
            for (const double d : density)
                mean += d / double(density.size()), squares += std::pow(d / rho0 - 1.0, 2) / double(density.size());
            qInfo("seed %u: mean %.6f rho0, RMS %.4f", seed, mean / rho0, std::sqrt(squares));
            QVERIFY2(std::abs(mean / rho0 - 1.0) < 3e-3, std::to_string(mean).c_str());
            QVERIFY2(std::sqrt(squares) < 0.02, std::to_string(squares).c_str());
        }
        // The continuity density's relaxation towards summation: particles at rest on the lattice, their densities
        // 2 % high, relax at exactly (rho0 - 1.02 rho0) / tau (no continuity rate at rest; delta-SPH has no
        // difference to diffuse).
        {
            const std::vector<double> rest = lattice(1.0, 1, 0.0);
            ParticleState particles;
            for (int k = 0; k < int(rest.size()); ++k)
                particles.add(spacing * Eigen::Vector3d(k % kSide, (k / kSide) % kSide, k / (kSide * kSide)),
                              1.02 * rho0, rho0 * spacing * spacing * spacing, false, -1.0, 0.0);
            NeighbourGrid grid(kernel.support(), Eigen::Vector3d::Constant(spacing * kSide));
            grid.build(particles.position);
            FluidModel relaxing = fluid;
            relaxing.densitySummation = false, relaxing.densityRelaxationS = 2e-3;
            SphRates rates;
            computeRates(particles, pressures(particles, relaxing), grid, kernel, relaxing, 0.0, rates);
            for (const double rate : rates.densityRate)
                QVERIFY2(std::abs(rate / (-0.02 * rho0 / 2e-3) - 1.0) < 1e-9, std::to_string(rate).c_str());
        }
        for (const char* name : {"free_surface", "fluid_tension", "fpm", "density_relaxation_s"})
        {
            const double value = std::string(name) == "fluid_tension" ? 0.0 : 1.0;
            const std::string refusal = test::sphRefusal({{"density_summation", 1.0}, {name, value}});
            QVERIFY2(refusal.find("density_summation") != std::string::npos, name);
        }
        QCOMPARE(test::sphRefusal({{"density_summation", 1.0}}), std::string());
        QCOMPARE(test::sphRefusal({{"density_relaxation_s", 1e-3}}), std::string());
    }

    /// The fluid loss guard: the stenosis pipe at 0.2 mm without inflow and its outlet 200 Pa below the fluid's
    /// level (the reference pressure) empties through the outlet; with fluid_loss_guard 0.01 the run stops once the
    /// net outflow passes 1 % of the first fluid mass, saying so, at the state before that step (the ledger's share
    /// within the guard); with the guard off the same run goes on past that time.
    void fluidLossGuardStopsAnEmptyingVessel()
    {
        StenosisPipe pipe;
        pipe.spacingMm = 0.2;
        pipe.inflowWaveform.points = {{0.0, 0.0}};
        auto run = [&](double guard, double untilS)
        {
            auto solver = std::make_unique<SphSolver>();
            configureStenosisPipe(pipe, *solver);
            ParameterSet parameters = stenosisPipeParameters(pipe);
            parameters.set("reference_pressure_pa", 200.0);
            parameters.set("fluid_loss_guard", guard);
            parameters.set("end_time_s", untilS);
            SimulationInput input;
            input.data["particles"] = stenosisPipeParticles(pipe);
            solver->initialize(input, parameters);
            RunStatus status;
            sim::StepOutcome outcome;
            while (outcome.kind == sim::StepOutcome::Kind::Continue && solver->position() < untilS)
                outcome = solver->step(status, {});
            return std::pair{std::move(solver), outcome};
        };
        const auto [guarded, stop] = run(0.01, 0.02);
        QCOMPARE(int(stop.kind), int(sim::StepOutcome::Kind::Guard));
        QVERIFY2(stop.message.find("fluid_loss_guard 1 %") != std::string::npos, stop.message.c_str());
        const std::map<std::string, double> metrics = guarded->metrics();
        const double initial = metrics.at("fluid_mass_kg") - metrics.at("fluid_mass_change_kg");
        const double lost = (metrics.at("outflow_kg") - metrics.at("inflow_kg")) / initial;
        qInfo("stopped at %.4f ms, net outflow %.4f of the first fluid mass: %s", 1e3 * guarded->position(), lost,
              stop.message.c_str());
        QVERIFY(lost > 0.0 && lost <= 0.01);
        const auto [unguarded, end] = run(0.0, guarded->position() + 1e-3);
        QCOMPARE(int(end.kind), int(sim::StepOutcome::Kind::Continue));
        QVERIFY(unguarded->position() > guarded->position());
    }

    /// A particle field the solver does not read is refused with its name (a misspelt void fraction would
    /// otherwise leave every particle at the default); the fields it reads are taken.
    void unknownParticleFieldsAreRefused()
    {
        const std::string refusal = test::sphRefusal({}, {{"void_fractoin", {0.2, 0.2}}});
        QVERIFY2(refusal.find("'void_fractoin'") != std::string::npos, refusal.c_str());
        QCOMPARE(test::sphRefusal({}, {{"void_fraction", {0.2, 0.2}}, {"pressure_pa", {0.0, 0.0}}}),
                 std::string());
    }

    /// The density guard says which way a particle left the rest density (a jet's compression or a tensile
    /// void): the stenosis pipe at 0.2 mm, at rest, its fluid seeded 5 % denser or lighter than rho0, stops
    /// at its first step with the worst particle's departure printed with its sign, about +5 or -5 %.
    void densityGuardSaysCompressedOrStretched()
    {
        StenosisPipe pipe;
        pipe.spacingMm = 0.2;
        pipe.inflowWaveform.points = {{0.0, 0.0}};
        for (const double offset : {0.05, -0.05})
        {
            SphSolver solver;
            configureStenosisPipe(pipe, solver);
            ParticleSet particles = stenosisPipeParticles(pipe);
            // Tait's pressure of that density (gamma 7, B = rho0 c0^2 / 7): the solver seeds its densities
            // from it.
            const double tait = pipe.densityKgM3 * pipe.soundSpeedMS * pipe.soundSpeedMS / 7.0 *
                                (std::pow(1.0 + offset, 7.0) - 1.0);
            particles.fields["pressure_pa"].assign(particles.size(), tait);
            SimulationInput input;
            input.data["particles"] = particles;
            solver.initialize(input, stenosisPipeParameters(pipe));
            RunStatus status;
            const sim::StepOutcome stop = solver.step(status, {});
            QCOMPARE(int(stop.kind), int(sim::StepOutcome::Kind::Guard));
            const std::string key = "density is ";
            const std::size_t at = stop.message.find(key);
            QVERIFY2(at != std::string::npos, stop.message.c_str());
            const std::string number = stop.message.substr(at + key.size());
            qInfo("seeded %+.0f %%: %s", 100.0 * offset, stop.message.c_str());
            QCOMPARE(number.front(), offset > 0.0 ? '+' : '-');
            QVERIFY(std::abs(std::stod(number) - 100.0 * offset) < 0.5);
        }
    }
};

QTEST_APPLESS_MAIN(SphDensity)
#include "tst_sph_density.moc"
