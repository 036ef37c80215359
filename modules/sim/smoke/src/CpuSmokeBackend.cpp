#include "vsim/sim/smoke/SmokeBackend.h"

#include "vsim/sim/smoke/SmokeForces.h"
#include "vsim/sim/smoke/SmokeSimulation.h"

#include <algorithm>
#include <cmath>

namespace vsim::sim::smoke {

void CpuSmokeBackend::applySource(SmokeGrid& grid, const SmokeSource& source, double dt, bool setVelocity)
{
    // The cells whose centres lie in the source's sphere (its bounding box searched).
    const Eigen::Vector3d reach = Eigen::Vector3d::Constant(source.radius / grid.h + 1.0);
    const Eigen::Vector3d low = (source.centre - grid.origin) / grid.h - reach;
    const Eigen::Vector3d high = (source.centre - grid.origin) / grid.h + reach;
    for (int k = std::max(0, int(low.z())); k <= std::min(grid.nz - 1, int(high.z())); ++k)
        for (int j = std::max(0, int(low.y())); j <= std::min(grid.ny - 1, int(high.y())); ++j)
            for (int i = std::max(0, int(low.x())); i <= std::min(grid.nx - 1, int(high.x())); ++i)
            {
                const std::size_t c = grid.cell(i, j, k);
                if (grid.solid[c] || (grid.centre(i, j, k) - source.centre).norm() > source.radius)
                    continue;
                if (setVelocity)
                {
                    // The source sets its velocity on the faces of its cells (before the projection, which makes
                    // the flow around it divergence-free).
                    grid.u[grid.uFace(i, j, k)] = grid.u[grid.uFace(i + 1, j, k)] = float(source.velocity.x());
                    grid.v[grid.vFace(i, j, k)] = grid.v[grid.vFace(i, j + 1, k)] = float(source.velocity.y());
                    grid.w[grid.wFace(i, j, k)] = grid.w[grid.wFace(i, j, k + 1)] = float(source.velocity.z());
                    continue;
                }
                grid.density[c] += float(source.densityRate * dt);
                grid.temperature[c] = std::max(grid.temperature[c], float(source.temperatureK));
            }
}

void CpuSmokeBackend::advect(SmokeGrid& grid, double dt, const SmokeSettings& settings, bool reverseSweeps)
{
    smoke::advect(grid, dt, settings.scheme, settings.scalarScheme, reverseSweeps);
}

void CpuSmokeBackend::addHeatForces(SmokeGrid& grid, double dt, const SmokeSettings& settings)
{
    if (settings.coolingPerS > 0.0)
    {
        const float keep = float(std::exp(-settings.coolingPerS * dt));
        for (float& t : grid.temperature)
            t *= keep;
    }
    addBuoyancy(grid, dt, settings.buoyancyAlpha, settings.buoyancyBeta, settings.up);
}

void CpuSmokeBackend::addVortexForces(SmokeGrid& grid, double dt, const SmokeSettings& settings,
                                      const VortexParticles& particles)
{
    m_force.assign(grid.cells(), Eigen::Vector3f::Zero());
    accumulateVorticityConfinement(grid, settings.confinement, m_force);
    particles.accumulateForcing(grid, settings.particleStrength, settings.particleRadius, m_force);
    addCellForces(grid, m_force, dt);
}

void CpuSmokeBackend::placeSolids(SmokeGrid& grid, const std::vector<std::uint8_t>& staticSolid,
                                  const MovingSphere* sphere)
{
    std::vector<std::uint8_t> solid = staticSolid;
    std::fill(grid.solidVelocity.begin(), grid.solidVelocity.end(), Eigen::Vector3f::Zero());
    if (sphere)
        for (int k = 0; k < grid.nz; ++k)
            for (int j = 0; j < grid.ny; ++j)
                for (int i = 0; i < grid.nx; ++i)
                    if ((grid.centre(i, j, k) - sphere->centre).norm() <= sphere->radius)
                    {
                        const std::size_t c = grid.cell(i, j, k);
                        solid[c] = kSolid;
                        grid.solidVelocity[c] = sphere->velocity.cast<float>();
                    }
    if (solid != grid.solid || !m_prepared)
    {
        grid.solid = std::move(solid);
        m_projection.prepare(grid);
        m_prepared = true;
    }
    for (std::size_t c = 0; c < grid.cells(); ++c)
        if (grid.solid[c])
            grid.density[c] = 0.0f, grid.temperature[c] = 0.0f;
}

ProjectionReport CpuSmokeBackend::project(SmokeGrid& grid, double tolerance, int maxIterations, bool withSink, double stepS)
{
    if (!m_prepared)
    {
        m_projection.prepare(grid);
        m_prepared = true;
    }
    return m_projection.project(grid, tolerance, maxIterations, withSink ? &m_sink : nullptr, stepS);
}

void CpuSmokeBackend::advanceParticles(const SmokeGrid& grid, VortexParticles& particles, double dt)
{
    particles.advance(grid, dt);
}

void CpuSmokeBackend::seedParticles(const SmokeGrid& grid, VortexParticles& particles,
                                    const std::vector<Eigen::Vector3d>& places)
{
    particles.seedAt(grid, places);
}

bool CpuSmokeBackend::finite(const SmokeGrid& grid)
{
    for (const std::vector<float>* field : {&grid.u, &grid.v, &grid.w, &grid.density, &grid.temperature})
        if (!std::all_of(field->begin(), field->end(), [](float v) { return std::isfinite(v); }))
            return false;
    return true;
}

} // namespace vsim::sim::smoke
