#include "vsim/sim/network/FillingSolver.h"

#include "vsim/core/Error.h"
#include "vsim/sim/common/RunDriver.h"

#include <algorithm>

namespace vsim::sim::network {

FillingSolver::FillingSolver(const NetworkRunResult& run, int steps) : m_run(run), m_steps(std::max(1, steps)) {}

void FillingSolver::initialize(const SimulationInput& input, const ParameterSet&)
{
    if (!input.data.empty())
        throw Error("the filling takes no input: its network comes with the solved run");
    m_step = 0;
}

StepOutcome FillingSolver::step(RunStatus& status, const Progress&)
{
    if (m_step == 0)
        status = m_run.status; // the steady solves the filling follows
    ++m_step;
    return {};
}

SimulationData FillingSolver::snapshot() const
{
    VesselNetwork network = m_run.network;
    std::vector<double> lengths;
    filledLengths(m_run.network, m_run.twoPhase, m_run.filling, position(), lengths);
    std::vector<double> fraction(lengths.size());
    for (std::size_t s = 0; s < lengths.size(); ++s)
        fraction[s] = network.segments[s].lengthMm > 0.0 ? std::clamp(lengths[s] / network.segments[s].lengthMm, 0.0, 1.0) : 0.0;
    network.segmentFields["filled_length_mm"] = std::move(lengths);
    network.segmentFields["filled_fraction"] = std::move(fraction);
    return network;
}

SolverRun fillingRun(const NetworkRunResult& run, int steps)
{
    FillingSolver solver(run, steps);
    RunControl control;
    control.frameEverySteps = 1;
    control.maxSteps = steps;
    SolverRun filling = runSolver(solver, {}, ParameterSet(std::vector<ParameterSpec>{}), control);
    if (filling.status.solves == 0) // no step (nothing reached): the run's own status
    {
        const RunStatus status = filling.status;
        filling.status = run.status;
        filling.status.reachedQuantity = status.reachedQuantity, filling.status.reachedUnit = status.reachedUnit;
        filling.status.reached = status.reached, filling.status.target = status.target;
    }
    return filling;
}

} // namespace vsim::sim::network
