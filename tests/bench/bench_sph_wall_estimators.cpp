// The wall loads of a settled stenosis flow read again from its end (issue 18: the throat's TAWSS against OpenFOAM):
// bench_sph_cuda_stenosis --checkpoint saves the run's last state, and here the CPU reads it back into the same
// problem and evaluates the stenosis pipe's wall rings (every 0.05 mm, 8 points each) at that instant by WallShear.h
// (so a saved run can be read again by a changed estimate), beside the run's own time averages from the
// checkpoint (TAWSS, OSI: a steady flow, OSI 0, reads the same at an instant as over the window). Prints one JSON
// object: the throat slab's means and every ring.
//
//   bench_sph_wall_estimators <checkpoint> <spacing mm> [mean speed m/s] [length mm] [particle shifting A]
//                             [solver parameter=value]... [--steps N] [--profile-at X_MM]
//
// --steps goes on N steps on the CPU first, printing each step's largest density variation (stderr): whether a
// saved GPU run goes on smoothly in double precision.
// --profile-at adds the fluid particles within a spacing of the section at x = X_MM ("profile": their distance from
// the axis and from the wall, mm, and their axial speed, m/s): the near-wall velocity profile the wall shear is
// read from, for a comparison with the reference solver's cells there (compare_throat_profile.py).
//
// The arguments after the checkpoint are bench_sph_cuda_stenosis's (its every and sound speed left out: the sound
// speed follows the speed as there).

#include "StenosisArguments.h"

#include "vsim/core/Error.h"
#include "vsim/sim/sph/SphCheckpoint.h"
#include "vsim/sim/sph/SphSolver.h"
#include "vsim/sim/sph/StenosisPipe.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace vsim;
using namespace vsim::sim::sph;

int main(int argc, char** argv)
try
{
    long cpuSteps = 0;
    double profileAtMm = NAN;
    for (bool taken = true; taken && argc > 2;)
    {
        const std::string option = argv[argc - 2];
        taken = option == "--steps" || option == "--profile-at";
        if (option == "--steps")
            cpuSteps = std::stol(argv[argc - 1]);
        else if (option == "--profile-at")
            profileAtMm = std::stod(argv[argc - 1]);
        if (taken)
            argc -= 2;
    }
    if (argc < 3)
    {
        std::fprintf(stderr, "usage: bench_sph_wall_estimators <checkpoint> <spacing mm> [mean speed m/s] [length mm] "
                             "[particle shifting A] [solver parameter=value]...\n");
        return 2;
    }
    StenosisPipe pipe;
    pipe.spacingMm = std::stod(argv[2]);
    if (argc > 3)
        pipe = pipe.atFlow(std::stod(argv[3]), argc > 4 ? std::stod(argv[4]) : pipe.lengthMm);
    if (argc > 5)
        pipe.particleShifting = std::stod(argv[5]);
    bench::takeSmoothingRatio(pipe, 6, argc, argv);
    SphSolver solver;
    configureStenosisPipe(pipe, solver);
    SimulationInput input;
    input.data["particles"] = stenosisPipeParticles(pipe);
    ParameterSet parameters = stenosisPipeParameters(pipe);
    for (int a = 6; a < argc; ++a)
        parameters.setFromText(argv[a]);
    const auto saved = std::make_shared<SphCheckpoint>(readSphCheckpoint(argv[1]));
    solver.setStartState(saved);
    solver.initialize(input, parameters);
    for (long step = 0; step < cpuSteps; ++step)
    {
        RunStatus status;
        const sim::StepOutcome outcome = solver.step(status, {});
        const auto metrics = solver.metrics();
        std::fprintf(stderr, "CPU step %ld: t = %.6f ms, largest density variation %.5f%s\n", step + 1,
                     1e3 * solver.position(), metrics.at("largest_density_variation"),
                     outcome.kind == sim::StepOutcome::Kind::Guard ? " (a guard stopped it)" : "");
        if (outcome.kind == sim::StepOutcome::Kind::Guard)
            break;
    }
    const ParticleState& particles = solver.particles();
    NeighbourGrid grid(solver.kernel().support());
    grid.build(particles.position);
    const double spacing = 1e-3 * pipe.spacingMm;
    const std::vector<WallPoint>& points = solver.wallLoads().points();
    const std::vector<WallLoadAverage> averaged = solver.wallLoads().averages();
    const int around = 8;
    nlohmann::json rings = nlohmann::json::array();
    double throat[4] = {0.0, 0.0, 0.0, 0.0}; // |tau_w| and p now, the run's TAWSS and OSI
    int throatRings = 0;
    for (std::size_t ring = 0; ring * around < points.size(); ++ring)
    {
        double shear = 0.0, pressure = 0.0, run = 0.0, osi = 0.0;
        for (std::size_t k = ring * around; k < (ring + 1) * around; ++k)
        {
            const WallLoad load = wallLoad(particles, grid, solver.kernel(), solver.fluid(), spacing, points[k]);
            shear += load.shearPa.norm() / around, pressure += load.pressurePa / around;
            if (k < averaged.size())
                run += averaged[k].tawssPa / around, osi += averaged[k].osi / around;
        }
        const double xMm = 1e3 * points[ring * around].positionM.x();
        rings.push_back({{"x_mm", xMm}, {"wss_pa", shear}, {"pressure_pa", pressure}, {"run_tawss_pa", run},
                         {"run_osi", osi}});
        if (std::abs(xMm - pipe.throatAtMm) <= 0.5 * pipe.sectionThicknessMm() + 1e-9)
            throat[0] += shear, throat[1] += pressure, throat[2] += run, throat[3] += osi, ++throatRings;
    }
    for (double& value : throat)
        value /= std::max(1, throatRings);
    nlohmann::json profile = nlohmann::json::object();
    if (std::isfinite(profileAtMm))
    {
        const double radiusMm = pipe.radiusAtMm(profileAtMm);
        std::vector<double> axis, wall, speed;
        for (std::size_t i = 0; i < particles.size(); ++i)
        {
            const Eigen::Vector3d& x = particles.position[i];
            if (!particles.isFluid(i) || std::abs(1e3 * x.x() - profileAtMm) > pipe.spacingMm)
                continue;
            const double r = 1e3 * std::hypot(x.y(), x.z());
            axis.push_back(r), wall.push_back(radiusMm - r), speed.push_back(particles.velocity[i].x());
        }
        profile = {{"x_mm", profileAtMm}, {"radius_mm", radiusMm}, {"half_width_mm", pipe.spacingMm},
                   {"axis_distance_mm", axis}, {"wall_distance_mm", wall}, {"axial_speed_m_s", speed}};
    }
    const nlohmann::json report = {{"case", "sph-stenosis wall shear estimates at the run's end"},
                                   {"checkpoint", argv[1]},
                                   {"time_s", solver.position()},
                                   {"spacing_mm", pipe.spacingMm},
                                   {"mean_speed_m_s", pipe.meanSpeedMS},
                                   {"throat_reynolds", pipe.throatReynolds()},
                                   {"throat", {{"wss_pa", throat[0]}, {"pressure_pa", throat[1]},
                                               {"run_tawss_pa", throat[2]}, {"run_osi", throat[3]}}},
                                   {"rings", rings},
                                   {"profile", profile}};
    std::printf("%s\n", report.dump(1).c_str());
    return 0;
}
catch (const std::exception& error)
{
    std::fprintf(stderr, "bench_sph_wall_estimators: %s\n", error.what());
    return 1;
}
