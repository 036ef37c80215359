// The smoke step's CUDA backend against the CPU's (issue 21: CPU / CUDA parity on a 64^3 run). The same
// simulation is built twice, once on each backend, and stepped with the same time steps (the CPU's stable
// step); at checkpoints the smoke density is compared cell by cell (relative to the largest density), the face
// velocities (relative to the largest speed), the smoke mass, the vortex particles alive, and every projection's
// iterations and residual. Cases: the benchmark's plume at 64^3 (buoyancy, confinement, vortex particles, an
// open top: the parity run), the thesis's ball drop at 32^3 (a moving solid: the operator rebuilt every
// step), the liver box at 32^3 with its suction (vents, a sink), a puff in a closed box (a singular operator:
// its null space removed) with MacCormack for the velocity. Both backends compute in single precision; their
// sums are ordered differently (reductions, atomics, fused multiply-adds), so the runs part at the rounding
// level (1e-6 after 10 - 20 steps: the bound there is 1e-4) and the flow's instability (buoyant plumes,
// confinement) then grows the difference, as it grows any: the plume's test runs the CPU against itself with the
// source's rate changed by 1e-6 and bounds the GPU's difference after 60 steps by the larger of 3 times that
// and 1e-3. The smoke mass, the particles alive and the iterations agree throughout. Last, the run driver with
// the GPU as the solver's backend (SmokeSolver::setBackend, what `simulate smoke --backend cuda` runs): the
// liver box with its suction through 22 s at 32 cells, the run's figures against the CPU's. Skips without a device.

#include "vsim/cuda_common/DeviceInfo.h"
#include "SmokePlume.h"
#include "vsim/cuda_smoke/CudaSmokeBackend.h"
#include "vsim/sim/smoke/SmokeForces.h"
#include "vsim/sim/smoke/SmokeScenes.h"
#include "vsim/sim/smoke/SmokeSimulation.h"
#include "vsim/sim/smoke/SmokeSolver.h"
#include "vsim/sim/common/RunDriver.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <functional>

using namespace vsim;
using namespace vsim::sim::smoke;

