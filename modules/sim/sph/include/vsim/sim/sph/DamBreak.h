#pragma once

// The 3D dam break of SPHERIC benchmark 2 (Kleefsman et al. 2005; DualSPHysics' speed case): a tank 3.22 x 1.0 x
// 1.0 m with a water column 1.228 x 1.0 x 0.55 m at its far end (x from 1.992 to 3.22 m), gravity -z, here without
// the box obstacle. Particles on a lattice of `spacingMm`, the tank's floor and walls as four layers of wall
// particles with their depths, the water at its hydrostatic pressure. The speed benchmarks run it; its validation
// against the experiment's water-height probes needs the obstacle and is not here yet.

#include "vsim/core/ParticleSet.h"

namespace vsim::sim::sph {

/// The particles (mm, tank corner at the origin, z up) with the fields "wall", "wall_depth_mm" and "pressure_pa"
/// for SphSolver's input "particles".
ParticleSet damBreakParticles(double spacingMm);

/// The water column's height (m).
constexpr double kDamBreakWaterHeightM = 0.55;

} // namespace vsim::sim::sph
