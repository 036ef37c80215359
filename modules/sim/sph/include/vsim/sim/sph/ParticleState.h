#pragma once

// The SPH solver's particles, structure of arrays in SI (m, m/s, kg/m^3, kg) so that the CPU loops and the
// GPU copies stay contiguous. Wall particles (the dynamic boundary: frozen, their density evolving with the
// fluid's) carry wall = 1. `id` is each particle's number at the start: frames and tracking follow it through
// the reordering.

#include "vsim/sim/sph/NeighbourGrid.h"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace vsim::sim::sph {

struct ParticleState
{
    std::vector<Eigen::Vector3d> position, velocity;
    std::vector<double> density, mass;
    std::vector<double> voidFraction; ///< s of the mixture particle (FluidModel.h); walls: the fluid's default
    std::vector<std::uint8_t> wall;
    /// Wall particles: how deep below the wall's surface they sit (m; the first layer half a spacing), for the
    /// no-slip velocity (SphRates.h); < 0 when unknown (the plain dynamic boundary then). Fluid particles: unused.
    std::vector<double> wallDepth;
    std::vector<int> id;

    std::size_t size() const { return position.size(); }
    /// Appends a particle at rest.
    void add(const Eigen::Vector3d& positionM, double densityKgM3, double massKg, bool isWall, double wallDepthM = -1.0,
             double voidFraction = 0.0);
    /// Puts every array in the grid's sorted order (the grid built on `position`).
    void reorder(const NeighbourGrid& grid);
};

} // namespace vsim::sim::sph
