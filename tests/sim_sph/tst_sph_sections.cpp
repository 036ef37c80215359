// The sections' time averages (CrossSections.h, issue 18) on imposed flows, no stepping: a slab of particles whose
// speed pulses as 1 + a sin(2 pi t / T), sampled as a run samples it, against the analytic cycle mean and the
// analytic mean over the systole's phase window; and the pulsatile stenosis pipe's set-up (StenosisPipe::pulsatile).

#include "vsim/core/Error.h"
#include "vsim/sim/sph/CrossSections.h"
#include "vsim/sim/sph/FluidModel.h"
#include "vsim/sim/sph/StenosisPipe.h"

#include <QtTest>

#include <cmath>
#include <numbers>

using namespace vsim;
using namespace vsim::sim::sph;

class SphSections : public QObject
{
    Q_OBJECT
private slots:
    /// A sample's span (the time since the last sample) counts in the window as far as it overlaps it, in any cycle.
    void phaseWindowHoldsTheTimesOfEachCycle()
    {
        const PhaseWindow window{0.03, 0.006, 0.009};
        QVERIFY(std::abs(window.overlap(0.0075, 0.001) - 0.001) < 1e-15);
        QVERIFY(std::abs(window.overlap(0.0675, 0.001) - 0.001) < 1e-15); // two cycles on
        QVERIFY(std::abs(window.overlap(0.0065, 0.001) - 0.0005) < 1e-15); // the span starts before the window
        QVERIFY(std::abs(window.overlap(0.0095, 0.001) - 0.0005) < 1e-15); // the sample after its end
        QCOMPARE(window.overlap(0.005, 0.001), 0.0);
        QCOMPARE(window.overlap(0.0105, 0.001), 0.0);
        QVERIFY(PhaseWindow{}.empty() && PhaseWindow{}.overlap(0.0075, 0.001) == 0.0);
    }

