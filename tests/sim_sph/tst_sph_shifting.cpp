// Particle shifting (issue 18; SphRates.h): the shift evens out a jittered lattice and sends a displaced particle
// back; its Taylor correction adds the exact (s . grad) v in a shear flow; the solver refuses shifting with a free
// surface or without tension. Split from tst_sph_particles.cpp (the particle machinery).

#include "JitteredLattice.h"
#include "SphRefusal.h"

#include "vsim/core/Error.h"
#include "vsim/sim/sph/FluidModel.h"
#include "vsim/sim/sph/NeighbourGrid.h"
#include "vsim/sim/sph/QuarticKernel.h"
#include "vsim/sim/sph/SphRates.h"
#include "vsim/sim/sph/SphSolver.h"

#include <QtTest>

#include <cmath>
#include <numbers>
#include <random>

using namespace vsim;
using namespace vsim::sim::sph;

class SphShifting : public QObject
{
    Q_OBJECT
private slots:
    /// Particle shifting (SphRates.h) on a periodic lattice of fluid moving as a whole: none on the perfect lattice
    /// (by symmetry, to rounding); one particle moved 0.3 spacings off its site is sent back along the line it left by;
    /// a lattice jittered by up to 0.25 spacings (three seeds) moved by the shift alone evens out: the RMS shift
    /// velocity falls at least fivefold in 200 moves by dt s_i, |v| dt = 0.05 spacings. With a speed floor a slower
    /// fluid is shifted as at the floor's speed. Off (A = 0): no shift computed.
    void particleShiftingEvensOutTheParticles()
    {
        const double spacing = 1e-4, period = 10 * spacing;
        const Eigen::Vector3d velocity(0.1, 0.0, 0.0);
        const QuarticKernel kernel(2.0 * spacing);
        FluidModel fluid;
        fluid.particleShifting = 2.0;
        fluid.shiftingReciprocalWeight = 1.0 / kernel.value(spacing);
        NeighbourGrid grid(kernel.support(), Eigen::Vector3d::Constant(period));
        auto lattice = [&](double jitter, unsigned seed)
        {
            std::mt19937 random(seed);
            std::uniform_real_distribution<double> offset(-jitter, jitter);
            ParticleState particles;
            for (int k = 0; k < 10; ++k)
                for (int j = 0; j < 10; ++j)
                    for (int i = 0; i < 10; ++i)
                    {
                        const Eigen::Vector3d site = spacing * (Eigen::Vector3d(i, j, k) + Eigen::Vector3d::Constant(0.5));
                        const Eigen::Vector3d moved(offset(random), offset(random), offset(random));
                        particles.add(grid.wrap(site + spacing * moved), fluid.restDensity,
                                      fluid.restDensity * spacing * spacing * spacing, false);
                        particles.velocity.back() = velocity;
                    }
            return particles;
        };
        auto shifts = [&](const ParticleState& particles, const FluidModel& model)
        {
            grid.build(particles.position);
            SphRates rates;
            computeRates(particles, pressures(particles, model), grid, kernel, model, 0.0, rates);
            return rates.shiftVelocity;
        };
        auto rms = [](const std::vector<Eigen::Vector3d>& values)
        {
            double sum = 0.0;
            for (const auto& v : values)
                sum += v.squaredNorm();
            return std::sqrt(sum / double(values.size()));
        };
        ParticleState perfect = lattice(0.0, 1);
        double largest = 0.0;
        for (const auto& s : shifts(perfect, fluid))
            largest = std::max(largest, s.norm());
        QVERIFY2(largest <= 1e-9 * velocity.norm(), qPrintable(QString::number(largest)));

        const std::size_t moved = 555; // i = j = k = 5
        perfect.position[moved].y() += 0.3 * spacing;
        const Eigen::Vector3d back = shifts(perfect, fluid)[moved];
        qInfo("a particle 0.3 spacings off its site: shift velocity (%.3g, %.3g, %.3g) m/s at |v| %.3g m/s", back.x(),
              back.y(), back.z(), velocity.norm());
        QVERIFY(back.y() < -1e-3 * velocity.norm());
        QVERIFY(std::abs(back.x()) <= 1e-6 * std::abs(back.y()) && std::abs(back.z()) <= 1e-6 * std::abs(back.y()));

        // The speed floor (FluidModel::shiftingSpeedMS): the same particle in a fluid at a tenth of the speed is
        // shifted as at the floor's speed; a floor below |v| changes nothing.
        ParticleState slow = perfect;
        for (auto& v : slow.velocity)
            v = 0.1 * velocity;
        FluidModel floored = fluid;
        floored.shiftingSpeedMS = velocity.norm();
        const Eigen::Vector3d slowBack = shifts(slow, fluid)[moved], flooredBack = shifts(slow, floored)[moved];
        QVERIFY((slowBack - 0.1 * back).norm() <= 1e-9 * back.norm());
        QVERIFY((flooredBack - back).norm() <= 1e-9 * back.norm());
        floored.shiftingSpeedMS = 0.5 * velocity.norm();
        QVERIFY((shifts(perfect, floored)[moved] - back).norm() <= 1e-12 * back.norm());

        for (unsigned seed : {11u, 12u, 13u})
        {
            ParticleState jittered = lattice(0.25, seed);
            const double step = 0.05 * spacing / velocity.norm(); // |v| dt = 0.05 spacings
            const double before = rms(shifts(jittered, fluid));
            for (int move = 0; move < 200; ++move)
            {
                const std::vector<Eigen::Vector3d> s = shifts(jittered, fluid);
                for (std::size_t i = 0; i < jittered.size(); ++i)
                    jittered.position[i] = grid.wrap(jittered.position[i] + step * s[i]);
            }
            const double after = rms(shifts(jittered, fluid));
            qInfo("seed %u: RMS shift velocity %.4g -> %.4g m/s after 200 moves", seed, before, after);
            QVERIFY(after < 0.2 * before);
        }
        FluidModel off = fluid;
        off.particleShifting = 0.0;
        QVERIFY(shifts(perfect, off).empty());
    }

