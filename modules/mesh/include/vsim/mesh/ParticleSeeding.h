#pragma once

// The blood-flow solver's particles from a segmented lumen (issue 18): fluid particles on a lattice of the given
// spacing (mm, aligned with the patient axes) at every lattice point whose nearest voxel is lumen, and wall
// particles in `wallLayers` layers outside it (the dynamic boundary, as deep as the kernel's support: 4 layers for
// h = 2 spacings), each with its depth below the lumen's surface: its distance to the nearest fluid particle less
// half a spacing (the surface lies half a spacing beyond the last fluid particle), which the solver's no-slip
// velocity needs. Where the lumen meets the image's border the wall particles close it: open ends are the inlets'
// and outlets' business.

#include "vsim/core/ImageVolume.h"
#include "vsim/core/ParticleSet.h"

#include <cstdint>

namespace vsim::mesh {

struct ParticleSeeding
{
    double spacingMm = 0.5;
    int wallLayers = 4;
    std::uint8_t lumenValue = 1;
};

/// Fields "wall" (0 fluid, 1 wall) and "wall_depth_mm" (0 in the fluid). Throws vsim::Error for a label without
/// lumen voxels, a spacing that is not positive, wall layers outside 1..8, or a lattice over kMaxLatticePoints.
ParticleSet seedVesselParticles(const LabelVolume& label, const ParticleSeeding& seeding);

inline constexpr std::size_t kMaxLatticePoints = std::size_t(1) << 30;

} // namespace vsim::mesh