    /// A 10 x 10 x 4 block of particles in a section's slab, all at speed u(t) = 1 + a sin(2 pi t / T), sampled every
    /// step of T / 400 (and every 4th) from one cycle on for two cycles: the averages read the cycle mean 1 and the
    /// systole's (0.2 T to 0.3 T) analytic mean 1 + a (cos 0.4 pi - cos 0.6 pi) / (0.2 pi) within the rectangle
    /// rule's error (a sample's change of u), and the phase window's time is a tenth of the two cycles, exactly.
    void phaseAveragesReadTheSystoleOfAPulsingFlow()
    {
        const double period = 0.03, amplitude = 0.5, s = 1e-4;
        FluidModel fluid;
        fluid.restDensity = 1060.0, fluid.viscosity = 3.5e-3, fluid.soundSpeed = 10.0;
        ParticleState particles;
        for (int i = 0; i < 10; ++i)
            for (int j = 0; j < 10; ++j)
                for (int k = 0; k < 4; ++k)
                    particles.add(Eigen::Vector3d((k - 1.5) * s, (i - 4.5) * s, (j - 4.5) * s), fluid.restDensity,
                                  fluid.restDensity * s * s * s, false);
        const CrossSection section{Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), 1.0, 4.0 * s};
        const double systoleMean = 1.0 + amplitude * (std::cos(0.4 * std::numbers::pi) - std::cos(0.6 * std::numbers::pi)) /
                                             (0.2 * std::numbers::pi);
        for (int every : {1, 4})
        {
            SectionSeries series({section}, period, every);
            series.setPhaseWindow({period, 0.2 * period, 0.3 * period});
            const int steps = 1200;
            const double dt = 3.0 * period / steps;
            for (int n = 1; n <= steps; ++n)
            {
                const double t = n * dt, u = 1.0 + amplitude * std::sin(2.0 * std::numbers::pi * t / period);
                for (auto& v : particles.velocity)
                    v = Eigen::Vector3d(u, 0.0, 0.0);
                series.sample(particles, fluid, t, dt);
            }
            const SectionFlow mean = series.averages().at(0), systole = series.phaseAverages().at(0);
            qInfo("every %d: cycle mean %.6f (1), systole %.6f (%.6f), systole's time %.6f s (%.6f)", every,
                  mean.meanVelocityMS, systole.meanVelocityMS, systoleMean, series.phaseAveragedTime(), 0.2 * period);
            const double tolerance = 2.0 * amplitude * 2.0 * std::numbers::pi * every * dt / period; // a sample's change
            QVERIFY(std::abs(mean.meanVelocityMS - 1.0) <= tolerance);
            QVERIFY(std::abs(systole.meanVelocityMS - systoleMean) <= tolerance);
            QVERIFY(std::abs(systole.peakVelocityMS - systoleMean) <= tolerance);
            QVERIFY(std::abs(series.phaseAveragedTime() - 0.2 * period) <= 1e-12);
            // Gone on from its sums (a checkpoint's) it holds them.
            SectionSeries again({section}, period, every);
            again.setPhaseWindow(series.phaseWindow());
            again.restore(series.sums());
            QCOMPARE(again.phaseAverages().at(0).meanVelocityMS, systole.meanVelocityMS);
        }
        // Without a window: no phase averages.
        SectionSeries steady({section}, 0.0);
        steady.sample(particles, fluid, 0.01, 1e-3);
        QCOMPARE(steady.phaseAveragedTime(), 0.0);
        QCOMPARE(steady.phaseAverages().at(0).particles, 0);
    }

    /// StenosisPipe::pulsatile: the waveform's peak at T / 4 (1 + a), its mean 1 over a cycle, the averaged window one
    /// whole cycle after the steady window's start, the systole about the peak, the sound speed and the Courant number
    /// those at the peak's speed, the Womersley number R0 sqrt(omega rho / mu); a reversing amplitude is refused.
    void pulsatilePipeHoldsWholeCycles()
    {
        const StenosisPipe steady = StenosisPipe{}.atFlow(0.1, 8.0);
        const StenosisPipe pipe = steady.pulsatile(0.03, 0.5);
        QCOMPARE(pipe.inflowWaveform.period(), 0.03);
        QVERIFY(std::abs(pipe.inflowWaveform.factorAt(0.0075) - 1.5) < 1e-12);
        QVERIFY(std::abs(pipe.inflowWaveform.factorAt(0.0225 + 0.06) - 0.5) < 1e-12);
        double mean = 0.0;
        for (int k = 0; k < 3000; ++k)
            mean += pipe.inflowWaveform.factorAt(0.03 * (k + 0.5) / 3000) / 3000;
        QVERIFY(std::abs(mean - 1.0) < 1e-9);
        QVERIFY(pipe.averageFromS >= steady.averageFromS - 1e-12);
        QVERIFY(std::abs(std::remainder(pipe.averageFromS, 0.03)) < 1e-12);
        QVERIFY(std::abs(pipe.endTimeS - pipe.averageFromS - 0.03) < 1e-12);
        QVERIFY(std::abs(pipe.systole.fromS - 0.006) < 1e-12 && std::abs(pipe.systole.toS - 0.009) < 1e-12);
        QVERIFY(std::abs(pipe.soundSpeedMS - 1.5 * steady.soundSpeedMS) < 1e-9);
        QVERIFY(std::abs(pipe.cfl - steady.cfl / 1.5) < 1e-12);
        QCOMPARE(pipe.inflowFactor(1.0), pipe.inflowWaveform.factorAt(1.0));
        QCOMPARE(pipe.inflowFactor(0.0), 0.0); // the ramp from rest
        const double alpha = 0.8e-3 * std::sqrt(2.0 * std::numbers::pi / 0.03 * 1060.0 / 3.5e-3);
        QVERIFY(std::abs(pipe.womersleyNumber() - alpha) < 1e-12);
        QCOMPARE(steady.womersleyNumber(), 0.0);
        QVERIFY_THROWS_EXCEPTION(Error, steady.pulsatile(0.03, 1.0));
        QVERIFY_THROWS_EXCEPTION(Error, steady.pulsatile(0.0, 0.5));
    }
};

QTEST_GUILESS_MAIN(SphSections)
#include "tst_sph_sections.moc"
