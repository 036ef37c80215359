#pragma once

// A place other than this CPU where WallSimulation's implicit step can run: the CUDA backend (cuda/fem) provides
// one, the run driver takes it through a factory, so that this module does not depend on CUDA. A stepper holds
// its own copy of the state and runs the same algorithm as BackwardEuler (element pass, assembly, pressure,
// block-Jacobi PCG warm-started from the last step); WallSimulation copies the state back after every step and
// makes a new stepper whenever the model changes (tearing, a guard restoring the last good state).

#include "vsim/sim/fem/BackwardEuler.h"
#include "vsim/sim/fem/CorotationalFem.h"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace vsim::sim::fem {

class ImplicitStepper
{
public:
    virtual ~ImplicitStepper() = default;
    /// One backward-Euler step with `pressurePa` on the faces the stepper was made with (a follower load).
    virtual StepReport step(double pressurePa) = 0;
    /// The state after the last step: positions (m) and velocities (m/s), 3 entries per node.
    virtual void download(Eigen::VectorXd& positions, Eigen::VectorXd& velocities) const = 0;
};

/// Makes a stepper from the model's current state, its constrained components (3 per node, 1 = fixed) and the
/// faces under pressure. Throws vsim::Error when it cannot (no device, a material it does not run).
using StepperFactory = std::function<std::unique_ptr<ImplicitStepper>(
    const CorotationalFem& model, const BackwardEulerSettings& settings, const std::vector<std::uint8_t>& constrained,
    const std::vector<std::array<int, 3>>& pressureFaces)>;

} // namespace vsim::sim::fem
