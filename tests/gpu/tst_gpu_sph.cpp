// The CUDA SPH step against the CPU one (same algorithm; issue 18's parity: fields within 1e-4 relative after
// 100 steps): the 3D dam break (DamBreak.h) at 40 mm spacing, 100 steps on both, every particle compared by
// its number; and the sph-stenosis pipe (StenosisPipe.h, 0.1 mm, its inflow ramped over 1 ms so that the open
// boundaries exchange particles within the run), the particles given at the start compared by their numbers
// after 100 and 300 steps (those the inlet creates are numbered in another order on the GPU; positions against
// single precision's rounding floor, see the test; plain, with particle shifting, and with the Finite Particle
// Method's density rate), and after 300 the particle count, each particle's buffer,
// the mass through the boundaries and their flow rates (1e-4). Last, the run driver with the GPU as the solver's
// stepper (SphSolver::setStepper, what `simulate sph --backend cuda` runs): the stenosis pipe at 0.2 mm through its
// 25 ms, the stenosis figures from the sections (sampled every 10th step on the GPU, every step on the CPU) within
// 1 % of the CPU's, the throat's wall shear stress within 3 %. A GPU run saved halfway and gone on from
// (SphCheckpoint.h) against the run that did not stop, at the CPU parity's tolerances. Position and velocity differences are relative to the
// largest displacement and the largest speed, the density's to the rest density, the time's to the CPU's. The
// GPU runs in single precision, the CPU in double. Skips without a device.

#include "vsim/cuda_common/DeviceInfo.h"
#include "vsim/cuda_sph/CudaSph.h"
#include "vsim/sim/sph/DamBreak.h"
#include "vsim/sim/sph/SphCheckpoint.h"
#include "vsim/sim/sph/SphSolver.h"
#include "vsim/sim/common/RunDriver.h"
#include "vsim/sim/sph/StenosisFigures.h"
#include "vsim/sim/sph/StenosisPipe.h"

#include <QtTest>

#include <chrono>

#include <cmath>
#include <filesystem>
#include <unordered_map>

using namespace vsim;
using namespace vsim::sim::sph;

namespace {

void initializeDamBreak(SphSolver& solver, double spacingMm, double absorptionMm = 0.0, bool tension = true)
{
    SimulationInput input;
    input.data["particles"] = damBreakParticles(spacingMm);
    ParameterSet parameters = damBreakParameters(spacingMm);
    parameters.set("absorption_distance_mm", absorptionMm);
    parameters.set("fluid_tension", tension ? 1.0 : 0.0);
    solver.initialize(input, parameters);
}

/// The particles in the order of their numbers.
ParticleState byId(const ParticleState& p)
{
    ParticleState out = p;
    for (std::size_t s = 0; s < p.size(); ++s)
    {
        const std::size_t i = std::size_t(p.id[s]);
        out.position[i] = p.position[s], out.velocity[i] = p.velocity[s], out.density[i] = p.density[s];
        out.wall[i] = p.wall[s], out.id[i] = p.id[s];
    }
    return out;
}

} // namespace

