#pragma once

// The blood-flow solver's particles from a segmented lumen (issue 18): fluid particles on a lattice of the given
// spacing (mm, aligned with the patient axes) at every lattice point whose nearest voxel is lumen, and wall
// particles in `wallLayers` layers outside it (the dynamic boundary, as deep as the kernel's support: 4 layers for
// h = 2 spacings), each with its depth below the lumen's surface: its distance to the nearest fluid particle less
// half a spacing (the surface lies half a spacing beyond the last fluid particle), which the solver's no-slip
// velocity needs. Where the lumen meets the image's border the wall particles close it, unless an open end is
// given there: an inlet's or an outlet's plane (a disk), behind which the lumen's section at the plane is extruded
// by the buffer's depth, filled with buffer particles (field "open_boundary", the end's number + 1) and walled
// around, and cut off beyond (the solver's OpenBoundary.h takes it from there).

#include "vsim/core/ImageVolume.h"
#include "vsim/core/ParticleSet.h"

#include <cstdint>
#include <vector>

namespace vsim::mesh {

/// An open vessel end: its plane's centre (mm), unit normal into the lumen, the disk's radius (mm: at least the
/// lumen's there) and the buffer's depth behind it (mm: the kernel's support, 2h).
struct OpenEnd
{
    Eigen::Vector3d centreMm = Eigen::Vector3d::Zero();
    Eigen::Vector3d normal = Eigen::Vector3d::UnitX();
    double radiusMm = 0.0;
    double bufferDepthMm = 0.0;
};

struct ParticleSeeding
{
    double spacingMm = 0.5;
    int wallLayers = 4;
    std::uint8_t lumenValue = 1;
    std::vector<OpenEnd> openEnds;
};

/// Fields "wall" (0 fluid, 1 wall), "wall_depth_mm" (0 in the fluid) and, with open ends, "open_boundary". Throws
/// vsim::Error for a label without lumen voxels, a spacing that is not positive, wall layers outside 1..8, an open
/// end without a unit normal, a positive radius and depth, or a lattice over kMaxLatticePoints.
ParticleSet seedVesselParticles(const LabelVolume& label, const ParticleSeeding& seeding);

inline constexpr std::size_t kMaxLatticePoints = std::size_t(1) << 30;

} // namespace vsim::mesh
