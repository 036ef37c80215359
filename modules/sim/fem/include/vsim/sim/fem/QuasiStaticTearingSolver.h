#pragma once

// Quasi-static tearing (QuasiStaticTearing.h) on the run driver (sim/common): input "wall", the axis the ramp's
// pressure (kPa) to its end, one driver step per ramp increment (its equilibrium, the onset's bisection and the
// releases one element at a time), except that the first onset's equilibrium is a step of its own so that its
// state is a frame before any release. Frames are key frames (StepOutcome::keyFrame): the start, the onset, the
// state after each pressure's releases; the driver adds the last. Every frame is the last converged equilibrium.

#include "vsim/sim/common/Solver.h"
#include "vsim/sim/fem/QuasiStaticTearing.h"
#include "vsim/sim/fem/WallSimulation.h"

#include <memory>

namespace vsim::sim::fem {

class QuasiStaticTearingSolver : public Solver
{
public:
    /// `setup` without its wall: the wall comes as the input "wall".
    explicit QuasiStaticTearingSolver(QuasiStaticTearingSetup setup);
    ~QuasiStaticTearingSolver() override;

    std::string name() const override { return "fem-quasi-static-tearing"; }
    std::vector<ParameterSpec> parameters() const override { return {}; }
    /// Checks the setup (throws vsim::Error) and solves the equilibrium at the ramp's start.
    void initialize(const SimulationInput& input, const ParameterSet& parameters) override;
    RunAxis axis() const override { return {"pressure", "kPa", m_setup.endPa * 1e-3}; }
    /// The pressure whose releases are done (kPa).
    double position() const override { return m_safe * 1e-3; }
    StepOutcome step(RunStatus& status, const Progress& progress) override;
    /// The last converged equilibrium.
    SimulationData snapshot() const override { return m_lastGood; }
    /// final_pressure_kpa, tear_onset_pressure_mpa (-1 without a tear), tear_onset_bracket_mpa,
    /// first_torn_element, torn_elements, fracture_entropy, equilibrium_solves, failed_equilibria.
    std::map<std::string, double> metrics() const override;

    /// The pressure (Pa) of the last converged equilibrium, and the equilibria solved, after driver step `step`.
    double pressureAfter(long step) const { return m_after.at(std::size_t(step)).first; }
    int solvesAfter(long step) const { return m_after.at(std::size_t(step)).second; }
    double lastGoodPressurePa() const { return m_lastGoodPressure; }
    const std::vector<std::pair<double, double>>& entropyCurve() const { return m_entropyCurve; }

private:
    /// The equilibrium at `pressure` from the wall's state; false when it fails (the state restored, m_failure says
    /// why). A converged one's solves go into `status`.
    bool equilibrium(double pressure, RunStatus& status, const Progress& progress);
    /// Releases the most stressed element and solves again at m_over until none is over its strength.
    StepOutcome release(RunStatus& status, const Progress& progress);
    StepOutcome record(StepOutcome outcome);
    /// The guard when the equilibrium at m_over failed (m_failure says why).
    StepOutcome equilibriumFailed() const;

    QuasiStaticTearingSetup m_setup;
    std::unique_ptr<WallSimulation> m_wall;
    TetMesh m_lastGood;
    double m_lastGoodPressure = 0.0, m_safe = 0.0, m_over = 0.0, m_onset = -1.0, m_bracket = 0.0;
    Eigen::VectorXd m_safeState;
    std::size_t m_firstTorn = 0;
    int m_solves = 0, m_failed = 0;
    bool m_releasePending = false;
    std::string m_failure, m_startProblem;
    RunStatus m_startStatus; ///< the start's equilibrium, handed to the run's status at the first step
    std::vector<std::pair<double, int>> m_after; ///< per driver step (0: the start)
    std::vector<std::pair<double, double>> m_entropyCurve;
};

} // namespace vsim::sim::fem