class TestGpuSph : public QObject
{
    Q_OBJECT
private slots:
    /// With and without tension in the fluid (FluidModel::tension: the pressure clipped at 0 and the guard on
    /// compression only).
    void damBreakParityAfter100Steps_data()
    {
        QTest::addColumn<bool>("tension");
        QTest::newRow("with tension") << true;
        QTest::newRow("without tension") << false;
    }
    void damBreakParityAfter100Steps()
    {
        if (vsim::cuda::devices().empty())
            QSKIP("no CUDA device on this machine; run on the accelerator with the device tool");
        QFETCH(bool, tension);
        SphSolver cpu;
        initializeDamBreak(cpu, 40.0, 0.0, tension);
        const ParticleState start = byId(cpu.particles());
        cuda::CudaSph gpu(cpu);
        RunStatus status;
        double position = 0.0, velocity = 0.0, density = 0.0;
        for (int s = 1; s <= 100; ++s)
        {
            QVERIFY(cpu.step(status, {}).kind != sim::StepOutcome::Kind::Guard);
            const std::string guard = gpu.step();
            QVERIFY2(guard.empty(), guard.c_str());
            if (s != 1 && s != 10 && s != 100)
                continue;
            const ParticleState a = byId(cpu.particles()), b = gpu.download();
            QCOMPARE(a.size(), b.size());
            double displacement = 0.0, speed = 0.0, dx = 0.0, dv = 0.0, fluidRho = 0.0, wallRho = 0.0;
            std::size_t worst = 0, differing = 0;
            for (std::size_t i = 0; i < a.size(); ++i)
            {
                QCOMPARE(int(a.wall[i]), int(b.wall[i]));
                displacement = std::max(displacement, (a.position[i] - start.position[i]).norm());
                speed = std::max(speed, a.velocity[i].norm());
                dx = std::max(dx, (a.position[i] - b.position[i]).norm());
                dv = std::max(dv, (a.velocity[i] - b.velocity[i]).norm());
                const double d = std::abs(a.density[i] - b.density[i]);
                if (a.wall[i] && d > wallRho)
                    wallRho = d, worst = i;
                if (!a.wall[i])
                    fluidRho = std::max(fluidRho, d);
                if (a.wall[i] && d > 0.1)
                    ++differing;
            }
            position = dx / displacement, velocity = dv / speed,
            density = std::max(fluidRho, wallRho) / 1000.0;
            qInfo("dam break at 40 mm, %zu particles, step %d, t = %.5f s (GPU %.5f s): largest displacement "
                  "%.4g mm, "
                  "speed %.4g m/s; GPU (single) - CPU (double): position %.3g, velocity %.3g, density %.3g "
                  "in the fluid, "
                  "%.3g in the walls (relative; worst particle %zu, wall %d, at %.1f %.1f %.1f mm: %.3f vs "
                  "%.3f kg/m3); "
                  "largest density variation CPU %.4g, GPU %.4g; %zu walls differ by more than 0.1 kg/m3",
                  a.size(), s, cpu.position(), gpu.timeS(), 1e3 * displacement, speed, position, velocity,
                  fluidRho / 1000.0, wallRho / 1000.0, worst, int(a.wall[worst]), 1e3 * a.position[worst].x(),
                  1e3 * a.position[worst].y(), 1e3 * a.position[worst].z(), a.density[worst],
                  b.density[worst], cpu.metrics().at("largest_density_variation"),
                  gpu.largestDensityVariation(), differing);
        }
        const double time = std::abs(gpu.timeS() - cpu.position()) / cpu.position();
        QVERIFY(position <= 1e-4 && velocity <= 1e-4 && density <= 1e-4 && time <= 1e-4);
    }

