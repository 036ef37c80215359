#pragma once

// The interface every solver offers the run driver (RunDriver.h; ARCHITECTURE.md, "Solvers"): it declares its
// parameters, sets itself up from its inputs, advances by steps, and shows its state as a frame and its figures as
// metrics. The driver owns the loop, the frames, progress, cancel, the guards and the run status; a solver owns only
// its physics. `modules/sim/heat` is the smallest example (sim/common/README.md).

#include "vsim/core/Parameters.h"
#include "vsim/core/Progress.h"
#include "vsim/core/RunStatus.h"
#include "vsim/core/SimulationData.h"
#include "vsim/core/SolverRun.h"

#include <map>
#include <string>
#include <vector>

namespace vsim::sim {

/// What one step did.
struct StepOutcome
{
    enum class Kind
    {
        Continue,     ///< stepped; the driver checks the end
        Finished,     ///< the solver's own end (e.g. the last load increment), whatever position() says
        EndCondition, ///< a physical end condition (e.g. the fracture entropy): `message` says which
        Guard         ///< the step failed (NaN, inverted elements, breakdown): the solver is back at its last good
                      ///< state, `message` says what happened and where
    };
    Kind kind = Kind::Continue;
    std::string message;
    /// The solver asks for a frame of this state whatever the schedule (an event: a tear's onset, the state after
    /// a release).
    bool keyFrame = false;

    static StepOutcome guard(std::string why) { return {Kind::Guard, std::move(why)}; }
};

class Solver
{
public:
    virtual ~Solver() = default;

    /// Short name for files and messages ("heat", "fem", "network").
    virtual std::string name() const = 0;
    /// Every parameter the solver reads, with units and ranges (forms, --param, provenance).
    virtual std::vector<ParameterSpec> parameters() const = 0;
    /// Sets the solver up for a new run. Throws vsim::Error for bad input or parameters (nothing is run then).
    virtual void initialize(const SimulationInput& input, const ParameterSet& parameters) = 0;
    /// The run's axis; valid after initialize().
    virtual RunAxis axis() const = 0;
    /// Where the run stands on its axis (in the axis unit).
    virtual double position() const = 0;
    /// The share of the progress bar that the axis fills (the rest is a final solve after the axis's end, as the
    /// wall's equilibrium after its load path); 1 by default.
    virtual double axisProgressShare() const { return 1.0; }
    /// Advances by one step; each linear or nonlinear solve it makes is recorded in `status` (recordSolve), and a
    /// final force residual where the solver has one. `progress` is the run's: a long step checks it for a cancel
    /// (vsim::Cancelled, the state put back to the last good one) and reports past axisProgressShare().
    virtual StepOutcome step(RunStatus& status, const Progress& progress) = 0;
    /// The current state as a frame (mm, fields with units in their names).
    virtual SimulationData snapshot() const = 0;
    /// The solver's figures of the current state, with units in their keys ("peak_temperature_rise_k").
    virtual std::map<std::string, double> metrics() const = 0;
};

} // namespace vsim::sim
