#pragma once

// The 3D dam break of SPHERIC benchmark 2 (Kleefsman et al. 2005; DualSPHysics' speed case): a tank 3.22 x 1.0 x
// 1.0 m with a water column 1.228 x 1.0 x 0.55 m at its far end (x from 1.992 to 3.22 m), gravity -z, here without
// the box obstacle. Particles on a lattice of `spacingMm`, the tank's floor and walls as four layers of wall
// particles with their depths, the water at its hydrostatic pressure. The speed benchmarks run it; its validation
// against the experiment's water-height probes needs the obstacle and is not here yet.

#include "vsim/core/Parameters.h"
#include "vsim/core/ParticleSet.h"

#include <cstddef>

namespace vsim::sim::sph {

/// The particles (mm, tank corner at the origin, z up) with the fields "wall", "wall_depth_mm" and "pressure_pa"
/// for SphSolver's input "particles".
ParticleSet damBreakParticles(double spacingMm);

/// The water column's height (m).
constexpr double kDamBreakWaterHeightM = 0.55;

/// The dam break at about `particles` particles in all, walls included (the speed benchmarks' size).
struct DamBreakCase
{
    double spacingMm = 0.0;
    ParticleSet particles;
    std::size_t wallParticles = 0;
};
DamBreakCase damBreakCase(double particles);

/// SphSolver's parameters for the dam break at `spacingMm`: water (1000 kg/m^3, 1 mPa s), gravity 9.81 m/s^2 along -z,
/// a free surface, the sound speed `soundSpeedFactor` sqrt(g H) (10: about 1 % density variation; DualSPHysics'
/// CoefSound is 20), run to `endTimeS`.
ParameterSet damBreakParameters(double spacingMm, double soundSpeedFactor = 10.0, double endTimeS = 10.0);

} // namespace vsim::sim::sph
