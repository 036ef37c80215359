// SPHERIC benchmark 2's set-up (DamBreak.h) and its water-height probe (DamBreakProbes.h), without stepping: the
// obstacle's wall particles and depths, the probe on still water of known depth, and the experiment's record.

#include "vsim/sim/sph/DamBreak.h"
#include "vsim/sim/sph/DamBreakProbes.h"

#include <QtTest>

#include <cmath>

using namespace vsim;
using namespace vsim::sim::sph;

namespace {

/// The particles of a ParticleSet (mm) as the solver holds them (m), at rest density.
ParticleState stateOf(const ParticleSet& set, double spacingM)
{
    ParticleState particles;
    const auto& wall = set.fields.at("wall");
    const auto& depth = set.fields.at("wall_depth_mm");
    for (std::size_t i = 0; i < set.positionsMm.size(); ++i)
        particles.add(1e-3 * set.positionsMm[i], 1000.0, 1000.0 * std::pow(spacingM, 3), wall[i] > 0.5,
                      wall[i] > 0.5 ? 1e-3 * depth[i] : -1.0);
    return particles;
}

} // namespace

class SphDamBreak : public QObject
{
    Q_OBJECT
private slots:
    /// The obstacle is a block of wall particles where the experiment's box stands (none of it water), their
    /// depth the distance to the box's nearest face (the floor side excepted); without it the set-up is the
    /// speed benchmarks' as before.
    void obstacleIsTheExperimentsBox()
    {
        const double s = 40.0; // mm
        const ParticleSet plain = damBreakParticles(s), withBox = damBreakParticles(s, true);
        const auto& wall = withBox.fields.at("wall");
        const auto& depth = withBox.fields.at("wall_depth_mm");
        std::size_t inBox = 0;
        for (std::size_t i = 0; i < withBox.positionsMm.size(); ++i)
        {
            const Eigen::Vector3d x = 1e-3 * withBox.positionsMm[i];
            bool inside = x.z() > 0.0;
            for (int a = 0; a < 3; ++a)
                inside = inside && x[a] > kDamBreakObstacleM[0][a] && x[a] < kDamBreakObstacleM[1][a];
            if (!inside)
                continue;
            ++inBox;
            QVERIFY(wall[i] > 0.5);
            const double nearest = std::min({x.x() - kDamBreakObstacleM[0][0], kDamBreakObstacleM[1][0] - x.x(),
                                             x.y() - kDamBreakObstacleM[0][1], kDamBreakObstacleM[1][1] - x.y(),
                                             kDamBreakObstacleM[1][2] - x.z()});
            QVERIFY(std::abs(depth[i] - 1e3 * nearest) < 1e-9);
        }
        // The box is 0.161 x 0.403 x 0.161 m: about 4 x 10 x 4 lattice points of 40 mm.
        QVERIFY2(inBox >= 120 && inBox <= 200, qPrintable(QString::number(inBox)));
        QCOMPARE(withBox.positionsMm.size(), plain.positionsMm.size() + inBox);
    }

    /// Still water of depth d over the tank's floor: the probe reads d within a fifth of a spacing wherever it
    /// stands against the lattice, and a dry floor reads under half a spacing. (The lattice's top layer sits half
    /// a spacing under d, so the surface of equal volume is d.)
    void probeReadsStillWater()
    {
        const double s = 0.02, depthM = 0.3;
        const QuarticKernel kernel(2.0 * s);
        ParticleState particles;
        for (int k = -4; k < 40; ++k)
            for (int i = -4; i < 24; ++i)
                for (int j = -4; j < 24; ++j)
                {
                    const bool wall = k < 0 || i < 0 || j < 0 || i >= 20 || j >= 20;
                    const Eigen::Vector3d x((i + 0.5) * s, (j + 0.5) * s, (k + 0.5) * s);
                    const bool water = !wall && x.z() < depthM && x.x() < 0.2;
                    if (wall || water)
                        particles.add(x, 1000.0, 1000.0 * s * s * s, wall, wall ? 0.5 * s : -1.0);
                }
        for (const double x : {0.1, 0.1033, 0.1071})
        {
            const double h = waterHeightM(particles, kernel, s, x, 0.2);
            QVERIFY2(std::abs(h - depthM) < 0.2 * s, qPrintable(QString("x %1: %2 m").arg(x).arg(h)));
        }
        const double dry = waterHeightM(particles, kernel, s, 0.33, 0.2);
        QVERIFY2(dry < 0.5 * s, qPrintable(QString::number(dry)));
    }

    /// The set-up's own column as the probes read it at t = 0: H1-H3 dry, H4 the column's height as the lattice
    /// holds it (the layers whose points lie under 0.55 m: 0.54 m at 20 mm; the experiment's H4 read 0.547 m).
    void probesReadTheColumnAtRest()
    {
        const double s = 20.0;
        const ParticleState particles = stateOf(damBreakParticles(s, true), 1e-3 * s);
        const QuarticKernel kernel(2.0 * 1e-3 * s);
        for (int p = 0; p < 3; ++p)
            QVERIFY(waterHeightM(particles, kernel, 1e-3 * s, kDamBreakProbeXM[std::size_t(p)], kDamBreakProbeYM) <
                    0.5e-3 * s);
        const double h4 = waterHeightM(particles, kernel, 1e-3 * s, kDamBreakProbeXM[3], kDamBreakProbeYM);
        const double layers = std::ceil(1e3 * kDamBreakWaterHeightM / s - 0.5);
        QVERIFY2(std::abs(h4 - 1e-3 * s * layers) < 0.2e-3 * s, qPrintable(QString::number(h4)));
        QVERIFY(std::abs(damBreakExperiment().at(0.0)[3] - 0.5467) < 1e-12);
    }

    /// The record between its samples is linear, and times outside it are refused.
    void experimentsRecordInterpolates()
    {
        const DamBreakExperiment& e = damBreakExperiment();
        QCOMPARE(e.heightsM.size(), std::size_t(52));
        QVERIFY(std::abs(e.lastTimeS() - 1.02) < 1e-12);
        const double mid = e.at(0.19)[2];
        QVERIFY(std::abs(mid - 0.5 * (e.heightsM[9][2] + e.heightsM[10][2])) < 1e-12);
        QVERIFY_THROWS_EXCEPTION(std::exception, e.at(1.03));
    }
};

QTEST_APPLESS_MAIN(SphDamBreak)
#include "tst_sph_dambreak.moc"
