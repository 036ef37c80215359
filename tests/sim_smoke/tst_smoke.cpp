// The smoke solver (issue 21): its validation cases with their stated tolerances (smoke-divergence,
// smoke-taylor-green, smoke-mass, smoke-ball; SmokeValidation.h), and the parts they rest on: the multigrid
// preconditioner is symmetric (as conjugate gradients needs), a uniform stream through open ends passes the
// projection unchanged, the conservative transport keeps a uniform field uniform and a blob non-negative, a vortex
// particle spins the air in the sense of its own vorticity (the printed eq. 7.23 would spin it backwards), hot air
// rises, a run pushed past stability stops with a message, and a grid too small is refused.

#include "vsim/core/Error.h"
#include "vsim/sim/smoke/Advection.h"
#include "vsim/sim/smoke/PoissonMultigrid.h"
#include "vsim/sim/smoke/PressureProjection.h"
#include "vsim/sim/smoke/PressureWarmStart.h"
#include "vsim/sim/smoke/SmokeForces.h"
#include "vsim/sim/smoke/SmokeSimulation.h"
#include "vsim/sim/smoke/SmokeValidation.h"
#include "vsim/sim/smoke/VortexParticles.h"

#include <QtTest>

#include <cmath>
#include <random>

using namespace vsim;
using namespace vsim::sim::smoke;

namespace {

/// A 24^3 box of 1 m with a solid block, open at the top.
SmokeGrid boxWithBlock()
{
    DomainBoundaries boundaries{};
    boundaries[5] = DomainBoundary::Open;
    SmokeGrid grid = SmokeGrid::make(24, 24, 24, 1.0 / 24.0, boundaries);
    for (int k = 8; k < 14; ++k)
        for (int j = 9; j < 15; ++j)
            for (int i = 5; i < 12; ++i)
                grid.solid[grid.cell(i, j, k)] = 1;
    return grid;
}

std::vector<float> randomOnFluid(const PoissonMultigrid& multigrid, unsigned seed)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> value(-1.0f, 1.0f);
    std::vector<float> x(multigrid.fluid().size(), 0.0f);
    for (std::size_t c = 0; c < x.size(); ++c)
        if (multigrid.fluid()[c])
            x[c] = value(random);
    return x;
}

double dot(const std::vector<float>& a, const std::vector<float>& b)
{
    double sum = 0.0;
    for (std::size_t c = 0; c < a.size(); ++c)
        sum += double(a[c]) * b[c];
    return sum;
}

} // namespace

class SmokeSolver : public QObject
{
    Q_OBJECT
private slots:
    void validationCases_data()
    {
        QTest::addColumn<QString>("name");
        for (const std::string& name : smokeValidationCases())
            QTest::newRow(name.c_str()) << QString::fromStdString(name);
    }

    void validationCases()
    {
        QFETCH(QString, name);
        const ValidationResult result = runSmokeValidation(name.toStdString());
        qInfo("%s (%.1f s)", result.description.c_str(), result.seconds);
        for (const ValidationFigure& figure : result.figures)
            qInfo("%s = %.4g (expected %.3g +- %.3g)", figure.name.c_str(), figure.measured, figure.expected,
                  figure.tolerance);
        QVERIFY(result.passed());
    }

    // Conjugate gradients needs a symmetric preconditioner: (M^-1 a, b) = (a, M^-1 b), with solids and an open
    // face, and on a closed box (singular operator).
    void preconditionerIsSymmetric()
    {
        for (bool closed : {false, true})
        {
            SmokeGrid grid = boxWithBlock();
            if (closed)
                grid.boundaries[5] = DomainBoundary::Wall;
            PoissonMultigrid multigrid;
            multigrid.prepare(grid);
            QVERIFY(multigrid.levels() >= 2);
            QCOMPARE(multigrid.singular(), closed);
            std::vector<float> a = randomOnFluid(multigrid, 1), b = randomOnFluid(multigrid, 2), ma, mb;
            multigrid.removeNullSpace(a), multigrid.removeNullSpace(b);
            ma.resize(a.size()), mb.resize(b.size());
            multigrid.precondition(a, ma);
            multigrid.precondition(b, mb);
            const double left = dot(ma, b), right = dot(a, mb);
            QVERIFY2(std::abs(left - right) <= 1e-4 * std::abs(left), qPrintable(QString("%1 vs %2").arg(left).arg(right)));
            QVERIFY(dot(ma, a) > 0.0); // positive definite on the fluid cells (less the constant when closed)
        }
    }