    void stenosisPipeParityWithOpenBoundaries_data()
    {
        QTest::addColumn<double>("shifting");
        QTest::addColumn<bool>("correction");
        QTest::addColumn<bool>("fpm");
        QTest::addColumn<bool>("summation");
        QTest::addColumn<double>("relaxationS");
        QTest::newRow("plain") << 0.0 << false << false << false << 0.0;
        QTest::newRow("particle shifting A 2") << 2.0 << false << false << false << 0.0;
        QTest::newRow("particle shifting A 2, corrected") << 2.0 << true << false << false << 0.0;
        QTest::newRow("Finite Particle Method") << 0.0 << false << true << false << 0.0;
        QTest::newRow("density by summation, shifting A 2") << 2.0 << false << false << true << 0.0;
        QTest::newRow("continuity relaxed to summation over 0.5 ms, shifting A 2") << 2.0 << false << false << false << 5e-4;
    }
    void stenosisPipeParityWithOpenBoundaries()
    {
        if (vsim::cuda::devices().empty())
            QSKIP("no CUDA device on this machine; run on the accelerator with the device tool");
        QFETCH(double, shifting);
        QFETCH(bool, correction);
        QFETCH(bool, fpm);
        QFETCH(bool, summation);
        QFETCH(double, relaxationS);
        StenosisPipe pipe;
        pipe.rampS = 0.001;
        pipe.particleShifting = shifting;
        pipe.shiftCorrection = correction;
        pipe.densitySummation = summation;
        pipe.densityRelaxationS = relaxationS;
        SphSolver cpu;
        configureStenosisPipe(pipe, cpu);
        SimulationInput input;
        input.data["particles"] = stenosisPipeParticles(pipe);
        ParameterSet parameters = stenosisPipeParameters(pipe);
        parameters.set("fpm", fpm ? 1.0 : 0.0);
        cpu.initialize(input, parameters);
        const std::size_t given = cpu.particles().size();
        const ParticleState start = cpu.particles();
        std::vector<Eigen::Vector3d> startPosition(given);
        for (std::size_t i = 0; i < given; ++i)
            startPosition[std::size_t(start.id[i])] = start.position[i];
        cuda::CudaSph gpu(cpu);
        RunStatus status;
        struct Difference
        {
            double position = 0.0, positionPerSpacing = 0.0, velocity = 0.0, density = 0.0;
            std::size_t compared = 0, boundaryDiffers = 0, cpuParticles = 0, gpuParticles = 0;
        };
        // The particles given at the start, by number, on both sides.
        auto compare = [&]()
        {
            const ParticleState a = cpu.particles(), b = gpu.download();
            std::vector<std::size_t> atA(given, std::size_t(-1)), atB(given, std::size_t(-1));
            for (std::size_t s = 0; s < a.size(); ++s)
                if (std::size_t(a.id[s]) < given)
                    atA[std::size_t(a.id[s])] = s;
            for (std::size_t s = 0; s < b.size(); ++s)
                if (std::size_t(b.id[s]) < given)
                    atB[std::size_t(b.id[s])] = s;
            Difference d;
            d.cpuParticles = a.size(), d.gpuParticles = b.size();
            double displacement = 0.0, speed = 0.0, dx = 0.0, dv = 0.0, drho = 0.0;
            for (std::size_t i = 0; i < given; ++i)
            {
                if (atA[i] == std::size_t(-1) || atB[i] == std::size_t(-1))
                {
                    if (atA[i] != atB[i])
                        ++d.boundaryDiffers; // removed on one side only
                    continue;
                }
                const std::size_t sa = atA[i], sb = atB[i];
                if (a.wall[sa] != b.wall[sb] || a.boundary[sa] != b.boundary[sb])
                    ++d.boundaryDiffers;
                displacement = std::max(displacement, (a.position[sa] - startPosition[i]).norm());
                speed = std::max(speed, a.velocity[sa].norm());
                dx = std::max(dx, (a.position[sa] - b.position[sb]).norm());
                dv = std::max(dv, (a.velocity[sa] - b.velocity[sb]).norm());
                drho = std::max(drho, std::abs(a.density[sa] - b.density[sb]));
                ++d.compared;
            }
            d.position = dx / displacement, d.velocity = dv / speed, d.density = drho / 1060.0;
            d.positionPerSpacing = dx / (1e-3 * pipe.spacingMm);
            return d;
        };
        Difference at100, at300;
        for (int s = 1; s <= 300; ++s)
        {
            QVERIFY(cpu.step(status, {}).kind != sim::StepOutcome::Kind::Guard);
            const std::string guard = gpu.step();
            QVERIFY2(guard.empty(), guard.c_str());
            if (s == 100)
                at100 = compare();
        }
        at300 = compare();
        const MassLedger& la = cpu.massLedger();
        const MassLedger& lb = gpu.massLedger();
        const double inflow = double(la.totalInflow());
        const double inflowDifference = std::abs(double(lb.totalInflow()) - inflow) / inflow;
        const double outflowDifference = std::abs(double(lb.totalOutflow() - la.totalOutflow())) / inflow;
        const double q = cpu.openBoundaries().flowRate(0);
        const double inletDifference = std::abs(gpu.flowRate(0) - q) / q;
        const double outletDifference = std::abs(gpu.flowRate(1) - cpu.openBoundaries().flowRate(1)) / q;
        const double time = std::abs(gpu.timeS() - cpu.position()) / cpu.position();
        for (const auto& [steps, d] : {std::pair{100, at100}, std::pair{300, at300}})
            qInfo("stenosis pipe at 0.1 mm, particle shifting %g, FPM %d, summation %d, relaxation %g s, %d steps: particles CPU %zu, GPU %zu (%zu given, %zu compared, %zu "
                  "in another buffer or removed on one side); GPU - CPU: position %.3g of the largest "
                  "displacement, %.3g of the spacing; velocity %.3g, density %.3g (relative)",
                  shifting, int(fpm), int(summation), relaxationS, steps, d.cpuParticles, d.gpuParticles, given, d.compared, d.boundaryDiffers, d.position,
                  d.positionPerSpacing, d.velocity, d.density);
        qInfo("after 300 steps (t = %.5f s): inflow %.6g kg (GPU %.3g relative), outflow %.6g kg (GPU - CPU %.3g "
              "of the inflow); flow rates: inlet %.3g, outlet %.3g relative to the inlet's %.4g ml/s; time %.3g",
              cpu.position(), inflow, inflowDifference, double(la.totalOutflow()), outflowDifference,
              inletDifference, outletDifference, 1e6 * q, time);
        QVERIFY(la.totalInflow() > 0.0);
        QCOMPARE(at300.cpuParticles, at300.gpuParticles);
        QCOMPARE(at300.boundaryDiffers, std::size_t(0));
        // The parity for the fields (1e-4 after 100 steps; the velocity drifts on to about 1.2e-4 by 300).
        // Positions: here a particle moves 0.0025 spacings a step, and a single-precision position 5 mm from the
        // box's corner rounds by 2.3e-6 spacings a step, so the positions part by that floor (1.6e-4 spacings after
        // 300 steps, 5.7e-4 of the largest displacement after 100), not by the algorithm: bounded per spacing.
        // Density by summation reads the positions themselves, whose single-precision rounding (2.3e-6 spacings a
        // step, above) the continuity density never sees: after 100 steps the densities part by 3.2e-5 and the
        // velocities, tiny yet in the ramp's first tenth, by 2.7e-3 of the largest (on the H200, 2026-12-04;
        // 1.7e-3 after 300); relaxed towards summation over 0.5 ms, by 6.4e-6 and 6.8e-4 (6.4e-4 after 300). Their
        // velocities are held to 5e-3 and 2e-3: the 1e-4 is the continuity density's.
        const double velocityBound = summation ? 5e-3 : relaxationS > 0.0 ? 2e-3 : 1e-4;
        QVERIFY(at100.velocity <= velocityBound && at100.density <= 1e-4 && at100.positionPerSpacing <= 1e-3);
        // With particle shifting the single-precision difference grows faster after the first 100 steps (a shift
        // moves a particle by the small difference of large sums; 4.0e-4 in velocity after 300 steps on the H200).
        QVERIFY(at300.velocity <= (summation ? velocityBound : shifting > 0.0 ? 1e-3 : 3e-4) && at300.density <= 1e-4 &&
                at300.positionPerSpacing <= 1e-3 && time <= 1e-4);
        // The ledger counts whole particles: the same on both sides. The flow rates are the open ends' means
        // of the particles' velocities, so they part as the velocities do (relaxed towards summation: the
        // outlet by 8.0e-4 of the inlet's flow after 300 steps on the H200, 2026-12-04): held to the row's
        // velocity bound.
        const double flowRateBound = summation || relaxationS > 0.0 ? velocityBound : 1e-4;
        QVERIFY(inflowDifference <= 1e-4 && outflowDifference <= 1e-4);
        QVERIFY(inletDifference <= flowRateBound && outletDifference <= flowRateBound);
    }

