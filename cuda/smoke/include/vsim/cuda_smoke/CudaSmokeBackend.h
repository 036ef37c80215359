#pragma once

// The smoke step's work over the cells on the GPU (issue 21): sim::smoke::SmokeBackend with the grid in the
// device's memory, the same algorithm as the CPU's backend (modules/sim/smoke) in single precision (the vortex
// particles in double, as there): the advection (semi-Lagrangian or MacCormack with its limiter; the smoke and
// the heat by the conservative, minmod-limited transport swept axis by axis), the buoyancy and cooling, the
// vorticity confinement and the particles' forcing, the solids and the moving ball, the projection by
// conjugate gradients preconditioned with the red-black multigrid V-cycle (its coarsest level solved in one
// block), to the relative residual asked, warm-started. Each reduction (the dot products, the largest speed)
// comes back to the host as one small copy; the grid comes back only when the simulation's host copy is read.
// No CUDA types in this header.

#include "vsim/sim/smoke/SmokeBackend.h"

#include <memory>
#include <string>

namespace vsim::cuda {

class CudaSmokeBackend : public sim::smoke::SmokeBackend
{
public:
    /// Throws vsim::Error without a CUDA device.
    explicit CudaSmokeBackend(const sim::smoke::SmokeGrid& grid);
    ~CudaSmokeBackend() override;
    CudaSmokeBackend(const CudaSmokeBackend&) = delete;
    CudaSmokeBackend& operator=(const CudaSmokeBackend&) = delete;

    std::string name() const override;
    bool onHostGrid() const override { return false; }
    void upload(const sim::smoke::SmokeGrid& grid) override;
    void download(sim::smoke::SmokeGrid& grid) override;
    void applySource(sim::smoke::SmokeGrid& grid, const sim::smoke::SmokeSource& source, double dt, bool setVelocity) override;
    void advect(sim::smoke::SmokeGrid& grid, double dt, const sim::smoke::SmokeSettings& settings, bool reverseSweeps) override;
    void addHeatForces(sim::smoke::SmokeGrid& grid, double dt, const sim::smoke::SmokeSettings& settings) override;
    void addVortexForces(sim::smoke::SmokeGrid& grid, double dt, const sim::smoke::SmokeSettings& settings,
                         const sim::smoke::VortexParticles& particles) override;
    void placeSolids(sim::smoke::SmokeGrid& grid, const std::vector<std::uint8_t>& staticSolid,
                     const sim::smoke::MovingSphere* sphere) override;
    void setSink(const std::vector<float>& sink) override;
    sim::smoke::ProjectionReport project(sim::smoke::SmokeGrid& grid, double tolerance, int maxIterations,
                                         bool withSink, double stepS) override;
    void advanceParticles(const sim::smoke::SmokeGrid& grid, sim::smoke::VortexParticles& particles, double dt) override;
    void seedParticles(const sim::smoke::SmokeGrid& grid, sim::smoke::VortexParticles& particles,
                       const std::vector<Eigen::Vector3d>& places) override;
    double maxSpeed(const sim::smoke::SmokeGrid& grid) override;
    bool finite(const sim::smoke::SmokeGrid& grid) override;

    /// Bytes of GPU memory held.
    std::size_t deviceBytes() const;

private:
    struct Device;
    std::unique_ptr<Device> m_device;
};

/// For SmokeSimulation (and SmokeSolver::setBackend): a CudaSmokeBackend of the grid.
sim::smoke::SmokeBackendFactory cudaSmokeBackendFactory();

} // namespace vsim::cuda
