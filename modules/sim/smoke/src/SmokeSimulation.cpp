#include "vsim/sim/smoke/SmokeSimulation.h"

#include "vsim/core/Error.h"
#include "vsim/sim/smoke/SmokeForces.h"

#include <algorithm>
#include <chrono>
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

void SmokeSimulation::setSuction(const SmokeSuction& suction)
{
    if (m_projection.multigrid().singular())
        throw Error("a suction needs a vent or an open face for the gas it takes out to be replaced");
    std::vector<std::size_t> cells;
    for (int k = 0; k < m_grid.nz; ++k)
        for (int j = 0; j < m_grid.ny; ++j)
            for (int i = 0; i < m_grid.nx; ++i)
                if (m_grid.isFluid(m_grid.cell(i, j, k)) && (m_grid.centre(i, j, k) - suction.centre).norm() <= suction.radius)
                    cells.push_back(m_grid.cell(i, j, k));
    if (cells.empty())
        throw Error("the suction port has no fluid cell within its radius");
    m_suction = suction;
    m_sink.assign(m_grid.cells(), 0.0f);
    const double perCell = suction.flowM3S / (double(cells.size()) * m_grid.h * m_grid.h * m_grid.h);
    for (std::size_t c : cells)
        m_sink[c] = float(-perCell);
}

void SmokeSimulation::seedParticles(const Eigen::Vector3d& centre, double radius, int count)
{
    m_particles.seed(m_grid, centre, radius, count, m_random);
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
    const bool sucking = m_suction && m_time >= m_suction->onS && m_time < m_suction->offS;
    return m_projection.project(m_grid, m_settings.tolerance, m_settings.maxIterations, sucking ? &m_sink : nullptr);
}

void SmokeSimulation::applySources(double dt, bool setVelocity)
{
    for (const SmokeSource& source : m_sources)
    {
        if (m_time < source.onsetS || m_time >= source.endS)
            continue;
        // The cells whose centres lie in the source's sphere (its bounding box searched).
        const Eigen::Vector3d low = (source.centre - m_grid.origin) / m_grid.h - Eigen::Vector3d::Constant(source.radius / m_grid.h + 1.0);
        const Eigen::Vector3d high = (source.centre - m_grid.origin) / m_grid.h + Eigen::Vector3d::Constant(source.radius / m_grid.h + 1.0);
        for (int k = std::max(0, int(low.z())); k <= std::min(m_grid.nz - 1, int(high.z())); ++k)
            for (int j = std::max(0, int(low.y())); j <= std::min(m_grid.ny - 1, int(high.y())); ++j)
                for (int i = std::max(0, int(low.x())); i <= std::min(m_grid.nx - 1, int(high.x())); ++i)
                {
                    const std::size_t c = m_grid.cell(i, j, k);
                    if (m_grid.solid[c] || (m_grid.centre(i, j, k) - source.centre).norm() > source.radius)
                        continue;
                    if (setVelocity)
                    {
                        // The source sets its velocity on the faces of its cells (before the projection, which
                        // makes the flow around it divergence-free).
                        m_grid.u[m_grid.uFace(i, j, k)] = m_grid.u[m_grid.uFace(i + 1, j, k)] = float(source.velocity.x());
                        m_grid.v[m_grid.vFace(i, j, k)] = m_grid.v[m_grid.vFace(i, j + 1, k)] = float(source.velocity.y());
                        m_grid.w[m_grid.wFace(i, j, k)] = m_grid.w[m_grid.wFace(i, j, k + 1)] = float(source.velocity.z());
                        continue;
                    }
                    m_grid.density[c] += float(source.densityRate * dt);
                    m_grid.temperature[c] = std::max(m_grid.temperature[c], float(source.temperatureK));
                }
        if (setVelocity)
            continue;
        m_particleDebt += source.particlesPerSecond * dt;
        const int born = int(m_particleDebt);
        if (born > 0)
        {
            m_particleDebt -= born;
            m_particles.seed(m_grid, source.centre, source.radius, born, m_random);
        }
    }
}

SmokeStepReport SmokeSimulation::step(double dt)
{
    SmokeStepReport report;
    report.dt = dt;
    using Clock = std::chrono::steady_clock;
    const auto seconds = [](Clock::time_point from) { return std::chrono::duration<double>(Clock::now() - from).count(); };
    auto started = Clock::now();
    applySources(dt, false);
    advect(m_grid, dt, m_settings.scheme, m_settings.scalarScheme, m_steps % 2 == 1);
    report.advectionSeconds = seconds(started);
    started = Clock::now();
    if (m_settings.coolingPerS > 0.0)
    {
        const float keep = float(std::exp(-m_settings.coolingPerS * dt));
        for (float& t : m_grid.temperature)
            t *= keep;
    }
    addBuoyancy(m_grid, dt, m_settings.buoyancyAlpha, m_settings.buoyancyBeta, m_settings.up);
    if (m_settings.confinement > 0.0 || (m_settings.particleStrength > 0.0 && m_particles.size() > 0))
    {
        m_force.assign(m_grid.cells(), Eigen::Vector3f::Zero());
        accumulateVorticityConfinement(m_grid, m_settings.confinement, m_force);
        m_particles.accumulateForcing(m_grid, m_settings.particleStrength, m_settings.particleRadius, m_force);
        addCellForces(m_grid, m_force, dt);
    }
    if (m_sphere)
    {
        if (m_sphere->falls)
            m_sphere->velocity -= kGravity * dt * m_settings.up;
        m_sphere->centre += dt * m_sphere->velocity;
        // The domain's walls stop it (it comes to rest on the floor: no bounce).
        const Eigen::Vector3d low = m_grid.origin + Eigen::Vector3d::Constant(m_sphere->radius);
        const Eigen::Vector3d high =
            m_grid.origin + m_grid.h * Eigen::Vector3d(m_grid.nx, m_grid.ny, m_grid.nz) - Eigen::Vector3d::Constant(m_sphere->radius);
        const Eigen::Vector3d inside = m_sphere->centre.cwiseMax(low).cwiseMin(high);
        if (inside != m_sphere->centre)
        {
            m_sphere->centre = inside;
            m_sphere->velocity.setZero();
            m_sphere->falls = false;
        }
        placeSphere();
    }
    applySources(dt, true);
    report.forceSeconds = seconds(started);
    started = Clock::now();
    report.projection = project();
    report.projectionSeconds = seconds(started);
    started = Clock::now();
    m_particles.advance(m_grid, dt);
    if (m_suction && m_time >= m_suction->onS && m_time < m_suction->offS)
        m_particles.removeWithin(m_suction->centre, m_suction->radius);
    report.particleSeconds = seconds(started);
    m_time += dt;
    ++m_steps;
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
