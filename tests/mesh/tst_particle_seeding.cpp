// Particles for the blood-flow solver from a segmented lumen (issue 18, ParticleSeeding.h): a closed tube label
// (radius 5 mm, voxels of 0.5 mm), three lattice spacings up to the voxel and tube positions. The fluid's volume against the
// label's, every side-wall particle's depth against its exact depth below the tube's surface (r - R), the layers'
// extent; then the SPH solver takes the particles and the fluid at rest stays at rest. Open ends: buffers behind the
// planes, walled around, no caps, and an inflow run whose mass ledger balances.

#include "vsim/core/Error.h"
#include "vsim/mesh/ParticleSeeding.h"
#include "vsim/sim/common/RunDriver.h"
#include "vsim/sim/sph/SphSolver.h"

#include <QtTest>

#include <array>
#include <cmath>
#include <numbers>
#include <random>

using namespace vsim;

namespace {

constexpr double kRadiusMm = 5.0, kVoxelMm = 0.5;

/// A tube along z, radius 5 mm, its axis at (cx, cy), from z = 5 to 25 mm, in a 24 x 24 x 30 mm label.
LabelVolume tube(double cx, double cy)
{
    VolumeGeometry geometry;
    geometry.dims = {48, 48, 60};
    geometry.spacing = Eigen::Vector3d::Constant(kVoxelMm);
    LabelVolume label(geometry);
    for (int k = 0; k < 60; ++k)
        for (int j = 0; j < 48; ++j)
            for (int i = 0; i < 48; ++i)
            {
                const Eigen::Vector3d p = geometry.indexToPatient(Eigen::Vector3d(i, j, k));
                if (std::hypot(p.x() - cx, p.y() - cy) <= kRadiusMm && p.z() >= 5.0 && p.z() <= 25.0)
                    label.at(i, j, k) = 1;
            }
    return label;
}

} // namespace

class ParticleSeedingTest : public QObject
{
    Q_OBJECT
private slots:
    void tubeParticles()
    {
        std::mt19937 random(7);
        std::uniform_real_distribution<double> shift(-0.3, 0.3);
        for (double spacing : {0.3, 0.4, 0.5}) // at most the voxel: coarser lattices sample a 10 mm tube by 6 % (0.7 mm)
        {
            const double cx = 12.0 + shift(random), cy = 12.0 + shift(random);
            const LabelVolume label = tube(cx, cy);
            std::size_t lumenVoxels = 0;
            for (std::size_t v = 0; v < label.size(); ++v)
                lumenVoxels += label.data()[v] == 1;
            const ParticleSet particles = mesh::seedVesselParticles(label, {spacing, 4, 1});
            particles.validate();
            std::size_t fluid = 0;
            double worstDepth = 0.0, sumDepth = 0.0, signedSum = 0.0, deepest = 0.0, shallowest = INFINITY;
            int side = 0;
            for (std::size_t i = 0; i < particles.size(); ++i)
            {
                const Eigen::Vector3d& p = particles.positionsMm[i];
                if (particles.fields.at("wall")[i] < 0.5)
                {
                    ++fluid;
                    continue;
                }
                const double depth = particles.fields.at("wall_depth_mm")[i];
                deepest = std::max(deepest, depth), shallowest = std::min(shallowest, depth);
                if (p.z() < 8.0 || p.z() > 22.0) // the side wall, away from the closed ends
                    continue;
                const double error = depth - (std::hypot(p.x() - cx, p.y() - cy) - kRadiusMm);
                worstDepth = std::max(worstDepth, std::abs(error));
                sumDepth += std::abs(error), signedSum += error, ++side;
            }
            const double volumeRatio = double(fluid) * std::pow(spacing, 3) / (double(lumenVoxels) * std::pow(kVoxelMm, 3));
            qInfo("spacing %.1f mm: %zu fluid, %zu wall particles; fluid volume / label volume %.4f; side-wall depth "
                  "error mean %.3f mm (signed %+.3f), largest %.3f mm; depths %.3f .. %.3f mm",
                  spacing, fluid, particles.size() - fluid, volumeRatio, sumDepth / side, signedSum / side, worstDepth,
                  shallowest, deepest);
            QVERIFY(std::abs(volumeRatio - 1.0) < 0.03);
            // The label's staircase and the lattice's offsets each scatter the depth by about a quarter of their step
            // on average (the signed mean, printed, is the lattice's and the staircase's bias: -0.05 to -0.11 mm).
            QVERIFY(sumDepth / side < 0.3 * (spacing + kVoxelMm));
            // The label's surface lies within half a voxel diagonal of the tube's; the nearest lattice point within a
            // spacing of the distance to the label's surface.
            QVERIFY(worstDepth < spacing + 0.5 * std::sqrt(3.0) * kVoxelMm);
            QCOMPARE(shallowest, 0.5 * spacing);
            QVERIFY(deepest < 4.0 * spacing + 1e-9);
        }
        QVERIFY_THROWS_EXCEPTION(Error, mesh::seedVesselParticles(LabelVolume(tube(12, 12).geometry()), {0.5, 4, 1}));
        QVERIFY_THROWS_EXCEPTION(Error, mesh::seedVesselParticles(tube(12, 12), {0.0, 4, 1}));
    }

