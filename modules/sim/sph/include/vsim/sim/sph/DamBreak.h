#pragma once

// The 3D dam break of SPHERIC benchmark 2 (Kleefsman et al. 2005, J. Comput. Phys. 206: 363-393; DualSPHysics'
// speed case): a tank 3.22 x 1.0 x 1.0 m with a water column 1.228 x 1.0 x 0.55 m at its far end (x from 1.992 to
// 3.22 m), gravity -z, and, for the validation, the experiment's box obstacle (0.161 x 0.403 x 0.161 m on the floor,
// x from 0.6635 to 0.8245 m, centred across the tank). Particles on a lattice of `spacingMm`, the tank's floor and
// walls as four layers of wall particles with their depths, the obstacle filled with wall particles (their depth
// the distance to its nearest face), the water at its hydrostatic pressure. The speed benchmarks run it without
// the obstacle (as DualSPHysics' speed case does); DamBreakProbes.h reads the experiment's water heights.

#include "vsim/core/Parameters.h"
#include "vsim/core/ParticleSet.h"

#include <cstddef>

namespace vsim::sim::sph {

/// The particles (mm, tank corner at the origin, z up) with the fields "wall", "wall_depth_mm" and "pressure_pa"
/// for SphSolver's input "particles"; with `obstacle`, the experiment's box.
ParticleSet damBreakParticles(double spacingMm, bool obstacle = false);

/// The obstacle's extent (m): x, y and z from the first to the second corner.
constexpr double kDamBreakObstacleM[2][3] = {{0.6635, 0.2985, 0.0}, {0.8245, 0.7015, 0.161}};

/// The water column's height (m).
constexpr double kDamBreakWaterHeightM = 0.55;

/// The dam break at about `particles` particles in all, walls included (the speed benchmarks' size).
struct DamBreakCase
{
    double spacingMm = 0.0;
    ParticleSet particles;
    std::size_t wallParticles = 0;
};
DamBreakCase damBreakCase(double particles, bool obstacle = false);

/// SphSolver's parameters for the dam break at `spacingMm`: water (1000 kg/m^3, 1 mPa s), gravity 9.81 m/s^2 along -z,
/// a free surface, the sound speed `soundSpeedFactor` sqrt(g H) (10: about 1 % density variation; DualSPHysics'
/// CoefSound is 20), run to `endTimeS`.
ParameterSet damBreakParameters(double spacingMm, double soundSpeedFactor = 10.0, double endTimeS = 10.0);

} // namespace vsim::sim::sph
