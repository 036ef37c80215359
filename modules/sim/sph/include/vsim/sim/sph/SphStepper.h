#pragma once

// Another stepper for SphSolver's algorithm (issue 18): the GPU's (cuda/sph's CudaSph) takes the solver after its
// initialize() and steps the particles where they live; the solver fetches them back every few steps for its
// sections, wall loads, frames and metrics (SphSolver::setStepper). SI units.

#include "vsim/sim/sph/OpenBoundary.h"
#include "vsim/sim/sph/ParticleState.h"
#include "vsim/sim/sph/SphRates.h"

#include <functional>
#include <memory>
#include <string>

namespace vsim::sim::sph {

class SphSolver;

class SphStepper
{
public:
    virtual ~SphStepper() = default;
    /// One step of the solver's algorithm: "" or why a guard stopped it (the run is then over).
    virtual std::string step() = 0;
    virtual double timeS() const = 0;
    virtual double lastStepS() const = 0; ///< the last step's length (s)
    /// The particles in the order of their numbers (m, m/s, kg/m^3, their buffers).
    virtual ParticleState download() const = 0;
    /// The rates the next step's first kick takes, in download()'s order (acceleration, densityRate,
    /// shiftVelocity, wallDistance and the three largest values: what a checkpoint keeps); empty from a stepper
    /// that cannot give them.
    virtual SphRates nextRates() const { return {}; }
    /// Mass through the open boundaries since the start (kg), their last flow rates into the domain (m^3/s) and
    /// their buffers' mean pressures (Pa).
    virtual const MassLedger& massLedger() const = 0;
    virtual double flowRate(std::size_t k) const = 0;
    virtual double pressure(std::size_t k) const = 0;
};

/// Makes a stepper from an initialized solver; throws vsim::Error when it cannot run the solver's case, or returns
/// none to leave the steps to the CPU.
using SphStepperFactory = std::function<std::unique_ptr<SphStepper>(const SphSolver&)>;

} // namespace vsim::sim::sph
