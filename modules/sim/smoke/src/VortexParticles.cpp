#include "vsim/sim/smoke/VortexParticles.h"

#include "vsim/sim/smoke/SmokeForces.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace vsim::sim::smoke {
namespace {

bool insideFluid(const SmokeGrid& grid, const Eigen::Vector3d& x)
{
    const Eigen::Vector3d p = (x - grid.origin) / grid.h;
    const int i = int(std::floor(p.x())), j = int(std::floor(p.y())), k = int(std::floor(p.z()));
    return grid.inside(i, j, k) && grid.isFluid(grid.cell(i, j, k)); // not in a solid, nor gone out by a vent
}

} // namespace

Eigen::Vector3d VortexParticles::vorticityAt(const SmokeGrid& grid, const Eigen::Vector3d& x)
{
    const double delta = 0.5 * grid.h;
    Eigen::Vector3d d[3]; // d[a] = du/dx_a
    for (int axis = 0; axis < 3; ++axis)
    {
        const Eigen::Vector3d step = delta * Eigen::Vector3d::Unit(axis);
        d[axis] = (grid.velocityAt(x + step) - grid.velocityAt(x - step)) / (2.0 * delta);
    }
    return {d[1].z() - d[2].y(), d[2].x() - d[0].z(), d[0].y() - d[1].x()};
}

std::vector<Eigen::Vector3d> VortexParticles::places(const Eigen::Vector3d& centre, double radius, int count,
                                                     std::mt19937& random)
{
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::vector<Eigen::Vector3d> result;
    result.reserve(std::size_t(std::max(count, 0)));
    for (int n = 0; n < count; ++n)
    {
        Eigen::Vector3d offset;
        do
            offset = Eigen::Vector3d(unit(random), unit(random), unit(random));
        while (offset.squaredNorm() > 1.0);
        result.push_back(centre + radius * offset);
    }
    return result;
}

void VortexParticles::seedAt(const SmokeGrid& grid, const std::vector<Eigen::Vector3d>& places)
{
    for (const Eigen::Vector3d& x : places)
        if (insideFluid(grid, x))
            m_particles.push_back({x, vorticityAt(grid, x)});
}

void VortexParticles::advance(const SmokeGrid& grid, double dt)
{
    const double delta = 0.5 * grid.h;
#pragma omp parallel for schedule(static)
    for (long n = 0; n < long(m_particles.size()); ++n)
    {
        VortexParticle& particle = m_particles[std::size_t(n)];
        // (w . grad) u by central differences of the interpolated velocity, at the particle's old place (eq. 7.19).
        Eigen::Vector3d stretch = Eigen::Vector3d::Zero();
        for (int axis = 0; axis < 3; ++axis)
        {
            const Eigen::Vector3d step = delta * Eigen::Vector3d::Unit(axis);
            stretch += particle.vorticity[axis] *
                       (grid.velocityAt(particle.position + step) - grid.velocityAt(particle.position - step)) / (2.0 * delta);
        }
        // Thesis 7.2.3: each step starts from the grid's vorticity at the particle ([204]), which the stretching
        // then carries on over the step; a particle's vorticity cannot run away from the flow's.
        particle.vorticity = vorticityAt(grid, particle.position) + dt * stretch;
        const Eigen::Vector3d middle = particle.position + 0.5 * dt * grid.velocityAt(particle.position);
        particle.position += dt * grid.velocityAt(middle);
    }
    m_particles.erase(std::remove_if(m_particles.begin(), m_particles.end(),
                                     [&](const VortexParticle& p) {
                                         return !p.vorticity.allFinite() || !insideFluid(grid, p.position);
                                     }),
                      m_particles.end());
}

void VortexParticles::removeWithin(const Eigen::Vector3d& centre, double radius)
{
    m_particles.erase(std::remove_if(m_particles.begin(), m_particles.end(),
                                     [&](const VortexParticle& p) { return (p.position - centre).norm() <= radius; }),
                      m_particles.end());
}

void VortexParticles::accumulateForcing(const SmokeGrid& grid, double epsilon, double radius,
                                        std::vector<Eigen::Vector3f>& force) const
{
    if (m_particles.empty() || epsilon <= 0.0 || radius <= 0.0)
        return;
    const int reach = int(std::ceil(radius / grid.h));
    const double strength = epsilon * grid.h;
    for (const VortexParticle& particle : m_particles)
    {
        const Eigen::Vector3d p = (particle.position - grid.origin) / grid.h - Eigen::Vector3d(0.5, 0.5, 0.5);
        const int ci = int(std::lround(p.x())), cj = int(std::lround(p.y())), ck = int(std::lround(p.z()));
        for (int k = ck - reach; k <= ck + reach; ++k)
            for (int j = cj - reach; j <= cj + reach; ++j)
                for (int i = ci - reach; i <= ci + reach; ++i)
                {
                    if (!grid.inside(i, j, k) || grid.isSolid(i, j, k))
                        continue;
                    const Eigen::Vector3d toParticle = particle.position - grid.centre(i, j, k);
                    const double distance = toParticle.norm();
                    if (distance > radius || distance < 1e-9 * grid.h)
                        continue;
                    const Eigen::Vector3d weighted =
                        std::exp(-distance * distance / (2.0 * radius * radius)) * particle.vorticity;
                    force[grid.cell(i, j, k)] += (strength * (toParticle / distance).cross(weighted)).cast<float>();
                }
    }
}

} // namespace vsim::sim::smoke
