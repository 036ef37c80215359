#include "vsim/sim/smoke/SmokeSimulation.h"

#include "vsim/core/Error.h"
#include "vsim/core/Parameters.h"
#include "vsim/core/StoredText.h"
#include "vsim/sim/smoke/SmokeForces.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace vsim::sim::smoke {

SmokeSimulation::SmokeSimulation(SmokeGrid grid, const SmokeSettings& settings, std::unique_ptr<SmokeBackend> backend)
    : m_grid(std::move(grid)), m_settings(settings),
      m_backend(backend ? std::move(backend) : std::make_unique<CpuSmokeBackend>()), m_staticSolid(m_grid.solid),
      m_random(settings.seed)
{
}

const SmokeGrid& SmokeSimulation::grid() const
{
    if (!m_hostCurrent)
    {
        m_backend->download(m_grid);
        m_hostCurrent = true;
    }
    return m_grid;
}

SmokeBackend& SmokeSimulation::backend()
{
    if (!m_backendCurrent)
    {
        grid(); // the host's copy first, should the backend have run before
        m_backend->upload(m_grid);
        m_backendCurrent = true;
    }
    m_hostCurrent = m_backend->onHostGrid();
    m_speed = -1.0; // the work asked for may change the velocity
    return *m_backend;
}

void SmokeSimulation::setSphere(const MovingSphere& sphere)
{
    m_sphere = sphere;
    placeSphere();
}

void SmokeSimulation::placeSphere()
{
    backend().placeSolids(m_grid, m_staticSolid, m_sphere ? &*m_sphere : nullptr);
}

void SmokeSimulation::setSuction(const SmokeSuction& suction)
{
    const SmokeGrid& grid = this->grid();
    if (PoissonMultigrid::isSingular(grid))
        throw Error("a suction needs a vent or an open face for the gas it takes out to be replaced");
    std::vector<std::size_t> cells;
    for (int k = 0; k < grid.nz; ++k)
        for (int j = 0; j < grid.ny; ++j)
            for (int i = 0; i < grid.nx; ++i)
                if (grid.isFluid(grid.cell(i, j, k)) && (grid.centre(i, j, k) - suction.centre).norm() <= suction.radius)
                    cells.push_back(grid.cell(i, j, k));
    if (cells.empty())
        throw Error("the suction port has no fluid cell within its radius");
    m_suction = suction;
    // The sink's divergence (1/s), spread evenly over the port's cells.
    std::vector<float> sink(grid.cells(), 0.0f);
    const double perCell = suction.flowM3S / (double(cells.size()) * grid.h * grid.h * grid.h);
    for (std::size_t c : cells)
        sink[c] = float(-perCell);
    backend().setSink(sink);
}

void SmokeSimulation::seedParticles(const Eigen::Vector3d& centre, double radius, int count)
{
    backend().seedParticles(m_grid, m_particles, VortexParticles::places(centre, radius, count, m_random));
}

double SmokeSimulation::stableStep(double maxDt) const
{
    double speed = m_speed >= 0.0 ? m_speed : m_hostCurrent ? m_grid.maxSpeed() : m_backend->maxSpeed(m_grid);
    for (const SmokeSource& source : m_sources)
        speed = std::max(speed, source.velocity.norm());
    if (m_sphere)
        speed = std::max(speed, m_sphere->velocity.norm());
    return speed > 0.0 ? std::min(maxDt, m_settings.cfl * m_grid.h / speed) : maxDt;
}

ProjectionReport SmokeSimulation::projectStep(double stepS)
{
    const bool sucking = m_suction && m_time >= m_suction->onS && m_time < m_suction->offS;
    return backend().project(m_grid, m_settings.tolerance, m_settings.maxIterations, sucking, stepS);
}

void SmokeSimulation::applySources(double dt, bool setVelocity)
{
    for (const SmokeSource& source : m_sources)
    {
        if (m_time < source.onsetS || m_time >= source.endS)
            continue;
        backend().applySource(m_grid, source, dt, setVelocity);
        if (setVelocity)
            continue;
        m_particleDebt += source.particlesPerSecond * dt;
        const int born = int(m_particleDebt);
        if (born > 0)
        {
            m_particleDebt -= born;
            backend().seedParticles(m_grid, m_particles, VortexParticles::places(source.centre, source.radius, born, m_random));
        }
    }
}

SmokeStepReport SmokeSimulation::step(double dt)
{
    SmokeStepReport report;
    report.dt = dt;
    using Clock = std::chrono::steady_clock;
    const auto seconds = [](Clock::time_point from) { return std::chrono::duration<double>(Clock::now() - from).count(); };
    SmokeBackend& backend = this->backend();
    auto started = Clock::now();
    applySources(dt, false);
    backend.advect(m_grid, dt, m_settings, m_steps % 2 == 1);
    report.advectionSeconds = seconds(started);
    started = Clock::now();
    backend.addHeatForces(m_grid, dt, m_settings);
    if (m_settings.confinement > 0.0 || (m_settings.particleStrength > 0.0 && m_particles.size() > 0))
        backend.addVortexForces(m_grid, dt, m_settings, m_particles);
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
    report.projection = projectStep(dt);
    report.projectionSeconds = seconds(started);
    started = Clock::now();
    backend.advanceParticles(m_grid, m_particles, dt);
    if (m_suction && m_time >= m_suction->onS && m_time < m_suction->offS)
        m_particles.removeWithin(m_suction->centre, m_suction->radius);
    report.particleSeconds = seconds(started);
    m_time += dt;
    ++m_steps;
    report.time = m_time;
    report.particles = m_particles.size();
    m_speed = backend.maxSpeed(m_grid);
    report.cfl = m_speed * dt / m_grid.h;
    if (!backend.finite(m_grid))
    {
        report.guard = storedText(Pattern{"the flow is no longer finite at t = %1 s", {numberText(m_time)}});
        return report;
    }
    if (report.cfl > m_settings.cflGuard)
    {
        report.guard = storedText(Pattern{"the flow crossed %1 cells in one step at t = %2 s (the limit is %3): the "
                                          "run is unstable (too strong a confinement or vortex forcing, or too long "
                                          "a step)",
                                          {storedNumber(report.cfl, 1), storedNumber(m_time, 3),
                                           storedNumber(m_settings.cflGuard, 1)}});
    }
    return report;
}

} // namespace vsim::sim::smoke
