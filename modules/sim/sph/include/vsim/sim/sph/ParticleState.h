#pragma once

// The SPH solver's particles, structure of arrays in SI (m, m/s, kg/m^3, kg) so that the CPU loops and the
// GPU copies stay contiguous. Wall particles (frozen, their density the fluid's pressure extrapolated: SphRates.h)
// carry wall = 1; buffer particles of the open boundaries carry their boundary's number. `id` numbers
// each particle (those given first, then those the inlets create): frames and tracking follow it through the
// reordering.

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
    /// Wall particles: the depth the through-the-wall guard measures against (m): the smaller of wallDepth and
    /// the wall's depth on its own lattice, the distance to the nearest fluid particle as seeded less half a
    /// spacing (SphSolver::setGuardDepths). On a lattice-seeded curved wall the two differ: the wall particles'
    /// staircase leaves notches between the smooth surface and the particles, which the fluid may fill without
    /// passing a wall particle. < 0 when unknown; equal to wallDepth until the solver sets it.
    std::vector<double> guardDepth;
    /// 0 in the fluid and the walls; k + 1 for a particle in the buffer of open boundary k (OpenBoundary.h).
    std::vector<std::uint8_t> boundary;
    /// 1 at particles that carry the tracer (an injected drug: what the walls absorb); 0 otherwise.
    std::vector<std::uint8_t> tracer;
    /// 1 at wall particles that push the fluid back within their reach (the walls' backstop: FluidModel.h); 0
    /// in the fluid and at the walls around an open end's buffer (SphSolver.h).
    std::vector<std::uint8_t> backstop;
    std::vector<int> id;

    std::size_t size() const { return position.size(); }
    /// Neither a wall particle nor in a buffer: the particles the solver integrates.
    bool isFluid(std::size_t i) const { return !wall[i] && !boundary[i]; }
    /// Appends a particle at rest.
    void add(const Eigen::Vector3d& positionM, double densityKgM3, double massKg, bool isWall, double wallDepthM = -1.0,
             double voidFraction = 0.0);
    /// Appends a copy of particle i at `positionM` numbered `newId`.
    void appendCopy(std::size_t i, const Eigen::Vector3d& positionM, int newId);
    /// Keeps the particles whose `keep` entry is nonzero, in their order.
    void keepOnly(const std::vector<std::uint8_t>& keep);
    /// Puts every array in the grid's sorted order (the grid built on `position`).
    void reorder(const NeighbourGrid& grid);

    /// Calls f on every per-particle array: the one list the copies, removals, reorders and checkpoints
    /// (SphCheckpoint.h) share.
    template <class F> void forEachArray(F&& f)
    {
        f(position), f(velocity), f(density), f(mass), f(voidFraction), f(wall), f(wallDepth), f(guardDepth),
            f(boundary), f(tracer), f(backstop), f(id);
    }
    template <class F> void forEachArray(F&& f) const
    {
        const_cast<ParticleState*>(this)->forEachArray([&f](const auto& array) { f(array); });
    }
};

} // namespace vsim::sim::sph