namespace {

struct Differences
{
    double density = 0.0;   ///< largest |difference| / largest density
    double velocity = 0.0;  ///< largest |difference| / largest speed
    double mass = 0.0;      ///< |difference| / the first's mass
    long particles = 0;     ///< the first's alive - the second's alive
    int iterationGap = 0;   ///< largest |difference| of a projection's iterations
    double worstResidual = 0.0; ///< the second's worst relative residual
    int firstIterations = 0, secondIterations = 0;
};

double largestDifference(const std::vector<float>& a, const std::vector<float>& b)
{
    double largest = 0.0;
    for (std::size_t n = 0; n < a.size(); ++n)
        largest = std::max(largest, std::abs(double(a[n]) - double(b[n])));
    return largest;
}

double largestValue(const std::vector<float>& a)
{
    double largest = 0.0;
    for (float value : a)
        largest = std::max(largest, std::abs(double(value)));
    return largest;
}

using Build = std::function<std::unique_ptr<SmokeSimulation>(std::unique_ptr<SmokeBackend>)>;

/// Steps `first` (the CPU's) and `second` with the same steps; their differences at each checkpoint (steps).
std::vector<Differences> runPair(SmokeSimulation& first, SmokeSimulation& second, const std::vector<int>& checkpoints,
                                 double maxDt, const char* label)
{
    std::vector<Differences> results;
    Differences running;
    for (int s = 1; s <= checkpoints.back(); ++s)
    {
        const double dt = first.stableStep(maxDt);
        const SmokeStepReport a = first.step(dt), b = second.step(dt);
        if (!a.guard.empty() || !b.guard.empty())
            qFatal("a guard stopped the run: %s %s", a.guard.c_str(), b.guard.c_str());
        running.iterationGap = std::max(running.iterationGap, std::abs(a.projection.iterations - b.projection.iterations));
        running.worstResidual = std::max(running.worstResidual, b.projection.relativeResidual);
        running.firstIterations += a.projection.iterations, running.secondIterations += b.projection.iterations;
        if (std::find(checkpoints.begin(), checkpoints.end(), s) == checkpoints.end())
            continue;
        Differences result = running;
        const SmokeGrid& x = first.grid();
        const SmokeGrid& y = second.grid();
        result.density = largestDifference(x.density, y.density) / std::max(largestValue(x.density), 1e-30);
        std::size_t worst = 0;
        for (std::size_t c = 0; c < x.density.size(); ++c)
            if (std::abs(x.density[c] - y.density[c]) > std::abs(x.density[worst] - y.density[worst]))
                worst = c;
        qInfo("  the largest density difference at cell (%zu, %zu, %zu): %.6g against %.6g", worst % std::size_t(x.nx),
              worst / std::size_t(x.nx) % std::size_t(x.ny), worst / (std::size_t(x.nx) * x.ny), x.density[worst], y.density[worst]);
        const double speed = std::max(x.maxSpeed(), 1e-30);
        result.velocity = std::max({largestDifference(x.u, y.u), largestDifference(x.v, y.v), largestDifference(x.w, y.w)}) / speed;
        result.mass = std::abs(x.smokeMass() - y.smokeMass()) / std::max(x.smokeMass(), 1e-30);
        result.particles = long(first.particles().size()) - long(second.particles().size());
        qInfo("%s, %d steps: density %.2e, velocity %.2e, mass %.2e of the first's; particles %zu / %zu; iterations "
              "%d / %d (largest gap %d), the second's worst residual %.2e",
              label, s, result.density, result.velocity, result.mass, first.particles().size(), second.particles().size(),
              result.firstIterations, result.secondIterations, result.iterationGap, result.worstResidual);
        results.push_back(result);
    }
    return results;
}

std::vector<Differences> runBoth(const Build& build, const std::vector<int>& checkpoints, double maxDt)
{
    std::unique_ptr<SmokeSimulation> cpu = build(nullptr);
    std::unique_ptr<SmokeSimulation> gpu = build(cuda::cudaSmokeBackendFactory()(cpu->grid()));
    return runPair(*cpu, *gpu, checkpoints, maxDt, "CPU / GPU");
}

/// Rounding level: fields within 1e-4, the mass within 1e-6, the particles and iterations equal (one apart).
void verifyRoundingLevel(const Differences& d, double massBound = 1e-6)
{
    QVERIFY2(d.density < 1e-4, qPrintable(QString("density %1").arg(d.density)));
    QVERIFY2(d.velocity < 1e-4, qPrintable(QString("velocity %1").arg(d.velocity)));
    QVERIFY2(d.mass < massBound, qPrintable(QString("mass %1").arg(d.mass)));
    QCOMPARE(d.particles, 0L);
    QVERIFY(d.iterationGap <= 1);
    QVERIFY(d.worstResidual <= 1e-4);
}

using test::plumeSettings;

/// The benchmark's plume (tests/support/SmokePlume.h).
Build plume(int n, double rateFactor = 1.0)
{
    return [n, rateFactor](std::unique_ptr<SmokeBackend> backend) { return test::plumeSimulation(n, std::move(backend), rateFactor); };
}

/// A scene's simulation as SmokeSolver builds it, with fixed rates.
Build scene(const SmokeScene& scene, double suctionLMin)
{
    return [scene, suctionLMin](std::unique_ptr<SmokeBackend> backend) {
        SmokeSettings settings = plumeSettings(scene.grid.nx);
        settings.up = scene.up;
        settings.particleRadius = 2.0 * scene.grid.h;
        auto simulation = std::make_unique<SmokeSimulation>(scene.grid, settings, std::move(backend));
        SmokeSource source = scene.source;
        source.densityRate = 5e-3;
        source.temperatureK = 60.0;
        source.velocity = 0.3 * scene.up;
        source.particlesPerSecond = 400.0;
        simulation->addSource(source);
        if (scene.ball)
            simulation->setSphere(*scene.ball);
        if (scene.suction && suctionLMin > 0.0)
        {
            SmokeSuction suction = *scene.suction;
            suction.flowM3S = suctionLMin / 60000.0;
            suction.onS = 0.2;
            simulation->setSuction(suction);
        }
        return simulation;
    };
}

} // namespace

class TestGpuSmokeSolver : public QObject
{
    Q_OBJECT
private slots:
    void init()
    {
        if (cuda::devices().empty())
            QSKIP("no CUDA device on this machine; run on the accelerator with the device tool");
    }