    void runDriverWithTheGpuStepper()
    {
        if (vsim::cuda::devices().empty())
            QSKIP("no CUDA device on this machine; run on the accelerator with the device tool");
        StenosisPipe pipe;
        pipe.spacingMm = 0.2;
        SimulationInput input;
        input.data["particles"] = stenosisPipeParticles(pipe);
        StenosisPipeFlow flows[2];
        bool complete[2] = {false, false};
        std::string stopped[2];
        for (int gpu = 0; gpu < 2; ++gpu)
        {
            SphSolver solver;
            configureStenosisPipe(pipe, solver);
            if (gpu)
                solver.setStepper(cuda::cudaSphStepperFactory());
            sim::RunControl control;
            control.frameEverySteps = 500;
            const SolverRun run = sim::runSolver(solver, input, stenosisPipeParameters(pipe), control);
            QCOMPARE(solver.steppedElsewhere(), gpu == 1);
            complete[gpu] = run.status.complete();
            stopped[gpu] = run.status.complete() ? "its end" : run.status.stopMessage;
            flows[gpu] = stenosisPipeFlow(pipe, solver.sections(), solver.wallLoads(), run.metrics);
        }
        const StenosisFigures &a = flows[0].figures, &b = flows[1].figures;
        const auto relative = [](double x, double y) { return std::abs(x - y) / std::abs(y); };
        qInfo("stenosis pipe at 0.2 mm through the run driver, CPU / GPU stepper: stopped by %s / %s, %g / %g steps, "
              "peak ratio %.4f / %.4f, mean ratio %.4f / %.4f, pressure drop %.3f / %.3f Pa, throat TAWSS %.3f / "
              "%.3f Pa, inflow %.6g / %.6g kg",
              stopped[0].c_str(), stopped[1].c_str(), flows[0].metrics.at("steps"), flows[1].metrics.at("steps"),
              a.peakRatio, b.peakRatio, a.meanRatio, b.meanRatio, a.pressureDropPa, b.pressureDropPa,
              flows[0].throatWallShearPa, flows[1].throatWallShearPa, flows[0].metrics.at("inflow_kg"),
              flows[1].metrics.at("inflow_kg"));
        QVERIFY(complete[0] && complete[1]);
        QVERIFY(relative(b.peakRatio, a.peakRatio) <= 0.01 && relative(b.meanRatio, a.meanRatio) <= 0.01);
        QVERIFY(relative(b.pressureDropPa, a.pressureDropPa) <= 0.01);
        // The wall loads: both sample every 10th step, at another phase (2.7 % apart on the H100 while the GPU
        // path took every 100th step, before SphSolver::setStepper made the series sample at its cadence).
        QVERIFY(relative(flows[1].throatWallShearPa, flows[0].throatWallShearPa) <= 0.03);
        QVERIFY(relative(flows[1].metrics.at("inflow_kg"), flows[0].metrics.at("inflow_kg")) <= 1e-3);
    }

