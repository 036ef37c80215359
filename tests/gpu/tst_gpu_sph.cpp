// The CUDA SPH step against the CPU one (same algorithm; issue 18's parity: fields within 1e-4 relative after
// 100 steps): the 3D dam break (DamBreak.h) at 40 mm spacing, 100 steps on both, every particle compared by
// its number. Position and velocity differences are relative to the largest displacement and the largest
// speed, the density's to the rest density, the time's to the CPU's. The GPU runs in single precision, the
// CPU in double. Skips without a device.

#include "vsim/cuda_common/DeviceInfo.h"
#include "vsim/cuda_sph/CudaSph.h"
#include "vsim/sim/sph/DamBreak.h"
#include "vsim/sim/sph/SphSolver.h"

#include <QtTest>

#include <cmath>

using namespace vsim;
using namespace vsim::sim::sph;

namespace {

void initializeDamBreak(SphSolver& solver, double spacingMm, double absorptionMm = 0.0)
{
    SimulationInput input;
    input.data["particles"] = damBreakParticles(spacingMm);
    ParameterSet parameters = damBreakParameters(spacingMm);
    parameters.set("absorption_distance_mm", absorptionMm);
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
    void damBreakParityAfter100Steps()
    {
        if (vsim::cuda::devices().empty())
            QSKIP("no CUDA device on this machine; run on the accelerator with the device tool");
        SphSolver cpu;
        initializeDamBreak(cpu, 40.0);
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

    void refusesWhatItDoesNotRun()
    {
        if (vsim::cuda::devices().empty())
            QSKIP("no CUDA device on this machine; run on the accelerator with the device tool");
        SphSolver solver; // tracer absorption: the CPU's alone
        initializeDamBreak(solver, 80.0, 1.0);
        QVERIFY_THROWS_EXCEPTION(Error, cuda::CudaSph{solver});
    }
};

QTEST_GUILESS_MAIN(TestGpuSph)
#include "tst_gpu_sph.moc"
