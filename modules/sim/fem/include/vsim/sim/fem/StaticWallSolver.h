#pragma once

// The converged wall analysis (StaticWallRun.h) on the run driver (sim/common): input "wall" (a TetMesh in mm with
// wall_layer and end_set), the axis the lumen pressure (kPa) up to the target, one driver step per converged load
// increment (an increment that fails is undone and retried at half the size inside the step, down to 1/16 of the
// pressure; below that the step is a guard with the last converged increment kept). `runStaticWall` runs it.

#include "vsim/sim/common/Solver.h"
#include "vsim/sim/fem/QuadraticFem.h"
#include "vsim/sim/fem/StaticWallRun.h"

#include <memory>

namespace vsim::sim::fem {

class StaticWallSolver : public Solver
{
public:
    /// `setup` without its wall: the wall comes as the input "wall".
    explicit StaticWallSolver(StaticWallSetup setup);
    ~StaticWallSolver() override;

    std::string name() const override { return "fem-static"; }
    std::vector<ParameterSpec> parameters() const override { return {}; }
    void initialize(const SimulationInput& input, const ParameterSet& parameters) override;
    RunAxis axis() const override { return {"pressure", "kPa", m_setup.pressurePa * 1e-3}; }
    double position() const override { return m_reached * m_setup.pressurePa * 1e-3; }
    /// The next load increment to its equilibrium (Newton, StaticSolver.h); records every update's linear solve
    /// and the force residual against the tolerance in `status`. Cancel puts the last converged state back.
    StepOutcome step(RunStatus& status, const Progress& progress) override;
    /// The state on the linear wall mesh (mm): corner displacements, each element's mean Cauchy stress (kPa), and
    /// the wall's material field where it has one.
    SimulationData snapshot() const override;
    /// load_cutbacks, thrombus_elements, element_order (2), quadratic_nodes, load_increments (converged),
    /// equilibrium_updates, equilibrium_factorisations, final_pressure_kpa.
    std::map<std::string, double> metrics() const override;

    /// The relative force residual before each Newton update of every increment, and at each increment's end.
    const std::vector<double>& equilibriumResiduals() const { return m_residuals; }

private:
    StaticWallSetup m_setup;
    TetMesh m_wall;
    std::unique_ptr<QuadraticFem> m_model;
    std::vector<std::uint8_t> m_held;
    std::vector<std::array<int, 6>> m_faces;
    std::vector<double> m_faceExtraPa; ///< per face, the wall's kLumenExtraPressureField (empty without it)
    double m_reached = 0.0, m_increment = 1.0; ///< load factors
    int m_converged = 0, m_updates = 0, m_cutbacks = 0, m_factorisations = 0;
    std::vector<double> m_residuals;
};

} // namespace vsim::sim::fem