    /// A GPU run saved at step 150 (SphCheckpoint.h: the particles fetched, no rates), read back and gone on from
    /// on a new GPU stepper to step 300, against the run that did not stop: the stenosis pipe at 0.1 mm with its
    /// inlet's ramp of 1 ms, the particles given at the start compared by number as in the CPU parity (the resumed
    /// run evaluates its first rates at the saved state, where the run that went on took them mid-step: half a kick
    /// apart once), the particle count, the time and the mass through the ends.
    void aSavedGpuRunGoesOn()
    {
        if (vsim::cuda::devices().empty())
            QSKIP("no CUDA device on this machine; run on the accelerator with the device tool");
        StenosisPipe pipe;
        pipe.rampS = 0.001;
        SimulationInput input;
        input.data["particles"] = stenosisPipeParticles(pipe);
        const ParameterSet parameters = stenosisPipeParameters(pipe);
        auto stepTo = [](SphSolver& solver, int steps) {
            RunStatus status;
            while (solver.metrics().at("steps") < steps)
                QVERIFY(solver.step(status, {}).kind != sim::StepOutcome::Kind::Guard);
        };
        SphSolver whole;
        configureStenosisPipe(pipe, whole);
        whole.setStepper(cuda::cudaSphStepperFactory());
        whole.initialize(input, parameters);
        const std::size_t given = whole.particles().size();
        stepTo(whole, 300);
        SphSolver first;
        configureStenosisPipe(pipe, first);
        first.setStepper(cuda::cudaSphStepperFactory());
        first.initialize(input, parameters);
        stepTo(first, 150);
        QTemporaryDir folder;
        const std::filesystem::path file = folder.filePath("gpu.sphcheckpoint").toStdString();
        writeSphCheckpoint(first.checkpoint(), file);
        const SphCheckpoint saved = readSphCheckpoint(file);
        QCOMPARE(saved.rates.acceleration.size(), saved.particles.size()); // the GPU gives its rates
        // The run gone on from the checkpoint, and from the checkpoint without its rates (evaluated again at the
        // saved state, after the last kick rather than between the two), against the run that went on.
        struct Departure
        {
            double position = 0.0, velocity = 0.0, density = 0.0, time = 0.0, inflow = 0.0;
        };
        auto goOn = [&](const SphCheckpoint& from) {
            SphSolver second;
            configureStenosisPipe(pipe, second);
            second.setStepper(cuda::cudaSphStepperFactory());
            second.setStartState(std::make_shared<SphCheckpoint>(from));
            second.initialize(input, parameters);
            Departure d;
            if (!second.steppedElsewhere())
                return Departure{INFINITY, INFINITY, INFINITY, INFINITY, INFINITY};
            stepTo(second, 300);
            const ParticleState a = whole.particles(), b = second.particles();
            std::unordered_map<int, std::size_t> at;
            for (std::size_t s = 0; s < b.size(); ++s)
                at[b.id[s]] = s;
            double speed = 0.0;
            std::size_t compared = 0, fluid = 0;
            for (std::size_t s = 0; s < a.size(); ++s)
            {
                if (std::size_t(a.id[s]) >= given || a.boundary[s] || a.wall[s])
                    continue;
                ++fluid;
                if (!at.count(a.id[s]))
                    continue;
                const std::size_t r = at[a.id[s]];
                speed = std::max(speed, a.velocity[s].norm());
                d.position = std::max(d.position, (a.position[s] - b.position[r]).norm() / (1e-3 * pipe.spacingMm));
                d.velocity = std::max(d.velocity, (a.velocity[s] - b.velocity[r]).norm());
                d.density = std::max(d.density, std::abs(a.density[s] - b.density[r]) / 1060.0);
                ++compared;
            }
            d.velocity /= speed;
            const double inflow = whole.metrics().at("inflow_kg");
            d.inflow = std::abs(second.metrics().at("inflow_kg") - inflow) / inflow;
            d.time = std::abs(second.position() - whole.position()) / whole.position();
            if (b.size() != a.size() || fluid == 0 || compared != fluid)
                d.position = INFINITY;
            return d;
        };
        const Departure exact = goOn(saved);
        SphCheckpoint withoutRates = saved;
        withoutRates.rates = {};
        const Departure evaluated = goOn(withoutRates);
        for (const auto& [name, d] :
             {std::pair{"with the saved rates", exact}, std::pair{"rates evaluated again", evaluated}})
            qInfo("stenosis pipe at 0.1 mm on the GPU, saved at step 150 and gone on to 300 (%s) against the run "
                  "that went on: position %.3g of the spacing, velocity %.3g of the largest speed, density %.3g "
                  "(relative), time %.3g, inflow %.3g",
                  name, d.position, d.velocity, d.density, d.time, d.inflow);
        // The CPU parity's tolerances (1e-3, 3e-4, 1e-4) for the rates evaluated again; the saved rates leave
        // only the sums' order (the particles are sorted afresh). H200, 2026-12-01: with the saved rates 1.0e-5,
        // 4.4e-6, 1.2e-7, time 2.9e-9; evaluated again 3.3e-5, 4.6e-5, 1.0e-6, time 5.4e-7.
        QVERIFY(evaluated.position <= 1e-3 && evaluated.velocity <= 3e-4 && evaluated.density <= 1e-4);
        QVERIFY(evaluated.time <= 1e-4 && evaluated.inflow <= 1e-4);
        QVERIFY(exact.position <= 2e-5 && exact.velocity <= 1e-5 && exact.density <= 5e-7);
        QVERIFY(exact.time <= 1e-7 && exact.inflow <= 1e-5);
    }

