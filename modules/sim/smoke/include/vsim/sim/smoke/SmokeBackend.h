#pragma once

// Where the smoke step's work on the grid runs. SmokeSimulation.h orchestrates every step and keeps the small
// state on the host (the sources, the ball's motion, the list of vortex particles, the random numbers); a backend
// does the work over the cells: the CPU's (CpuSmokeBackend below: the functions of Advection.h, SmokeForces.h,
// PressureProjection.h and VortexParticles.h on the simulation's own grid) or the GPU's (cuda/smoke: the same
// algorithm in single precision with the grid kept in the device's memory, uploaded before the first step and
// downloaded when the host reads it). Each call gets the simulation's host grid: the CPU's backend works on it,
// a device backend reads only its shape and boundaries between upload() and download().

#include "vsim/sim/smoke/Advection.h"
#include "vsim/sim/smoke/PressureProjection.h"
#include "vsim/sim/smoke/SmokeGrid.h"
#include "vsim/sim/smoke/VortexParticles.h"

#include <Eigen/Core>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace vsim::sim::smoke {

struct SmokeSource;
struct SmokeSettings;
struct MovingSphere;

class SmokeBackend
{
public:
    virtual ~SmokeBackend() = default;
    /// "cpu", or "cuda (device name)".
    virtual std::string name() const = 0;
    /// True when the backend works on the host grid itself (upload and download do nothing).
    virtual bool onHostGrid() const = 0;
    /// The host grid (velocity, smoke, temperature, solids and the solids' velocity) to the backend.
    virtual void upload(const SmokeGrid& grid) = 0;
    /// The backend's velocity, smoke, temperature, solids and the solids' velocity to the host grid.
    virtual void download(SmokeGrid& grid) = 0;

    /// A source's smoke and heat over dt (s) in its cells (`setVelocity` false), or its velocity on their faces.
    virtual void applySource(SmokeGrid& grid, const SmokeSource& source, double dt, bool setVelocity) = 0;
    /// Advection.h's advect().
    virtual void advect(SmokeGrid& grid, double dt, const SmokeSettings& settings, bool reverseSweeps) = 0;
    /// The temperature's cooling over dt and the buoyancy (SmokeForces.h's addBuoyancy).
    virtual void addHeatForces(SmokeGrid& grid, double dt, const SmokeSettings& settings) = 0;
    /// Vorticity confinement and the vortex particles' forcing, added to the faces over dt.
    virtual void addVortexForces(SmokeGrid& grid, double dt, const SmokeSettings& settings,
                                 const VortexParticles& particles) = 0;
    /// The solids: `staticSolid` (the anatomy, per cell kFluid / kSolid / kVent) and the sphere (may be null),
    /// whose cells take its velocity; the projection's operator is rebuilt when the solids changed; solid cells
    /// hold no smoke and no heat.
    virtual void placeSolids(SmokeGrid& grid, const std::vector<std::uint8_t>& staticSolid,
                             const MovingSphere* sphere) = 0;
    /// The suction's divergence per cell (1/s), which project() keeps when asked to.
    virtual void setSink(const std::vector<float>& sink) = 0;
    /// PressureProjection.h's project(), with the sink when `withSink`; `stepS` the step it ends (0: none).
    virtual ProjectionReport project(SmokeGrid& grid, double tolerance, int maxIterations, bool withSink, double stepS) = 0;
    /// VortexParticles::advance.
    virtual void advanceParticles(const SmokeGrid& grid, VortexParticles& particles, double dt) = 0;
    /// VortexParticles::seedAt: particles at `places` (m) that lie in fluid, with the grid's vorticity there.
    virtual void seedParticles(const SmokeGrid& grid, VortexParticles& particles,
                               const std::vector<Eigen::Vector3d>& places) = 0;
    /// The largest |u| of any face (m/s).
    virtual double maxSpeed(const SmokeGrid& grid) = 0;
    /// False when any velocity, smoke or temperature value is not finite.
    virtual bool finite(const SmokeGrid& grid) = 0;
};

/// The CPU's backend: the functions of this module on the host grid (OpenMP).
class CpuSmokeBackend : public SmokeBackend
{
public:
    std::string name() const override { return "cpu"; }
    bool onHostGrid() const override { return true; }
    void upload(const SmokeGrid&) override {}
    void download(SmokeGrid&) override {}
    void applySource(SmokeGrid& grid, const SmokeSource& source, double dt, bool setVelocity) override;
    void advect(SmokeGrid& grid, double dt, const SmokeSettings& settings, bool reverseSweeps) override;
    void addHeatForces(SmokeGrid& grid, double dt, const SmokeSettings& settings) override;
    void addVortexForces(SmokeGrid& grid, double dt, const SmokeSettings& settings,
                         const VortexParticles& particles) override;
    void placeSolids(SmokeGrid& grid, const std::vector<std::uint8_t>& staticSolid, const MovingSphere* sphere) override;
    void setSink(const std::vector<float>& sink) override { m_sink = sink; }
    ProjectionReport project(SmokeGrid& grid, double tolerance, int maxIterations, bool withSink, double stepS) override;
    void advanceParticles(const SmokeGrid& grid, VortexParticles& particles, double dt) override;
    void seedParticles(const SmokeGrid& grid, VortexParticles& particles,
                       const std::vector<Eigen::Vector3d>& places) override;
    double maxSpeed(const SmokeGrid& grid) override { return grid.maxSpeed(); }
    bool finite(const SmokeGrid& grid) override;

private:
    PressureProjection m_projection;
    bool m_prepared = false;
    std::vector<float> m_sink;
    std::vector<Eigen::Vector3f> m_force; ///< confinement and particle forcing at the cell centres (m/s^2)
};

/// Makes a backend for a simulation: the GPU's (cuda/smoke: cudaSmokeBackendFactory) or, when empty, the CPU's.
using SmokeBackendFactory = std::function<std::unique_ptr<SmokeBackend>(const SmokeGrid& grid)>;

} // namespace vsim::sim::smoke
