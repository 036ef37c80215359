#pragma once

// Vortex particles (thesis 7.2.3, after Selle, Rasmussen & Fedkiw 2005): particles that carry vorticity through
// the flow, so that swirls the grid smooths away live on. Each particle is seeded with the grid's vorticity where
// it is born, moves with the grid velocity (eq. 7.18); each step its vorticity starts from the grid's at its place
// (the thesis: "the velocity field obtained from the grid-based method was used to compute the initial vorticities
// of the vortex particles at the beginning of each time step") and is stretched by the velocity gradient (eq. 7.19),
// and at each step it pushes the grid within a control radius r: at a cell a distance d away the particle's
// vorticity weighs w_a = w_p exp(-d^2 / 2 r^2) (the clamped Gaussian of eq. 7.20 scaled to 1 at the particle), and
// the force f = epsilon h (N x w_a) with N the unit vector from the cell towards the particle, the confinement
// force of a vortex centred on the particle (eqs. 7.21 - 7.23). The printed eq. 7.23 points N away from the
// particle, which would spin the flow against the particle's vorticity and damp it; the printed eq. 7.22 also
// carries a factor |w_p| |u . w_a| whose units are not those of an acceleration: both are left out here.
// Particles that leave the domain, enter a solid or a vent, or are sucked into a suction port are removed.

#include "vsim/sim/smoke/SmokeGrid.h"

#include <Eigen/Core>

#include <random>
#include <vector>

namespace vsim::sim::smoke {

struct VortexParticle
{
    Eigen::Vector3d position;  ///< m
    Eigen::Vector3d vorticity; ///< 1/s
};

class VortexParticles
{
public:
    /// Adds `count` particles uniformly inside the sphere (centre, radius; m), each with the grid's vorticity
    /// where it lands (vorticityAt); a place in a solid is skipped.
    void seed(const SmokeGrid& grid, const Eigen::Vector3d& centre, double radius, int count, std::mt19937& random)
    {
        seedAt(grid, places(centre, radius, count, random));
    }
    /// `count` places drawn uniformly inside the sphere (centre, radius; m).
    static std::vector<Eigen::Vector3d> places(const Eigen::Vector3d& centre, double radius, int count,
                                               std::mt19937& random);
    /// Adds a particle at each place that lies in a fluid cell, with the grid's vorticity there.
    void seedAt(const SmokeGrid& grid, const std::vector<Eigen::Vector3d>& places);
    void add(const VortexParticle& particle) { m_particles.push_back(particle); }
    /// Replaces every particle (a device backend's moved and stretched ones).
    void replace(std::vector<VortexParticle> particles) { m_particles = std::move(particles); }

    /// Moves every particle with the grid velocity over dt (midpoint rule) and stretches its vorticity,
    /// w += dt (w . grad) u; removes those outside the domain, in a solid or a vent, or whose vorticity is not
    /// finite.
    void advance(const SmokeGrid& grid, double dt);

    /// Removes the particles within `radius` of `centre` (m): those a suction port takes out with the gas.
    void removeWithin(const Eigen::Vector3d& centre, double radius);

    /// Adds every particle's forcing within `radius` (m) to `force` (m/s^2 at the cell centres); epsilon is
    /// dimensionless.
    void accumulateForcing(const SmokeGrid& grid, double epsilon, double radius, std::vector<Eigen::Vector3f>& force) const;

    /// The vorticity of the grid's velocity at x (1/s): central differences of the interpolated velocity, h/2 apart.
    static Eigen::Vector3d vorticityAt(const SmokeGrid& grid, const Eigen::Vector3d& x);

    const std::vector<VortexParticle>& particles() const { return m_particles; }
    std::size_t size() const { return m_particles.size(); }

private:
    std::vector<VortexParticle> m_particles;
};

} // namespace vsim::sim::smoke
