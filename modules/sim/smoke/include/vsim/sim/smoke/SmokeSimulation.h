#pragma once

// One stable-fluids step of surgical smoke (thesis ch. 7; Stam 1999, Fedkiw et al. 2001, Selle et al. 2005), in
// this order: the sources add smoke, heat and newborn vortex particles; the velocity, the smoke and the temperature
// are advected (semi-Lagrangian, MacCormack as an option) by the last projected, divergence-free velocity;
// buoyancy, vorticity confinement and the vortex particles' forcing act and the sources set their velocity; the
// moving body takes its new place; the projection makes the flow
// divergence-free with no flow through solids; the vortex particles move and stretch. Inviscid (the thesis: gas
// viscosity is negligible at these scales); the temperature relaxes towards the ambient at a cooling rate.

#include "vsim/sim/smoke/Advection.h"
#include "vsim/sim/smoke/PressureProjection.h"
#include "vsim/sim/smoke/SmokeBackend.h"
#include "vsim/sim/smoke/SmokeGrid.h"
#include "vsim/sim/smoke/VortexParticles.h"

#include <Eigen/Core>

#include <limits>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace vsim::sim::smoke {

/// A smoke source: the cautery's contact with tissue (SI).
struct SmokeSource
{
    Eigen::Vector3d centre = Eigen::Vector3d::Zero(); ///< m
    double radius = 0.0;                              ///< m
    double densityRate = 0.0;    ///< smoke added per second inside the source (kg/m^3/s)
    double temperatureK = 0.0;   ///< the source's temperature rise above the ambient (K), held inside it
    Eigen::Vector3d velocity = Eigen::Vector3d::Zero(); ///< the plume's initial velocity (m/s)
    double onsetS = 0.0;         ///< time the smoke starts (s)
    double endS = std::numeric_limits<double>::infinity(); ///< time it stops (s)
    double particlesPerSecond = 0.0; ///< vortex particles born per second
};

/// A suction (smoke evacuation) port: takes `flowM3S` of gas, with the smoke it carries, out of the cells within
/// `radius` of `centre` while it is on; the gas comes back in through the vents or open faces.
struct SmokeSuction
{
    Eigen::Vector3d centre = Eigen::Vector3d::Zero(); ///< m
    double radius = 0.0;                              ///< m
    double flowM3S = 0.0;                             ///< m^3/s (1 l/min = 1.667e-5 m^3/s)
    double onS = 0.0, offS = std::numeric_limits<double>::infinity(); ///< s
};

/// A rigid sphere moving through the domain (the thesis's falling ball): position, velocity, and gravity on it.
struct MovingSphere
{
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();   ///< m
    double radius = 0.0;                                ///< m
    Eigen::Vector3d velocity = Eigen::Vector3d::Zero(); ///< m/s
    bool falls = false;                                 ///< accelerated by gravity (against `up`); no drag; it
                                                        ///< comes to rest at the domain's walls
};

struct SmokeSettings
{
    AdvectionScheme scheme = AdvectionScheme::SemiLagrangian;            ///< for the velocity
    AdvectionScheme scalarScheme = AdvectionScheme::Conservative;        ///< for the smoke and the heat
    double buoyancyAlpha = 0.0; ///< m/s^2 per kg/m^3 of smoke (pulls down)
    double buoyancyBeta = 0.0;  ///< m/s^2 per K (lifts)
    Eigen::Vector3d up = Eigen::Vector3d::UnitZ(); ///< against gravity, in the grid's axes
    double coolingPerS = 0.0;   ///< temperature relaxation rate (1/s)
    double confinement = 0.0;   ///< vorticity confinement epsilon (dimensionless)
    double particleStrength = 0.0; ///< the vortex particles' forcing epsilon (dimensionless)
    double particleRadius = 0.0;   ///< their control radius r (m)
    double tolerance = 1e-4;       ///< the projection's relative residual
    int maxIterations = 200;       ///< conjugate-gradient iterations per projection at most
    double cfl = 2.0;              ///< the step is chosen so that the fastest flow crosses this many cells
    double cflGuard = 10.0;        ///< a step whose flow crosses more cells than this stops the run
    unsigned seed = 1;             ///< for the vortex particles' places
};

/// What one step did.
struct SmokeStepReport
{
    double dt = 0.0;    ///< s
    double time = 0.0;  ///< s after the step
    double cfl = 0.0;   ///< largest |u| dt / h after the step
    ProjectionReport projection;
    std::size_t particles = 0;
    /// Wall-clock seconds of the step's parts: sources and advection, forces (buoyancy, confinement, particle
    /// forcing), the projection, the vortex particles' motion.
    double advectionSeconds = 0.0, forceSeconds = 0.0, projectionSeconds = 0.0, particleSeconds = 0.0;
    std::string guard; ///< not empty: the step failed (not finite, CFL); the state is not usable
};

class SmokeSimulation
{
public:
    /// The grid's solid cells are the static anatomy. `backend` does the work over the cells (SmokeBackend.h):
    /// the CPU's when null.
    SmokeSimulation(SmokeGrid grid, const SmokeSettings& settings, std::unique_ptr<SmokeBackend> backend = nullptr);

    void addSource(const SmokeSource& source) { m_sources.push_back(source); }
    /// Throws vsim::Error when the domain has neither a vent nor an open face (the gas would have nowhere to come
    /// from).
    void setSuction(const SmokeSuction& suction);
    void setSphere(const MovingSphere& sphere);
    /// Seeds vortex particles from the grid's current vorticity (the Taylor-Green case).
    void seedParticles(const Eigen::Vector3d& centre, double radius, int count);

    /// The step that keeps |u| dt / h at the settings' CFL, at most `maxDt` (s).
    double stableStep(double maxDt) const;
    /// Advances by dt (s).
    SmokeStepReport step(double dt);

    /// The grid now (downloaded from a device backend when the host's copy is behind).
    const SmokeGrid& grid() const;
    /// "cpu", or the device backend's name.
    std::string backendName() const { return m_backend->name(); }
    const VortexParticles& particles() const { return m_particles; }
    const std::optional<MovingSphere>& sphere() const { return m_sphere; }
    double time() const { return m_time; }
    /// Makes the current velocity divergence-free (an initial field), with the solids as they are.
    ProjectionReport project() { return projectStep(0.0); }

private:
    /// The projection that ends a step of `stepS` seconds (0: outside a step).
    ProjectionReport projectStep(double stepS);
    /// The sources' smoke, heat and newborn particles (before the advection), or their velocity (`setVelocity`:
    /// after the forces, before the projection).
    void applySources(double dt, bool setVelocity);
    void placeSphere();
    /// The backend, with the host grid uploaded to it first when the backend's copy is behind; the host's copy is
    /// behind afterwards unless the backend works on it.
    SmokeBackend& backend();

    mutable SmokeGrid m_grid;
    SmokeSettings m_settings;
    std::unique_ptr<SmokeBackend> m_backend;
    mutable bool m_hostCurrent = true;
    bool m_backendCurrent = false;
    double m_speed = -1.0; ///< the largest face speed after the last step (m/s); < 0: not known
    std::vector<std::uint8_t> m_staticSolid;
    std::vector<SmokeSource> m_sources;
    std::optional<SmokeSuction> m_suction;
    std::optional<MovingSphere> m_sphere;
    VortexParticles m_particles;
    std::mt19937 m_random;
    double m_time = 0.0;
    long m_steps = 0;
    double m_particleDebt = 0.0; ///< fractions of particles owed by the sources
};

} // namespace vsim::sim::smoke