    /// The shift's correction (FluidModel::shiftCorrection, SphRates.h) adds (s_i . grad) v_i to the acceleration:
    /// in a periodic shear flow v = (U sin(2 pi y / L), 0, 0) on a jittered lattice (three seeds) the added
    /// acceleration against the exact s_y U (2 pi / L) cos(2 pi y / L) in x (with each particle's own shift s_i):
    /// RMS within 10 % of the exact's RMS, y and z within 10 % of it (G s, not G^T s, whose x would be s_x dv_y/dx
    /// = 0 and y s_x dv_x/dy); nothing added in a uniform flow, nor without shifting.
    void shiftCorrectionCarriesTheVelocityField()
    {
        const double spacing = 1e-4, speed = 0.1;
        const int nx = 10, ny = 24, nz = 10; // a periodic axis is at least 2.5 supports (10 spacings) long
        const double length = ny * spacing, wave = 2.0 * std::numbers::pi / length;
        const QuarticKernel kernel(2.0 * spacing);
        FluidModel fluid;
        fluid.particleShifting = 2.0;
        fluid.shiftingReciprocalWeight = 1.0 / kernel.value(spacing);
        NeighbourGrid grid(kernel.support(), spacing * Eigen::Vector3d(nx, ny, nz));
        auto lattice = [&](double jitter, unsigned seed, bool shear)
        {
            ParticleState particles;
            for (const Eigen::Vector3d& site : test::jitteredLattice({nx, ny, nz}, spacing, jitter, seed))
            {
                const Eigen::Vector3d x = grid.wrap(site + Eigen::Vector3d::Constant(0.5 * spacing));
                particles.add(x, fluid.restDensity, fluid.restDensity * spacing * spacing * spacing, false);
                particles.velocity.back() = Eigen::Vector3d(shear ? speed * std::sin(wave * x.y()) : speed, 0.0, 0.0);
            }
            return particles;
        };
        auto rates = [&](const ParticleState& particles, bool correction)
        {
            FluidModel model = fluid;
            model.shiftCorrection = correction;
            grid.build(particles.position);
            SphRates r;
            computeRates(particles, pressures(particles, model), grid, kernel, model, 0.0, r);
            return r;
        };
        for (unsigned seed : {21u, 22u, 23u})
        {
            const ParticleState particles = lattice(0.15, seed, true);
            const SphRates plain = rates(particles, false), corrected = rates(particles, true);
            double exact2 = 0.0, error2 = 0.0, across2 = 0.0;
            for (std::size_t i = 0; i < particles.size(); ++i)
            {
                const Eigen::Vector3d added = corrected.acceleration[i] - plain.acceleration[i];
                const Eigen::Vector3d& shift = corrected.shiftVelocity[i];
                QCOMPARE(shift, plain.shiftVelocity[i]);
                const double exact = shift.y() * speed * wave * std::cos(wave * particles.position[i].y());
                exact2 += exact * exact;
                error2 += (added.x() - exact) * (added.x() - exact);
                across2 += added.y() * added.y() + added.z() * added.z();
            }
            const double error = std::sqrt(error2 / exact2), across = std::sqrt(across2 / exact2);
            qInfo("seed %u: added acceleration in x against (s . grad) v: RMS error %.4f of the exact's RMS %.4g m/s^2; "
                  "in y and z %.2e of it",
                  seed, error, std::sqrt(exact2 / double(particles.size())), across);
            QVERIFY(exact2 > 0.0);
            QVERIFY(error <= 0.10);
            QVERIFY(across <= 0.10);
        }
        const ParticleState uniform = lattice(0.15, 24u, false);
        const SphRates plain = rates(uniform, false), corrected = rates(uniform, true);
        for (std::size_t i = 0; i < uniform.size(); ++i)
            QVERIFY((corrected.acceleration[i] - plain.acceleration[i]).norm() <= 1e-12 * speed / spacing * speed);
        FluidModel off = fluid;
        off.particleShifting = 0.0, off.shiftCorrection = true;
        grid.build(uniform.position);
        SphRates none;
        computeRates(uniform, pressures(uniform, off), grid, kernel, off, 0.0, none);
        FluidModel offPlain = off;
        offPlain.shiftCorrection = false;
        SphRates nonePlain;
        computeRates(uniform, pressures(uniform, offPlain), grid, kernel, offPlain, 0.0, nonePlain);
        QCOMPARE(none.acceleration, nonePlain.acceleration);
    }

    /// Particle shifting with a free surface or without tension is refused with the reason.
    void particleShiftingNeedsAFilledVessel()
    {
        for (const char* name : {"free_surface", "fluid_tension"})
        {
            const std::string refusal = test::sphRefusal(
                {{"particle_shifting", 2.0}, {name, std::string(name) == "free_surface" ? 1.0 : 0.0}});
            QVERIFY2(refusal.find("particle_shifting 0") != std::string::npos, name);
        }
    }

};

QTEST_APPLESS_MAIN(SphShifting)
#include "tst_sph_shifting.moc"
