#include "vsim/sim/sph/DamBreak.h"

#include "vsim/core/Error.h"
#include "vsim/sim/sph/SphSolver.h"

#include <algorithm>
#include <cmath>

namespace vsim::sim::sph {

namespace {

/// How deep inside the obstacle `xMm` lies (mm; <= 0 outside): the distance to its nearest face (its floor side
/// is the tank's).
double obstacleDepthMm(const Eigen::Vector3d& xMm)
{
    double depth = 1e30;
    for (int a = 0; a < 3; ++a)
    {
        if (a < 2) // the box's floor side is the tank's floor
            depth = std::min(depth, xMm[a] - 1000.0 * kDamBreakObstacleM[0][a]);
        depth = std::min(depth, 1000.0 * kDamBreakObstacleM[1][a] - xMm[a]);
    }
    return depth;
}

} // namespace

ParticleSet damBreakParticles(double spacingMm, bool obstacle)
{
    if (!(spacingMm > 0.0))
        throw Error("the dam break needs a positive particle spacing");
    constexpr double tank[3] = {3220.0, 1000.0, 1000.0}; // mm
    constexpr double waterStart = 3220.0 - 1228.0, waterHeight = 1000.0 * kDamBreakWaterHeightM;
    constexpr int layers = 4; // the support of h = 2 spacings
    const int cells[3] = {int(std::lround(tank[0] / spacingMm)), int(std::lround(tank[1] / spacingMm)),
                          int(std::lround(tank[2] / spacingMm))};
    ParticleSet set;
    auto& wall = set.fields["wall"];
    auto& depth = set.fields["wall_depth_mm"];
    auto& pressure = set.fields["pressure_pa"];
    for (int k = -layers; k < cells[2]; ++k)
        for (int j = -layers; j < cells[1] + layers; ++j)
            for (int i = -layers; i < cells[0] + layers; ++i)
            {
                const Eigen::Vector3d x = spacingMm * Eigen::Vector3d(i + 0.5, j + 0.5, k + 0.5);
                // How far outside the tank's interior the lattice point lies, in spacings (0 inside).
                const int outside = std::max({-i, i - cells[0] + 1, -j, j - cells[1] + 1, -k, 0});
                const double inObstacle = obstacle && outside == 0 ? obstacleDepthMm(x) : 0.0;
                const bool isWall = outside > 0 || inObstacle > 0.0;
                const bool water = !isWall && x.x() >= waterStart && x.z() < waterHeight;
                if (!isWall && !water)
                    continue;
                set.positionsMm.push_back(x);
                wall.push_back(isWall ? 1.0 : 0.0);
                depth.push_back(outside > 0 ? spacingMm * (outside - 0.5) : inObstacle);
                pressure.push_back(water ? 1000.0 * 9.81 * (waterHeight - x.z()) * 1e-3 : 0.0);
            }
    return set;
}

DamBreakCase damBreakCase(double particles, bool obstacle)
{
    if (!(particles >= 1000.0))
        throw Error("the dam break needs at least 1000 particles");
    // About 1.25 wall particles per water particle at these sizes: a first spacing for the total, then one
    // correction for the walls' true share.
    const double first = 1000.0 * std::cbrt(0.6754 * 2.25 / particles);
    DamBreakCase c;
    c.spacingMm = first * std::cbrt(double(damBreakParticles(first, obstacle).size()) / particles);
    c.particles = damBreakParticles(c.spacingMm, obstacle);
    for (double w : c.particles.fields.at("wall"))
        c.wallParticles += w > 0.5;
    return c;
}

ParameterSet damBreakParameters(double spacingMm, double soundSpeedFactor, double endTimeS)
{
    ParameterSet parameters(sphParameters());
    parameters.set("spacing_mm", spacingMm);
    parameters.set("density_kg_m3", 1000.0);
    parameters.set("viscosity_pa_s", 1e-3);
    parameters.set("sound_speed_m_s", soundSpeedFactor * std::sqrt(9.81 * kDamBreakWaterHeightM));
    parameters.set("gravity_z_m_s2", -9.81);
    parameters.set("free_surface", 1);
    parameters.set("end_time_s", endTimeS);
    return parameters;
}

} // namespace vsim::sim::sph
