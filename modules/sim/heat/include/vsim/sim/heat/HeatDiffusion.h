#pragma once

// The template solver of the run driver (sim/common/README.md: copy this one): heat diffusion dT/dt = D lap T in a
// cube of tissue whose faces are held at body temperature (a temperature rise of 0), stepped by forward Euler with
// the 7-point Laplacian on the voxel nodes (FTCS: stable for dt <= h^2 / (6 D)). The initial rise is the slowest
// mode A sin(pi x/L) sin(pi y/L) sin(pi z/L), whose exact solution decays as exp(-3 pi^2 D t / L^2): the
// validation case (HeatValidation.h). Parameters in mm, s and K; SI inside.

#include "vsim/sim/common/Solver.h"

namespace vsim::sim::heat {

/// The solver's parameters: diffusivity_mm2_s (soft tissue 0.14 mm^2/s), box_mm, cells, amplitude_k, end_time_s,
/// time_step_fraction (of the stability limit h^2 / (6 D)).
std::vector<ParameterSpec> heatParameters();

class HeatDiffusionSolver : public Solver
{
public:
    std::string name() const override { return "heat"; }
    std::vector<ParameterSpec> parameters() const override { return heatParameters(); }
    /// No input: the cube comes from the parameters.
    void initialize(const SimulationInput& input, const ParameterSet& parameters) override;
    RunAxis axis() const override { return {"time", "s", m_endTimeS}; }
    double position() const override { return m_timeS; }
    /// One forward-Euler step (the last one shortened to land on the end time). A rise above the initial maximum
    /// breaks the maximum principle (an unstable step): a guard, the field left as it was.
    StepOutcome step(RunStatus& status, const Progress& progress) override;
    /// The field "temperature_rise_k" on the (cells + 1)^3 nodes, mm.
    SimulationData snapshot() const override;
    /// peak_temperature_rise_k, analytic_peak_temperature_rise_k, relative_l2_error (against the exact solution,
    /// over the nodes), time_step_s.
    std::map<std::string, double> metrics() const override;

    /// The exact rise at node (i, j, k) at time t (s).
    double exact(int i, int j, int k, double timeS) const;

private:
    std::size_t index(int i, int j, int k) const { return std::size_t(i + m_nodes * (j + m_nodes * k)); }

    int m_nodes = 0;                  ///< per axis, faces included
    double m_spacingM = 0.0, m_diffusivityM2S = 0.0, m_amplitudeK = 0.0;
    double m_timeS = 0.0, m_endTimeS = 0.0, m_stepS = 0.0;
    double m_limitK = 0.0;            ///< the initial maximum: nothing may rise above it
    std::vector<double> m_rise, m_next; ///< K on the nodes
};

} // namespace vsim::sim::heat