    // The warm start's weights reproduce a pressure linear in time exactly, over steps of different lengths
    // (psi = dt p: the truth is dt p(t + dt)); they fall back to the last psi without two comparable steps.
    void warmStartExtrapolatesALinearPressure()
    {
        const auto pressure = [](double t) { return 3.0 + 20.0 * t; };
        PressureWarmStart start;
        const auto weights = [&](double dt) {
            const PressureWarmStart::Weights w = start.weights(dt);
            return std::pair<double, double>{w.current, w.previous};
        };
        QCOMPARE(weights(0.01), (std::pair<double, double>{1.0, 0.0})); // no step yet
        double t = 0.0, psiPrevious = 0.0, psiLast = 0.0;
        for (double dt : {0.010, 0.012, 0.011, 0.0095, 0.013})
        {
            if (t > 0.011) // two steps recorded: the guess is the truth to float rounding
            {
                const PressureWarmStart::Weights w = start.weights(dt);
                const double guess = double(w.current) * psiLast + double(w.previous) * psiPrevious;
                const double truth = dt * pressure(t + dt);
                QVERIFY2(std::abs(guess - truth) <= 1e-6 * truth, qPrintable(QString("%1 vs %2").arg(guess).arg(truth)));
            }
            t += dt;
            psiPrevious = psiLast, psiLast = dt * pressure(t);
            start.record(dt);
        }
        QCOMPARE(weights(0.03), (std::pair<double, double>{1.0, 0.0}));   // more than twice the last step
        QCOMPARE(weights(0.005), (std::pair<double, double>{1.0, 0.0}));  // less than half of it
        QCOMPARE(weights(0.0), (std::pair<double, double>{1.0, 0.0}));    // a projection outside a step
        start.record(0.0);                                                // forgets the history
        QCOMPARE(weights(0.013), (std::pair<double, double>{1.0, 0.0}));
        start.record(0.013);
        QCOMPARE(weights(0.013), (std::pair<double, double>{1.0, 0.0}));  // one step: the last psi as it is
        start.record(0.013);
        QCOMPARE(weights(0.013), (std::pair<double, double>{2.0, -1.0})); // equal steps: 2 psi_n - psi_n-1
    }

    // A uniform stream through a pipe open at both ends is divergence-free already: the projection leaves it.
    void uniformStreamPassesTheProjection()
    {
        DomainBoundaries boundaries{};
        boundaries[0] = boundaries[1] = DomainBoundary::Open;
        SmokeGrid grid = SmokeGrid::make(16, 8, 8, 0.01, boundaries);
        std::fill(grid.u.begin(), grid.u.end(), 0.3f);
        PressureProjection projection;
        projection.prepare(grid);
        const ProjectionReport report = projection.project(grid, 1e-6, 100);
        for (float value : grid.u)
            QVERIFY(std::abs(value - 0.3f) < 1e-5f);
        QVERIFY(report.maxDivergence < 1e-3);
    }

    // Conservative transport: in a closed box stirred by a divergence-free swirl (the Taylor-Green field at 1 m/s)
    // a uniform field stays uniform (each axis's sweep corrected by its own divergence), a blob's mass stays the
    // same to the projection's residual and its density non-negative.
    void conservativeTransportKeepsUniformFieldsAndMass()
    {
        SmokeGrid grid = SmokeGrid::make(20, 20, 20, 0.05);
        const double pi = 3.141592653589793, h = 0.05;
        for (int k = 0; k < 20; ++k)
            for (int j = 0; j < 20; ++j)
                for (int i = 0; i <= 20; ++i)
                    grid.u[grid.uFace(i, j, k)] =
                        float(std::sin(pi * i * h) * std::cos(pi * (j + 0.5) * h) * std::cos(pi * (k + 0.5) * h));
        for (int k = 0; k < 20; ++k)
            for (int j = 0; j <= 20; ++j)
                for (int i = 0; i < 20; ++i)
                    grid.v[grid.vFace(i, j, k)] =
                        float(-std::cos(pi * (i + 0.5) * h) * std::sin(pi * j * h) * std::cos(pi * (k + 0.5) * h));
        PressureProjection projection;
        projection.prepare(grid);
        projection.project(grid, 1e-7, 500);
        std::fill(grid.temperature.begin(), grid.temperature.end(), 5.0f);
        for (int k = 0; k < 20; ++k)
            for (int j = 0; j < 20; ++j)
                for (int i = 0; i < 20; ++i)
                    grid.density[grid.cell(i, j, k)] = (i > 6 && i < 12 && j > 6 && j < 12 && k > 6 && k < 12) ? 1.0f : 0.0f;
        const double mass = grid.smokeMass();
        for (int step = 0; step < 10; ++step)
        {
            // Only the scalars: advect() would move the velocity too.
            const std::vector<float> u = grid.u, v = grid.v, w = grid.w;
            advect(grid, 0.02, AdvectionScheme::SemiLagrangian, AdvectionScheme::Conservative, step % 2 == 1);
            grid.u = u, grid.v = v, grid.w = w;
        }
        for (float t : grid.temperature)
            QVERIFY2(std::abs(t - 5.0f) < 1e-4f, qPrintable(QString::number(t)));
        for (float rho : grid.density)
            QVERIFY(rho >= -1e-6f);
        QVERIFY(std::abs(grid.smokeMass() / mass - 1.0) < 1e-5);
    }

