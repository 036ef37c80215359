#pragma once

// The SPH solver's step on the GPU (issue 18): the same algorithm as sim::sph::SphSolver::step for closed
// domains (fluid and wall particles, gravity and the body force, mixture particles): leapfrog kick-drift-kick
// with the adaptive time step, the walls' pressure extrapolated from the fluid (Adami et al. 2012), the
// continuity equation with the delta-SPH term and its renormalised density gradient, the pressure force and
// Morris's viscous term with the no-slip wall velocity (SphRates.h has the equations). In single precision
// (positions relative to the domain's corner), the particles kept sorted by cell: each step counts sorts the
// cell keys (radix sort), gathers every array into that order and lists each cell's run, so a particle's
// neighbours lie in the 27 cells of the kernel's support around its own. The guards of the CPU step (a value
// not finite, the density guard, a particle out of the box) stop a step with the reason. Open boundaries,
// periodic axes and tracer absorption stay on the CPU: a solver that has them is refused. No CUDA types in
// this header.

#include "vsim/sim/sph/SphSolver.h"

#include <memory>
#include <string>

namespace vsim::cuda {

class CudaSph
{
public:
    /// Copies the CPU solver's particles (after its initialize()), fluid, kernel and step settings to the GPU
    /// and computes the rates at the start. Throws vsim::Error without a CUDA device, when memory runs out,
    /// or for a solver with open boundaries, periodic axes or tracer absorption.
    explicit CudaSph(const sim::sph::SphSolver& solver);
    ~CudaSph();
    CudaSph(const CudaSph&) = delete;
    CudaSph& operator=(const CudaSph&) = delete;

    /// One leapfrog step. Returns the empty string, or why a guard stopped it (the particles are then those
    /// at the step's end: the run is over).
    std::string step();
    double timeS() const;
    /// The largest |rho / rho0(s) - 1| over the fluid after the last step.
    double largestDensityVariation() const;
    /// The particles back on the host (m, m/s, kg/m^3) in the numbering `id` of the CPU solver's particles,
    /// position i holding the particle whose id is i.
    sim::sph::ParticleState download() const;
    /// Bytes of GPU memory held.
    std::size_t deviceBytes() const;

private:
    struct Device;
    std::unique_ptr<Device> m_device;
};

} // namespace vsim::cuda