    /// The seeded tube handed to the solver: closed, without gravity, the blood at 1 kPa (7.5 mmHg) everywhere, walls
    /// included, stays at rest: the wall layers leave no hole in any fluid particle's support (a hole would push it).
    void seededFluidStaysAtRest()
    {
        ParticleSet particles = mesh::seedVesselParticles(tube(12.0, 12.0), {0.7, 4, 1});
        particles.fields["pressure_pa"].assign(particles.size(), 1000.0);
        SimulationInput input;
        input.data["particles"] = particles;
        ParameterSet parameters(sim::sph::sphParameters());
        parameters.set("spacing_mm", 0.7);
        parameters.set("sound_speed_m_s", 10.0);
        parameters.set("end_time_s", 0.002);
        sim::sph::SphSolver solver;
        sim::RunControl control;
        control.keepFramesInMemory = false;
        const SolverRun run = sim::runSolver(solver, input, parameters, control);
        qInfo("seeded tube at rest after %.0f steps (%.3g s): largest speed %.3g m/s (%.2g of the sound speed), "
              "density within %.3g", run.metrics.at("steps"), solver.position(), run.metrics.at("largest_speed_m_s"),
              run.metrics.at("largest_speed_m_s") / 10.0, run.metrics.at("largest_density_variation"));
        QVERIFY(run.status.complete());
        QVERIFY(run.metrics.at("largest_speed_m_s") < 0.01 * 10.0);

        // A fluid particle shot at the wall at 30 m/s (a run gone wrong): the guard stops the run with the particle
        // and where it went through, the last frame the state before that step.
        particles.fields["velocity_x_m_s"].assign(particles.size(), 0.0);
        particles.fields["velocity_y_m_s"].assign(particles.size(), 0.0);
        particles.fields["velocity_z_m_s"].assign(particles.size(), 0.0);
        std::size_t shot = 0;
        for (std::size_t i = 0; i < particles.size(); ++i) // the fluid particle nearest the side wall at +x
            if (particles.fields.at("wall")[i] < 0.5 && std::abs(particles.positionsMm[i].z() - 15.0) < 0.4 &&
                particles.positionsMm[i].x() > particles.positionsMm[shot].x())
                shot = i;
        particles.fields["velocity_x_m_s"][shot] = 30.0;
        input.data["particles"] = particles;
        control.frameEverySteps = 1;
        control.keepFramesInMemory = true;
        sim::sph::SphSolver shooter;
        const SolverRun broken = sim::runSolver(shooter, input, parameters, control);
        qInfo("%s", broken.status.stopText().c_str());
        QCOMPARE(broken.status.stoppedBy, RunStatus::StoppedBy::Guard);
        QVERIFY(broken.status.stopMessage.find("into the wall") != std::string::npos);
        QVERIFY(broken.status.stopMessage.find("particle " + std::to_string(shot)) != std::string::npos);
        QVERIFY(!broken.frames.empty());
    }

