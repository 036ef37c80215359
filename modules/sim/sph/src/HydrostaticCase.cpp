// sph-hydrostatic: water at rest in an open tank under gravity (issue 18), and the same tank of two-phase mixture
// particles at void fraction 0.2 (thesis Table 5.1). A column of fluid particles on a 1 mm lattice, 8 x 8 across and
// 16 deep, in a tank of four layers of wall particles (their pressure the fluid's, extrapolated: SphRates.h), started
// from the hydrostatic density and let settle on the run driver with a damping viscosity. The
// pressure of the particles in the middle of the column, from 2h below the surface to the bottom, against
// rho0 g d, d their depth below the settled free surface (the top layer's mean height plus half a spacing);
// rho0 g d is taken with the density the equation of state gives at each depth (dp/dd = rho(p) g integrated
// exactly: 0.5 % above rho0 g d at the bottom for this sound speed).

#include "SphCases.h"

#include "vsim/core/Error.h"
#include "vsim/core/StoredText.h"
#include "vsim/sim/common/RunDriver.h"
#include "vsim/sim/sph/SphSolver.h"

#include <algorithm>
#include <cmath>

namespace vsim::sim::sph::detail {
namespace {

// The walls as deep as the support (2h = 4 spacings); 8 across keeps the middle column's support off the side walls
// (6 across: 0.3 % higher pressures, over the 2 % tolerance at void fraction 0.2).
constexpr int kAcross = 8, kDeep = 16, kWallLayers = 4;
constexpr double kSpacingMm = 1.0, kGravity = 9.81, kDensity = 1000.0;

/// The tank and its water (mm, z up), each fluid particle at its hydrostatic pressure, each wall particle at
/// the pressure of its depth below the surface.
ParticleSet tank(double densityKgM3)
{
    ParticleSet set;
    auto& wall = set.fields["wall"];
    auto& pressure = set.fields["pressure_pa"];
    const double surfaceMm = kDeep * kSpacingMm;
    for (int k = -kWallLayers; k < kDeep + 1; ++k)
        for (int j = -kWallLayers; j < kAcross + kWallLayers; ++j)
            for (int i = -kWallLayers; i < kAcross + kWallLayers; ++i)
            {
                const bool inside = i >= 0 && j >= 0 && i < kAcross && j < kAcross && k >= 0;
                if (inside && k >= kDeep)
                    continue; // the air above the water
                const Eigen::Vector3d x = kSpacingMm * Eigen::Vector3d(i + 0.5, j + 0.5, k + 0.5);
                set.positionsMm.push_back(x);
                wall.push_back(inside ? 0.0 : 1.0);
                pressure.push_back(densityKgM3 * kGravity * std::max(0.0, surfaceMm - x.z()) * 1e-3);
            }
    return set;
}


struct ColumnErrors
{
    double bottomRatio = 0.0, rms = 0.0, worst = 0.0, settled = 0.0;
    int compared = 0;
    long steps = 0;
};

/// The tank of mixture particles at `voidFraction` settled for 0.3 s; the middle column's pressure against the
/// model's own hydrostatics: dp/dd = rho(p) g with Tait's rho(p) about rho0(s), integrated exactly.
ColumnErrors settledColumn(double voidFraction, const Progress& progress)
{
    const double depthM = kDeep * kSpacingMm * 1e-3;
    // The viscosity damps the settling sloshes within the run (it does nothing at rest): 2 Pa s settles the tank to
    // 0.07 % of sqrt(g H) by 0.3 s with the extrapolated wall pressure (0.5 Pa s left it at 1.3 %, still moving).
    ParameterSet parameters = caseParameters(kSpacingMm, kDensity, 2.0, 10.0 * std::sqrt(kGravity * depthM));
    parameters.set("gravity_z_m_s2", -kGravity);
    parameters.set("end_time_s", 0.3);
    parameters.set("void_fraction", voidFraction);
    parameters.set("free_surface", 1);
    FluidModel mixture;
    mixture.restDensity = kDensity;
    SphSolver solver;
    const SolverRun run = runCase("sph-hydrostatic at void fraction " + numberText(voidFraction), solver,
                                  tank(mixture.mixtureDensity(voidFraction)), parameters, progress);
    const FluidModel& fluid = solver.fluid();
    const double density = fluid.mixtureDensity(voidFraction), b = fluid.stiffness(voidFraction), gamma = fluid.gamma;

    const ParticleState& particles = solver.particles();
    const std::vector<double> pressure = solver.pressure();
    double topSum = 0.0, highest = -INFINITY;
    int topCount = 0;
    for (std::size_t i = 0; i < particles.size(); ++i)
        if (!particles.wall[i])
            highest = std::max(highest, particles.position[i].z());
    for (std::size_t i = 0; i < particles.size(); ++i)
        if (!particles.wall[i] && particles.position[i].z() > highest - 0.5 * kSpacingMm * 1e-3)
            topSum += particles.position[i].z(), ++topCount;
    const double surface = topSum / topCount + 0.5 * kSpacingMm * 1e-3;
    const double centre = 0.5 * kAcross * kSpacingMm * 1e-3, h = solver.kernel().smoothingLength();
    ColumnErrors errors;
    double squares = 0.0, bottomDepth = 0.0;
    for (std::size_t i = 0; i < particles.size(); ++i)
    {
        const Eigen::Vector3d& x = particles.position[i];
        const double depth = surface - x.z();
        if (particles.wall[i] || std::max(std::abs(x.x() - centre), std::abs(x.y() - centre)) > kSpacingMm * 1e-3 ||
            depth < 2.0 * h)
            continue;
        const double expected =
            b * (std::pow(1.0 + (gamma - 1.0) / gamma * density * kGravity * depth / b, gamma / (gamma - 1.0)) - 1.0);
        const double error = (pressure[i] - expected) / expected;
        errors.worst = std::max(errors.worst, std::abs(error));
        squares += error * error, ++errors.compared;
        if (depth > bottomDepth)
            bottomDepth = depth, errors.bottomRatio = pressure[i] / expected;
    }
    errors.rms = std::sqrt(squares / std::max(1, errors.compared));
    errors.settled = run.metrics.at("largest_speed_m_s") / std::sqrt(kGravity * depthM);
    errors.steps = long(run.metrics.at("steps"));
    return errors;
}

} // namespace

ValidationResult hydrostaticCase(const Progress& progress)
{
    ValidationResult result;
    result.name = "sph-hydrostatic";
    result.description = storedText("water at rest in an open tank (8 x 8 x 16 particles of 1 mm, 4 wall layers) after "
                                    "0.3 s under gravity, and the same tank of mixture particles at void fraction 0.2 "
                                    "(thesis Table 5.1): the pressure in the middle of the column, 2h below the surface "
                                    "and deeper, against the hydrostatic pressure of the model's fluid");
    const ColumnErrors water = settledColumn(0.0, progress.subRange(0.0, 0.5));
    const ColumnErrors mixture = settledColumn(0.2, progress.subRange(0.5, 1.0));
    for (const auto& [label, errors] : {std::pair{"", water}, std::pair{"void 0.2: ", mixture}})
    {
        const std::string prefix = label;
        result.figures.push_back({prefix + "pressure at the deepest middle particle / hydrostatic", errors.bottomRatio, 1.0, 0.02, ""});
        result.figures.push_back({prefix + "RMS relative pressure error over the middle column", errors.rms, 0.0, 0.02, ""});
        result.figures.push_back({prefix + "largest relative pressure error over the middle column", errors.worst, 0.0, 0.02, ""});
        result.figures.push_back({prefix + "largest speed / sqrt(g H) (settled)", errors.settled, 0.0, 0.01, ""});
    }
    result.description += " (" + std::to_string(water.compared) + " particles compared, " +
                          std::to_string(water.steps) + " and " + std::to_string(mixture.steps) + " steps)";
    return result;
}

} // namespace vsim::sim::sph::detail
