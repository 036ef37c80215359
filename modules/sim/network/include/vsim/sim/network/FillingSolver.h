#pragma once

// The drug's filling of the tree over time (Filling.h) on the run driver (sim/common): a solved network run
// (NetworkRun.h: the steady split of the two-phase drug and the filling times) stepped in equal times from the
// injection's start to the front's last outlet arrival, each frame the network with its result fields and
// filled_length_mm and filled_fraction per segment. The steady solves are direct: the run status is the network
// run's (Kirchhoff's balance against kConservationTolerance).

#include "vsim/sim/common/Solver.h"
#include "vsim/sim/network/NetworkRun.h"

namespace vsim::sim::network {

class FillingSolver : public Solver
{
public:
    /// `run` must outlive the solver; `steps` equal time steps to the last arrival.
    FillingSolver(const NetworkRunResult& run, int steps);

    std::string name() const override { return "network"; }
    std::vector<ParameterSpec> parameters() const override { return {}; }
    /// No input: the network comes with the run.
    void initialize(const SimulationInput& input, const ParameterSet& parameters) override;
    RunAxis axis() const override { return {"time", "s", m_run.filling.lastArrival}; }
    double position() const override { return m_step * m_run.filling.lastArrival / m_steps; }
    StepOutcome step(RunStatus& status, const Progress& progress) override;
    SimulationData snapshot() const override;
    /// The network run's metrics.
    std::map<std::string, double> metrics() const override { return m_run.metrics; }

private:
    const NetworkRunResult& m_run;
    int m_steps = 1;
    int m_step = 0;
};

/// The filling as a run of steps + 1 frames (the network run's status and metrics, provenance solver "network").
SolverRun fillingRun(const NetworkRunResult& run, int steps = 100);

} // namespace vsim::sim::network