    /// The tube with open ends at z = 5 (an inlet, normal +z) and z = 25 mm (an outlet): behind each plane a buffer
    /// of the tube's section, a depth deep and walled around, no cap; then a short inflow run balances its ledger.
    void openEnds()
    {
        const double spacing = 1.0, depth = 4.0 * spacing;
        mesh::ParticleSeeding seeding{spacing, 4, 1, {}};
        seeding.openEnds.push_back({Eigen::Vector3d(12.0, 12.0, 5.0), Eigen::Vector3d::UnitZ(), kRadiusMm + 0.5, depth});
        seeding.openEnds.push_back({Eigen::Vector3d(12.0, 12.0, 25.0), -Eigen::Vector3d::UnitZ(), kRadiusMm + 0.5, depth});
        const ParticleSet particles = mesh::seedVesselParticles(tube(12.0, 12.0), seeding);
        const auto& wall = particles.fields.at("wall");
        const auto& buffer = particles.fields.at("open_boundary");
        std::array<int, 3> buffered{0, 0, 0};
        int capWalls = 0, bufferWalls = 0;
        for (std::size_t i = 0; i < particles.size(); ++i)
        {
            const Eigen::Vector3d& p = particles.positionsMm[i];
            const double r = std::hypot(p.x() - 12.0, p.y() - 12.0);
            if (wall[i] > 0.5)
            {
                capWalls += r < kRadiusMm - spacing;
                bufferWalls += (p.z() < 5.0 || p.z() > 25.0) && r > kRadiusMm;
                continue;
            }
            const int end = int(buffer[i]);
            ++buffered[std::size_t(end)];
            if (end == 1)
                QVERIFY(p.z() < 5.0 && p.z() >= 5.0 - depth);
            else if (end == 2)
                QVERIFY(p.z() > 25.0 && p.z() <= 25.0 + depth);
            else
                QVERIFY(p.z() >= 5.0 && p.z() <= 25.0);
        }
        const double expected = std::numbers::pi * kRadiusMm * kRadiusMm * depth / std::pow(spacing, 3);
        qInfo("open ends: %d and %d buffer particles (the section x depth: %.0f), %d walls around the buffers, %d in "
              "the caps", buffered[1], buffered[2], expected, bufferWalls, capWalls);
        QVERIFY(std::abs(buffered[1] / expected - 1.0) < 0.1 && std::abs(buffered[2] / expected - 1.0) < 0.1);
        QCOMPARE(capWalls, 0);
        QVERIFY(bufferWalls > 0);

        SimulationInput input;
        input.data["particles"] = particles;
        ParameterSet parameters(sim::sph::sphParameters());
        parameters.set("spacing_mm", spacing);
        parameters.set("sound_speed_m_s", 10.0);
        parameters.set("end_time_s", 0.016); // the buffer's first layer 0.75 mm behind the plane crosses it
        sim::sph::OpenBoundary inlet, outlet;
        inlet.name = "inlet", inlet.centreM = Eigen::Vector3d(12e-3, 12e-3, 5e-3), inlet.normal = Eigen::Vector3d::UnitZ();
        inlet.radiusM = 5.5e-3, inlet.prescribed = sim::sph::OpenBoundary::Prescribed::Velocity;
        inlet.flowRateM3S = 0.05 * std::numbers::pi * 25e-6; // a mean of 0.05 m/s, from rest over 2 ms
        inlet.rampS = 0.002;
        outlet.name = "outlet", outlet.centreM = Eigen::Vector3d(12e-3, 12e-3, 25e-3), outlet.normal = -Eigen::Vector3d::UnitZ();
        outlet.radiusM = 5.5e-3;
        sim::sph::SphSolver solver;
        solver.setOpenBoundaries({inlet, outlet});
        sim::RunControl control;
        control.keepFramesInMemory = false;
        const SolverRun run = sim::runSolver(solver, input, parameters, control);
        QVERIFY2(run.status.complete(), run.status.stopText().c_str());
        const double in = run.metrics.at("inflow_kg"), out = run.metrics.at("outflow_kg");
        qInfo("seeded tube with an inlet: %.0f steps, inflow %.3g kg, outflow %.3g kg, mass change %.3g kg", run.metrics.at("steps"), in,
              out, run.metrics.at("fluid_mass_change_kg"));
        QVERIFY(in > 0.0);
        QVERIFY(std::abs(in - out - run.metrics.at("fluid_mass_change_kg")) < 1e-12 * in);
    }
};

QTEST_APPLESS_MAIN(ParticleSeedingTest)
#include "tst_particle_seeding.moc"