    /// The phase profile (StepPhases.cuh) only waits: the same steps to the bit, and every phase of a closed
    /// domain's step listed, their times adding up to no more than the run's.
    void timingThePhasesChangesNothing()
    {
        if (vsim::cuda::devices().empty())
            QSKIP("no CUDA device on this machine; run on the accelerator with the device tool");
        SphSolver solver;
        initializeDamBreak(solver, 80.0);
        cuda::CudaSph plain(solver), timed(solver);
        timed.timePhases(true);
        const auto start = std::chrono::steady_clock::now();
        for (int s = 0; s < 20; ++s)
            QVERIFY(plain.step().empty() && timed.step().empty());
        const double both = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const ParticleState a = plain.download(), b = timed.download();
        QVERIFY(a.position == b.position && a.velocity == b.velocity && a.density == b.density);
        double total = 0.0;
        QStringList names;
        for (const auto& [phase, seconds] : timed.phaseSeconds())
            total += seconds, names << QString::fromStdString(phase);
        qInfo() << "phases:" << names.join(", ") << "in" << total << "s of" << both << "s for both runs";
        for (const char* phase : {"kick and drift", "cell keys", "radix sort", "gather", "cell ranges",
                                  "partition by kind", "wall pressure", "pressures", "neighbourhood (G, wall distance)",
                                  "rates", "kick", "reductions read back"})
            QVERIFY2(names.contains(phase), phase);
        QVERIFY(total > 0.0 && total <= both);
    }

    void refusesWhatItDoesNotRun()
    {
        if (vsim::cuda::devices().empty())
            QSKIP("no CUDA device on this machine; run on the accelerator with the device tool");
        SphSolver solver; // tracer absorption: the CPU's alone (open boundaries run on the GPU now)
        initializeDamBreak(solver, 80.0, 1.0);
        QVERIFY_THROWS_EXCEPTION(Error, cuda::CudaSph{solver});
    }
};

// Run on the accelerator outside ctest (scripts/gpu-bundle.sh), where QtTest's watchdog would stop a test
// function after its default 5 minutes: the stenosis parity rows took 150 s beside two runs on the GPU
// (2026-12-04). Half an hour unless given, as ctest gives (tests/CMakeLists.txt).
int main(int argc, char** argv)
{
    if (!qEnvironmentVariableIsSet("QTEST_FUNCTION_TIMEOUT"))
        qputenv("QTEST_FUNCTION_TIMEOUT", "1800000");
    QCoreApplication application(argc, argv);
    TestGpuSph test;
    return QTest::qExec(&test, argc, argv);
}
#include "tst_gpu_sph.moc"
