#pragma once

// The time-stepped wall on the run driver (sim/common): the wall (input "wall", a TetMesh in mm as
// mesh::buildWallMesh makes it) under a lumen pressure curve, one damped implicit step of WallSimulation per driver
// step (ends fixed, optional tearing with the fracture entropy as its end condition), on the axis of simulated time
// (s) to steps x h. With an equilibrium tolerance the step that reaches the end also solves the static equilibrium
// at the final pressure (WallSimulation::equilibrate): the run status is then the equilibrium's, and the load
// path's capped conjugate-gradient steps go to the metrics as path_*. Guards (NaN, inverted elements, a PCG
// breakdown) put the wall back at its last good state. `runFem` (FemRun.h) runs it for the protocols.

#include "vsim/sim/common/Solver.h"
#include "vsim/sim/fem/FemRun.h"
#include "vsim/sim/fem/WallSimulation.h"

#include <memory>

namespace vsim::sim::fem {

class WallPathSolver : public Solver
{
public:
    /// `setup` without its wall: the wall comes as the input "wall". `parameters` are the protocol's declarations
    /// (for the run's provenance); the setup already holds their values.
    WallPathSolver(FemRunSetup setup, std::vector<ParameterSpec> parameters);
    ~WallPathSolver() override;

    std::string name() const override { return "fem"; }
    std::vector<ParameterSpec> parameters() const override { return m_parameters; }
    void initialize(const SimulationInput& input, const ParameterSet& parameters) override;
    RunAxis axis() const override { return {"time", "s", m_setup.steps * m_setup.integrator.timeStep}; }
    double position() const override { return m_step * m_setup.integrator.timeStep; }
    double axisProgressShare() const override { return m_setup.equilibriumTolerance > 0.0 ? 0.7 : 1.0; }
    StepOutcome step(RunStatus& status, const Progress& progress) override;
    SimulationData snapshot() const override { return m_simulation->frame(); }
    /// steps, final_pressure_kpa; with tearing torn_elements, fracture_entropy, tear_onset_pressure_mpa (-1: none);
    /// after an equilibrium path_steps, path_capped_steps, path_mean_cg_iterations, equilibrium_updates.
    std::map<std::string, double> metrics() const override;

    /// The lumen pressure (Pa) at simulated time t (s).
    double pressureAt(double timeS) const { return m_setup.pressurePa(timeS); }
    /// Why the run ended early, with the step, time and pressure; empty when it ran through.
    const std::string& stopReason() const { return m_stopReason; }
    /// Per implicit step: the PCG iterations and final relative residual.
    const std::vector<int>& stepIterations() const { return m_stepIterations; }
    const std::vector<double>& stepResiduals() const { return m_stepResiduals; }
    /// (pressure Pa, entropy) after each tear; the equilibrium's force residual before each update and at the end.
    const std::vector<std::pair<double, double>>& entropyCurve() const { return m_entropyCurve; }
    const std::vector<double>& equilibriumResiduals() const { return m_equilibriumResiduals; }

private:
    /// The equilibrium at the final pressure after the path; replaces `status` by its own solves.
    StepOutcome equilibrate(RunStatus& status, const Progress& progress);

    FemRunSetup m_setup;
    std::vector<ParameterSpec> m_parameters;
    std::unique_ptr<WallSimulation> m_simulation;
    int m_step = 0;
    double m_onsetPressurePa = -1.0;
    std::string m_stopReason;
    std::vector<int> m_stepIterations;
    std::vector<double> m_stepResiduals, m_equilibriumResiduals;
    std::vector<std::pair<double, double>> m_entropyCurve;
    std::map<std::string, double> m_pathMetrics;
};

} // namespace vsim::sim::fem
