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
    return grid.inside(i, j, k) && !grid.isSolid(i, j, k);
}

/// The curl field sampled at x, trilinear over the cell centres (the edge cells beyond the domain).
Eigen::Vector3d curlAt(const SmokeGrid& grid, const std::vector<Eigen::Vector3f>& curl, const Eigen::Vector3d& x)
{
    const Eigen::Vector3d p = (x - grid.origin) / grid.h - Eigen::Vector3d(0.5, 0.5, 0.5);
    const int n[3] = {grid.nx, grid.ny, grid.nz};
    int lo[3];
    double t[3];
    for (int axis = 0; axis < 3; ++axis)
    {
        const double clamped = std::clamp(p[axis], 0.0, double(n[axis] - 1));
        lo[axis] = std::min(int(clamped), std::max(n[axis] - 2, 0));
        t[axis] = clamped - lo[axis];
    }
    Eigen::Vector3d value = Eigen::Vector3d::Zero();
    for (int corner = 0; corner < 8; ++corner)
    {
        double weight = 1.0;
        int at[3];
        for (int axis = 0; axis < 3; ++axis)
        {
            const int up = (corner >> axis) & 1;
            at[axis] = std::min(lo[axis] + up, n[axis] - 1);
            weight *= up ? t[axis] : 1.0 - t[axis];
        }
        value += weight * curl[grid.cell(at[0], at[1], at[2])].cast<double>();
    }
    return value;
}

} // namespace

void VortexParticles::seed(const SmokeGrid& grid, const std::vector<Eigen::Vector3f>& curl, const Eigen::Vector3d& centre,
                           double radius, int count, std::mt19937& random)
{
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int n = 0; n < count; ++n)
    {
        Eigen::Vector3d offset;
        do
            offset = Eigen::Vector3d(unit(random), unit(random), unit(random));
        while (offset.squaredNorm() > 1.0);
        const Eigen::Vector3d x = centre + radius * offset;
        if (insideFluid(grid, x))
            m_particles.push_back({x, curlAt(grid, curl, x)});
    }
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
        particle.vorticity += dt * stretch;
        const Eigen::Vector3d middle = particle.position + 0.5 * dt * grid.velocityAt(particle.position);
        particle.position += dt * grid.velocityAt(middle);
    }
    m_particles.erase(std::remove_if(m_particles.begin(), m_particles.end(),
                                     [&](const VortexParticle& p) {
                                         return !p.vorticity.allFinite() || !insideFluid(grid, p.position);
                                     }),
                      m_particles.end());
}

void VortexParticles::applyForcing(SmokeGrid& grid, double dt, double epsilon, double radius) const
{
    if (m_particles.empty() || epsilon <= 0.0 || radius <= 0.0)
        return;
    std::vector<Eigen::Vector3f> force(grid.cells(), Eigen::Vector3f::Zero());
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
    addCellForces(grid, force, dt);
}

} // namespace vsim::sim::smoke
