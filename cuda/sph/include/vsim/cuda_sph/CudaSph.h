#pragma once

// The SPH solver's step on the GPU (issue 18): the same algorithm as sim::sph::SphSolver::step (fluid and wall
// particles, gravity and the body force, mixture particles, open boundaries): leapfrog kick-drift-kick with the
// adaptive time step, the open boundaries' exchange after the drift and their buffers' imposed and
// extrapolated values (OpenBoundary.h), the walls' pressure extrapolated from the fluid (Adami et al. 2012),
// the continuity equation with the delta-SPH term and its renormalised density gradient, the pressure force
// and Morris's viscous term with the no-slip wall velocity (SphRates.h has the equations). In single precision
// (positions relative to the domain's corner), the particles kept sorted by cell: each step sorts the cell
// keys (radix sort), gathers every array into that order and lists each cell's run, so a particle's
// neighbours lie in the cells of the kernel's support around its own. The guards of the CPU step (a value
// not finite, the density guard, a particle out of the box, through a wall) stop a step with the reason.
// Periodic axes, tracer absorption and inlets that let in a tracer stay on the CPU: a solver that has them is
// refused. The particles an inlet creates are numbered in the order the GPU's threads reach them, which is not
// the CPU's: compare runs by the particles given at the start, and by their totals. SphSolver::setStepper runs
// it under the run driver (the CUDA stepper factory: cudaSphStepperFactory). No CUDA types in this header.

#include "vsim/sim/sph/SphSolver.h"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace vsim::cuda {

class CudaSph : public sim::sph::SphStepper
{
public:
    /// Copies the CPU solver's particles (after its initialize()), fluid, kernel, open boundaries and step
    /// settings to the GPU and computes the rates at the start, or takes the saved ones when the solver goes on
    /// from a checkpoint that holds them (SphSolver::savedStartRates). Throws vsim::Error without a CUDA device, when
    /// memory runs out, or for a solver with periodic axes, tracer absorption, an inlet of tracer or more than
    /// 32 open boundaries.
    explicit CudaSph(const sim::sph::SphSolver& solver);
    ~CudaSph() override;
    CudaSph(const CudaSph&) = delete;
    CudaSph& operator=(const CudaSph&) = delete;

    /// One leapfrog step. Returns the empty string, or why a guard stopped it (the particles are then those
    /// at the step's end: the run is over).
    std::string step() override;
    double timeS() const override;
    double lastStepS() const override; ///< the last step's length (s)
    /// The largest |rho / rho0(s) - 1| over the fluid after the last step.
    double largestDensityVariation() const;
    std::size_t particleCount() const;
    /// Mass in and out through each open boundary since the start (kg; the CPU solver's ledger at the start
    /// plus what the GPU's steps passed).
    const sim::sph::MassLedger& massLedger() const override;
    /// The last imposed flow rate of open boundary k into the domain (m^3/s) and its buffer's mean pressure
    /// (Pa), as OpenBoundaries::flowRate / pressure.
    double flowRate(std::size_t k) const override;
    double pressure(std::size_t k) const override;
    /// The particles back on the host (m, m/s, kg/m^3, their buffers) in the order of their numbers `id`
    /// (a closed domain's: position i holds the particle whose id is i).
    sim::sph::ParticleState download() const override;
    /// The rates of the next step's first kick in download()'s order (single precision, for a checkpoint).
    sim::sph::SphRates nextRates() const override;
    /// Times each phase of the steps from now on (StepPhases.cuh: waits for the device after each, so a run
    /// with it on is slower; for a profile, not a speed figure), or stops.
    void timePhases(bool on);
    /// Seconds per phase since timing began, in the order of the step.
    std::vector<std::pair<std::string, double>> phaseSeconds() const;
    /// Bytes of GPU memory held.
    std::size_t deviceBytes() const;

private:
    struct Device;
    std::unique_ptr<Device> m_device;
};

/// For SphSolver::setStepper: a CudaSph of the solver.
sim::sph::SphStepperFactory cudaSphStepperFactory();

} // namespace vsim::cuda