    /// The parity run: the plume at 64^3.
    void plumeAt64()
    {
        const std::vector<Differences> gpu = runBoth(plume(64), {1, 2, 3, 5, 10, 20, 60}, 1.0 / 30.0);
        verifyRoundingLevel(gpu[5]);
        // The same plume on the CPU with the source's rate changed by 1e-6: how far rounding-level differences grow.
        std::unique_ptr<SmokeSimulation> reference = plume(64)(nullptr), perturbed = plume(64, 1.0 + 1e-6)(nullptr);
        const Differences growth = runPair(*reference, *perturbed, {60}, 1.0 / 30.0, "CPU / CPU with the rate 1e-6 off").back();
        const double bound = std::max(1e-3, 3.0 * std::max(growth.density, growth.velocity));
        const Differences& last = gpu.back();
        QVERIFY2(last.density < bound && last.velocity < bound,
                 qPrintable(QString("density %1, velocity %2 against %3").arg(last.density).arg(last.velocity).arg(bound)));
        QVERIFY(last.mass < 1e-5);
        QCOMPARE(last.particles, 0L);
        QVERIFY(last.iterationGap <= 1);
        QVERIFY(last.worstResidual <= 1e-4);
    }

    void ballDrop()
    {
        const std::vector<Differences> d = runBoth(scene(ballDropScene(32), 0.0), {10, 40}, 1.0 / 30.0);
        verifyRoundingLevel(d[0]);
        QVERIFY2(d[1].density < 1e-2 && d[1].velocity < 1e-2 && d[1].mass < 1e-5, "the ball drop parted");
        QVERIFY(d[1].iterationGap <= 1);
    }

    void liverBoxWithSuction()
    {
        // The suction starts at 0.2 s, after about 6 steps.
        const std::vector<Differences> d = runBoth(scene(liverBoxScene(32), 20.0), {10, 40}, 1.0 / 30.0);
        verifyRoundingLevel(d[0]);
        QVERIFY2(d[1].density < 1e-2 && d[1].velocity < 1e-2 && d[1].mass < 1e-3, "the liver box parted");
        QVERIFY(d[1].iterationGap <= 1);
    }

    /// What `simulate smoke --backend cuda` runs: the solver on the run driver with the GPU's backend.
    void runDriverWithTheGpuBackend()
    {
        ParameterSet parameters(smokeParameters("liver-ablation"));
        parameters.set("grid_cells", 32);
        parameters.set("end_time_s", 22.0); // the suction from 10 s: its first 10 s
        std::map<std::string, double> figures[2];
        for (int onGpu = 0; onGpu < 2; ++onGpu)
        {
            SmokeSolver solver(liverBoxScene(32));
            if (onGpu)
                solver.setBackend(cuda::cudaSmokeBackendFactory());
            sim::RunControl control;
            control.frameEvery = 4.0;
            const SolverRun run = sim::runSolver(solver, {}, parameters, control);
            QCOMPARE(QString::fromStdString(solver.backendName()), QString(onGpu ? "cuda" : "cpu"));
            QVERIFY(run.status.stoppedBy == RunStatus::StoppedBy::End);
            QVERIFY(run.status.converged());
            figures[onGpu] = run.metrics;
        }
        for (const char* key : {"smoke_mass_mg", "peak_density_mg_m3", "smoke_removed_in_10s_percent", "peak_obscured_fraction",
                                "mean_projection_iterations"})
        {
            const double cpu = figures[0].at(key), gpu = figures[1].at(key);
            qInfo("%s: CPU %.6g, GPU %.6g", key, cpu, gpu);
            QVERIFY2(std::abs(gpu - cpu) <= 0.02 * std::abs(cpu) + 1e-9, key);
        }
        QVERIFY(figures[1].at("worst_relative_residual") <= 1e-4);
    }

    void closedBoxWithMacCormack()
    {
        const Build closed = [](std::unique_ptr<SmokeBackend> backend) {
            SmokeSettings settings = plumeSettings(32);
            settings.scheme = AdvectionScheme::MacCormack;
            settings.particleStrength = 0.0;
            SmokeGrid grid = SmokeGrid::make(32, 32, 32, 1.0 / 32.0);
            for (int k = 4; k < 10; ++k)
                for (int j = 12; j < 20; ++j)
                    for (int i = 12; i < 20; ++i)
                        grid.density[grid.cell(i, j, k)] = 1e-3f, grid.temperature[grid.cell(i, j, k)] = 50.0f;
            return std::make_unique<SmokeSimulation>(std::move(grid), settings, std::move(backend));
        };
        for (const Differences& d : runBoth(closed, {20, 60}, 1.0 / 30.0))
            verifyRoundingLevel(d, 1e-7);
    }
};

QTEST_GUILESS_MAIN(TestGpuSmokeSolver)
#include "tst_gpu_smoke_solver.moc"