    // A source in a closed box: the smoke in the box is what the source gave (the source's push made divergence-free
    // by the projection before the transport moves smoke with it), within 0.1 % after 60 steps.
    void sourceSmokeIsConserved()
    {
        SmokeSettings settings;
        settings.buoyancyAlpha = kGravity / kAirDensity;
        settings.buoyancyBeta = kGravity / kAmbientK;
        settings.confinement = 0.3;
        SmokeSimulation simulation(SmokeGrid::make(24, 24, 24, 1.0 / 24.0), settings);
        SmokeSource source;
        source.centre = {0.5, 0.5, 0.2};
        source.radius = 0.1;
        source.densityRate = 1e-3;
        source.temperatureK = 50.0;
        source.velocity = {0.0, 0.0, 0.4};
        simulation.addSource(source);
        int sourceCells = 0;
        const SmokeGrid& grid = simulation.grid();
        for (int k = 0; k < 24; ++k)
            for (int j = 0; j < 24; ++j)
                for (int i = 0; i < 24; ++i)
                    sourceCells += (grid.centre(i, j, k) - source.centre).norm() <= source.radius ? 1 : 0;
        double emitted = 0.0;
        for (int step = 0; step < 60; ++step)
        {
            const double dt = simulation.stableStep(0.02);
            QVERIFY(simulation.step(dt).guard.empty());
            emitted += source.densityRate * dt * sourceCells * std::pow(grid.h, 3);
        }
        QVERIFY2(std::abs(simulation.grid().smokeMass() / emitted - 1.0) < 1e-3,
                 qPrintable(QString("%1 of %2 kg").arg(simulation.grid().smokeMass()).arg(emitted)));
    }

    // A vortex particle with vorticity +z in still air makes the air around it turn counter-clockwise seen from +z
    // (positive circulation), as its own vorticity says.
    void vortexParticleSpinsTheAirItsWay()
    {
        SmokeGrid grid = SmokeGrid::make(16, 16, 16, 1.0 / 16.0);
        VortexParticles particles;
        particles.add({Eigen::Vector3d(0.5, 0.5, 0.5), Eigen::Vector3d(0.0, 0.0, 10.0)});
        std::vector<Eigen::Vector3f> force(grid.cells(), Eigen::Vector3f::Zero());
        particles.accumulateForcing(grid, 1.0, 3.0 / 16.0, force);
        addCellForces(grid, force, 0.01);
        double circulation = 0.0; // sum of (r x u).z around the particle in its plane
        for (int j = 0; j < 16; ++j)
            for (int i = 0; i < 16; ++i)
            {
                const Eigen::Vector3d r = grid.centre(i, j, 8) - Eigen::Vector3d(0.5, 0.5, 0.5);
                const Eigen::Vector3d u = grid.cellVelocity(i, j, 8);
                circulation += r.x() * u.y() - r.y() * u.x();
            }
        QVERIFY2(circulation > 0.0, qPrintable(QString::number(circulation)));
    }

    // Buoyancy: a hot cell's upper face gains upward speed g / T_ambient x rise x dt.
    void hotAirRises()
    {
        SmokeGrid grid = SmokeGrid::make(4, 4, 4, 0.1);
        grid.temperature[grid.cell(1, 1, 1)] = grid.temperature[grid.cell(1, 1, 2)] = 10.0f;
        addBuoyancy(grid, 0.1, kGravity / kAirDensity, kGravity / kAmbientK);
        QCOMPARE(grid.w[grid.wFace(1, 1, 2)], float(0.1 * kGravity / kAmbientK * 10.0));
        QVERIFY(grid.w[grid.wFace(2, 2, 2)] == 0.0f);
    }

    // An absurd confinement runs away: the step says so instead of carrying on with a meaningless flow.
    void unstableRunStopsWithAMessage()
    {
        SmokeGrid grid = SmokeGrid::make(16, 16, 16, 1.0 / 16.0);
        std::mt19937 random(5);
        std::uniform_real_distribution<float> speed(-1.0f, 1.0f);
        for (std::vector<float>* component : {&grid.u, &grid.v, &grid.w})
            for (float& value : *component)
                value = speed(random);
        SmokeSettings settings;
        settings.confinement = 1e4;
        SmokeSimulation simulation(std::move(grid), settings);
        std::string guard;
        for (int step = 0; step < 50 && guard.empty(); ++step)
            guard = simulation.step(0.05).guard;
        QVERIFY2(!guard.empty() && (guard.find("cells in one step") != std::string::npos ||
                                    guard.find("no longer finite") != std::string::npos),
                 guard.c_str());
    }

    void tooSmallGridIsRefused()
    {
        QVERIFY_THROWS_EXCEPTION(Error, SmokeGrid::make(1, 8, 8, 0.1));
        QVERIFY_THROWS_EXCEPTION(Error, SmokeGrid::make(8, 8, 8, 0.0));
    }
};

QTEST_APPLESS_MAIN(SmokeSolver)
#include "tst_smoke.moc"
