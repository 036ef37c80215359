// sph-poiseuille: laminar flow between two plates driven by a body force (issue 18; Morris et al. 1997's test). The
// channel is 20 particles across (0.1 mm, H = 2 mm) between four layers of wall particles on each side, periodic
// along the flow (x) and across it (z), started from rest; after 7 slowest-mode decay times H^2 / (pi^2 nu) the
// velocity of every fluid particle against the steady solution u(y) = G / (2 nu) y (H - y), the walls' no-slip
// planes at y = 0 and H (half a spacing beyond the last fluid layer), and the wall shear stress at points on both
// plates (WallShear.h), averaged over the last decay time, against 4 mu u_max / H.

#include "SphCases.h"

#include "vsim/core/Error.h"
#include "vsim/core/StoredText.h"
#include "vsim/sim/common/RunDriver.h"
#include "vsim/sim/sph/SphSolver.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vsim::sim::sph::detail {
namespace {

constexpr int kAcross = 20, kPeriod = 12, kWallLayers = 4;
constexpr double kSpacingMm = 0.1, kDensity = 1000.0, kViscosity = 0.1, kPeakSpeed = 0.1; // Pa s, m/s

ParticleSet channel()
{
    ParticleSet set;
    auto& wall = set.fields["wall"];
    auto& depth = set.fields["wall_depth_mm"]; // below the plates' surfaces at y = 0 and H
    for (int k = 0; k < kPeriod; ++k)
        for (int j = -kWallLayers; j < kAcross + kWallLayers; ++j)
            for (int i = 0; i < kPeriod; ++i)
            {
                set.positionsMm.push_back(kSpacingMm * Eigen::Vector3d(i + 0.5, j + 0.5, k + 0.5));
                wall.push_back(j < 0 || j >= kAcross ? 1.0 : 0.0);
                depth.push_back(kSpacingMm * (j < 0 ? -j - 0.5 : j >= kAcross ? j - kAcross + 0.5 : 0.0));
            }
    return set;
}

} // namespace

ValidationResult poiseuilleCase(const Progress& progress)
{
    ValidationResult result;
    result.name = "sph-poiseuille";
    const double heightM = kAcross * kSpacingMm * 1e-3, nu = kViscosity / kDensity;
    const double force = 8.0 * nu * kPeakSpeed / (heightM * heightM); // m/s^2 for the peak speed
    const double decay = heightM * heightM / (std::numbers::pi * std::numbers::pi * nu);
    result.description = storedText("plane Poiseuille flow, 20 particles across a 2 mm channel (periodic along and "
                                    "across the flow, peak 0.1 m/s, Re 2), after 7 decay times: every fluid particle's "
                                    "velocity against the steady profile");
    ParameterSet parameters = caseParameters(kSpacingMm, kDensity, kViscosity, 10.0 * kPeakSpeed);
    parameters.set("body_force_x_m_s2", force);
    parameters.set("periodic_x_mm", kPeriod * kSpacingMm);
    parameters.set("periodic_z_mm", kPeriod * kSpacingMm);
    parameters.set("end_time_s", 7.0 * decay);
    SphSolver solver;
    // The wall shear stress on both plates over the last decay time: tau_w = mu G H / (2 nu) = 4 mu u_max / H.
    std::vector<WallPoint> plates;
    for (int i = 0; i < kPeriod; i += 3)
        for (int k = 0; k < kPeriod; k += 3)
            for (int side : {0, 1})
                plates.push_back({1e-3 * kSpacingMm * Eigen::Vector3d(i + 0.25, side * kAcross, k + 0.25),
                                  Eigen::Vector3d(0.0, side ? -1.0 : 1.0, 0.0)});
    solver.setWallPoints(plates, 6.0 * decay);
    const SolverRun run = runCase(result.name, solver, channel(), parameters, progress);

    const ParticleState& particles = solver.particles();
    double squares = 0.0, worst = 0.0, peak = 0.0, across = 0.0;
    int count = 0;
    for (std::size_t i = 0; i < particles.size(); ++i)
    {
        if (particles.wall[i])
            continue;
        const double y = particles.position[i].y();
        const double exact = force / (2.0 * nu) * y * (heightM - y);
        const double error = (particles.velocity[i].x() - exact) / kPeakSpeed;
        squares += error * error, ++count;
        worst = std::max(worst, std::abs(error));
        peak = std::max(peak, particles.velocity[i].x());
        across = std::max(across, std::hypot(particles.velocity[i].y(), particles.velocity[i].z()));
    }
    result.figures.push_back({"RMS velocity error / peak velocity", std::sqrt(squares / count), 0.0, 0.01, ""});
    result.figures.push_back({"largest particle's speed / analytic peak", peak / kPeakSpeed, 1.0, 0.02, ""});
    result.figures.push_back({"largest density variation", run.metrics.at("largest_density_variation"), 0.0, 0.01, ""});
    result.figures.push_back({"largest cross-flow speed / peak velocity", across / kPeakSpeed, 0.0, 0.01, ""});
    const double exactShear = 4.0 * kViscosity * kPeakSpeed / heightM;
    double shear = 0.0, worstShear = 0.0;
    for (const WallLoadAverage& load : solver.wallLoads().averages())
    {
        shear += load.tawssPa / plates.size();
        worstShear = std::max(worstShear, std::abs(load.tawssPa / exactShear - 1.0));
    }
    result.figures.push_back({"wall shear stress / analytic (mean of " + std::to_string(plates.size()) + " points)",
                              shear / exactShear, 1.0, 0.05, ""});
    result.figures.push_back({"worst point's wall shear stress error", worstShear, 0.0, 0.05, ""});
    result.description += " (" + std::to_string(count) + " particles, " + std::to_string(long(run.metrics.at("steps"))) +
                          " steps; largest particle error " + numberText(100.0 * worst) + " % of the peak)";
    return result;
}

} // namespace vsim::sim::sph::detail
