#include "vsim/sim/smoke/SmokeSimulation.h"

#include "vsim/sim/smoke/SmokeForces.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vsim::sim::smoke {
namespace {

bool finite(const std::vector<float>& values)
{
    return std::all_of(values.begin(), values.end(), [](float v) { return std::isfinite(v); });
}

} // namespace

SmokeSimulation::SmokeSimulation(SmokeGrid grid, const SmokeSettings& settings)
    : m_grid(std::move(grid)), m_settings(settings), m_staticSolid(m_grid.solid), m_random(settings.seed)
{
    m_projection.prepare(m_grid);
}

void SmokeSimulation::setSphere(const MovingSphere& sphere)
{
    m_sphere = sphere;
    placeSphere();
}

void SmokeSimulation::placeSphere()
{
    std::vector<std::uint8_t> solid = m_staticSolid;
    std::fill(m_grid.solidVelocity.begin(), m_grid.solidVelocity.end(), Eigen::Vector3f::Zero());
    if (m_sphere)
        for (int k = 0; k < m_grid.nz; ++k)
            for (int j = 0; j < m_grid.ny; ++j)
                for (int i = 0; i < m_grid.nx; ++i)
                    if ((m_grid.centre(i, j, k) - m_sphere->centre).norm() <= m_sphere->radius)
                    {
                        const std::size_t c = m_grid.cell(i, j, k);
                        solid[c] = 1;
                        m_grid.solidVelocity[c] = m_sphere->velocity.cast<float>();
                    }
    if (solid != m_grid.solid)
    {
        m_grid.solid = std::move(solid);
        m_projection.prepare(m_grid);
    }
    for (std::size_t c = 0; c < m_grid.cells(); ++c)
        if (m_grid.solid[c])
            m_grid.density[c] = 0.0f, m_grid.temperature[c] = 0.0f;
}

void SmokeSimulation::seedParticles(const Eigen::Vector3d& centre, double radius, int count)
{
    m_particles.seed(m_grid, cellVorticity(m_grid), centre, radius, count, m_random);
}

double SmokeSimulation::stableStep(double maxDt) const
{
    double speed = m_grid.maxSpeed();
    for (const SmokeSource& source : m_sources)
        speed = std::max(speed, source.velocity.norm());
    if (m_sphere)
        speed = std::max(speed, m_sphere->velocity.norm());
    return speed > 0.0 ? std::min(maxDt, m_settings.cfl * m_grid.h / speed) : maxDt;
}

ProjectionReport SmokeSimulation::project()
{
    return m_projection.project(m_grid, m_settings.tolerance, m_settings.maxIterations);
}

void SmokeSimulation::applySources(double dt)
{
    std::vector<Eigen::Vector3f> push(m_grid.cells(), Eigen::Vector3f::Zero());
    bool pushed = false;
    for (const SmokeSource& source : m_sources)
    {
        if (m_time < source.onsetS || m_time >= source.endS)
            continue;
        for (int k = 0; k < m_grid.nz; ++k)
            for (int j = 0; j < m_grid.ny; ++j)
                for (int i = 0; i < m_grid.nx; ++i)
                {
                    const std::size_t c = m_grid.cell(i, j, k);
                    if (m_grid.solid[c] || (m_grid.centre(i, j, k) - source.centre).norm() > source.radius)
                        continue;
                    m_grid.density[c] += float(source.densityRate * dt);
                    m_grid.temperature[c] = std::max(m_grid.temperature[c], float(source.temperatureK));
                    // The source sets its velocity: the acceleration that brings the cell there in this step.
                    push[c] = ((source.velocity - m_grid.cellVelocity(i, j, k)) / dt).cast<float>();
                    pushed = true;
                }
        m_particleDebt += source.particlesPerSecond * dt;
        const int born = int(m_particleDebt);
        if (born > 0)
        {
            m_particleDebt -= born;
            m_particles.seed(m_grid, cellVorticity(m_grid), source.centre, source.radius, born, m_random);
        }
    }
    if (pushed)
        addCellForces(m_grid, push, dt);
}

SmokeStepReport SmokeSimulation::step(double dt)
{
    SmokeStepReport report;
    report.dt = dt;
    applySources(dt);
    advect(m_grid, dt, m_settings.scheme, m_settings.scalarScheme);
    if (m_settings.coolingPerS > 0.0)
    {
        const float keep = float(std::exp(-m_settings.coolingPerS * dt));
        for (float& t : m_grid.temperature)
            t *= keep;
    }
    addBuoyancy(m_grid, dt, m_settings.buoyancyAlpha, m_settings.buoyancyBeta);
    addVorticityConfinement(m_grid, dt, m_settings.confinement);
    m_particles.applyForcing(m_grid, dt, m_settings.particleStrength, m_settings.particleRadius);
    if (m_sphere)
    {
        if (m_sphere->falls)
            m_sphere->velocity.z() -= kGravity * dt;
        m_sphere->centre += dt * m_sphere->velocity;
        placeSphere();
    }
    report.projection = project();
    m_particles.advance(m_grid, dt);
    m_time += dt;
    report.time = m_time;
    report.particles = m_particles.size();
    report.cfl = m_grid.maxSpeed() * dt / m_grid.h;
    for (const std::vector<float>* field : {&m_grid.u, &m_grid.v, &m_grid.w, &m_grid.density, &m_grid.temperature})
        if (!finite(*field))
        {
            report.guard = "the flow is no longer finite at t = " + std::to_string(m_time) + " s";
            return report;
        }
    if (report.cfl > m_settings.cflGuard)
    {
        char text[160];
        std::snprintf(text, sizeof text,
                      "the flow crossed %.1f cells in one step at t = %.3f s (the limit is %.1f): the run is unstable "
                      "(too strong a confinement or vortex forcing, or too long a step)",
                      report.cfl, m_time, m_settings.cflGuard);
        report.guard = text;
    }
    return report;
}

} // namespace vsim::sim::smoke
