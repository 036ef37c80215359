#pragma once

// The smoke solver on the run driver (issue 21; sim/common/README.md): a scene (SmokeScenes.h) stepped by
// SmokeSimulation.h, each projection recorded as a solve (iterations, relative residual against the tolerance),
// the endoscope's obscuration (Obscuration.h) sampled along the run. Frames are the smoke density (mg/m^3) and the
// temperature rise (K) on the grid, in mm in the scene's frame (the patient frame where a study is involved).
// Guards: a flow that is not finite, a step whose flow crosses more than 10 cells.

#include "vsim/sim/common/Solver.h"
#include "vsim/sim/smoke/SmokeScenes.h"

#include <memory>
#include <utility>
#include <vector>

namespace vsim::sim::smoke {

/// The parameters with `scenario`'s defaults (ball-drop, evh, liver-ablation): grid_cells, end_time_s,
/// max_step_s, cfl, advection, tolerance, max_iterations, confinement, particle_strength, particle_radius_cells,
/// particles, source_rate_mg_s, source_temperature_k, source_speed_m_s, source_onset_s, source_duration_s,
/// cooling_per_s, suction_l_min, suction_on_s, suction_off_s, mass_extinction_m2_g, visible_transmittance,
/// obscuration_every_s.
std::vector<ParameterSpec> smokeParameters(const std::string& scenario = "ball-drop");

/// The scenarios: ball-drop, evh, liver-ablation.
std::vector<std::string> smokeScenarios();

class SmokeSolver : public Solver
{
public:
    explicit SmokeSolver(SmokeScene scene);
    std::string name() const override { return "smoke"; }
    std::vector<ParameterSpec> parameters() const override { return smokeParameters(m_scene.name); }
    /// No input: the scene is the geometry. Throws vsim::Error for a suction without a vent.
    void initialize(const SimulationInput& input, const ParameterSet& parameters) override;
    RunAxis axis() const override { return {"time", "s", m_endTimeS}; }
    double position() const override;
    StepOutcome step(RunStatus& status, const Progress& progress) override;
    SimulationData snapshot() const override;
    /// smoke_mass_mg, peak_density_mg_m3, vortex_particles, obscured_fraction, peak_obscured_fraction,
    /// time_to_50_percent_obscuration_s, time_to_90_percent_obscuration_s (-1: not reached), and with a suction
    /// time_to_clear_s (after it starts, the obscured fraction back under 10 %; -1: not), smoke_removed_in_10s_percent
    /// (of the smoke present when it started: Chou 2024's measure); mean_projection_iterations, worst_relative_residual,
    /// worst_divergence_ratio, time_step_s (the last).
    std::map<std::string, double> metrics() const override;

    /// (time s, obscured fraction) along the run.
    const std::vector<std::pair<double, double>>& obscurationCurve() const { return m_curve; }
    /// The endoscope's view now.
    ObscurationView view() const;
    const SmokeScene& scene() const { return m_scene; }
    /// Where the steps' work over the cells runs (SmokeBackend.h): the factory's backend from the next
    /// initialize() on; empty: the CPU's.
    void setBackend(SmokeBackendFactory factory) { m_backendFactory = std::move(factory); }
    /// "cpu" or "cuda" (after initialize()).
    std::string backendName() const { return m_simulation ? m_simulation->backendName() : "cpu"; }

private:
    SmokeScene m_scene;
    std::unique_ptr<SmokeSimulation> m_simulation;
    SmokeBackendFactory m_backendFactory;
    double m_endTimeS = 0.0, m_maxStepS = 0.0, m_extinction = 0.0, m_visible = 0.5, m_sampleEveryS = 0.1;
    double m_nextSampleS = 0.0, m_lastStepS = 0.0;
    std::vector<std::pair<double, double>> m_curve;
    long m_projections = 0, m_iterations = 0;
    double m_worstResidual = 0.0, m_worstDivergence = 0.0;
    double m_tolerance = 1e-4;
    int m_maxIterations = 200;
    double m_suctionOnS = -1.0;       ///< when the suction starts (s); < 0: no suction
    double m_massAtSuctionMg = -1.0;  ///< the smoke present when the suction started (mg)
    double m_massAfter10sMg = -1.0;   ///< and 10 s later
    bool m_released = false;
};

} // namespace vsim::sim::smoke
