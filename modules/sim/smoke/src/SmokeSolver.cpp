#include "vsim/sim/smoke/SmokeSolver.h"

#include "vsim/core/Error.h"
#include "vsim/sim/smoke/SmokeForces.h"

#include <algorithm>
#include <cmath>

namespace vsim::sim::smoke {
namespace {

constexpr double kClearLevel = 0.1; // the view is clear again below this obscured fraction

/// A scenario's default for a parameter: ball-drop, evh, liver-ablation.
double byScenario(const std::string& scenario, double ballDrop, double evh, double liver)
{
    return scenario == "evh" ? evh : scenario == "liver-ablation" ? liver : ballDrop;
}

} // namespace

std::vector<std::string> smokeScenarios()
{
    return {"ball-drop", "evh", "liver-ablation"};
}

std::vector<ParameterSpec> smokeParameters(const std::string& scenario)
{
    using K = ParameterSpec::Kind;
    const auto d = [&](double a, double b, double c) { return byScenario(scenario, a, b, c); };
    return {
        {"grid_cells", "Cells along the longest edge", "", 64, 8, 512, "Grid",
         "the grid's resolution (the thesis demo: 256); cubic cells", K::Integer},
        {"end_time_s", "End time", "s", d(3.0, 16.0, 21.0), 0.01, 600.0, "Time", "simulated time", K::Real},
        {"max_step_s", "Longest step", "s", 0.02, 1e-4, 0.2, "Time", "the step is shorter when the flow is fast (cfl)", K::Real},
        {"cfl", "Courant number", "", 2.0, 0.1, 5.0, "Time",
         "cells the fastest flow crosses in one step (semi-Lagrangian advection is stable beyond 1)", K::Real},
        {"advection", "Velocity advection", "", 0, 0, 1, "Solver",
         "0 semi-Lagrangian, 1 MacCormack with the limiter (Selle et al. 2008)", K::Integer},
        {"tolerance", "Projection tolerance", "", 1e-4, 1e-10, 1e-1, "Solver",
         "relative residual of the pressure solve (MGPCG)", K::Real},
        {"max_iterations", "Projection iterations", "", 200, 1, 10000, "Solver",
         "conjugate-gradient iterations per projection at most", K::Integer},
        {"confinement", "Vorticity confinement", "", 0.3, 0.0, 10.0, "Solver",
         "epsilon of Fedkiw et al. 2001 (thesis eq. 7.9): f = epsilon h (N x w)", K::Real},
        {"particle_strength", "Vortex particle strength", "", 0.3, 0.0, 10.0, "Solver",
         "epsilon of the particles' forcing (thesis eqs. 7.20-7.23); too large is unstable", K::Real},
        {"particle_radius_cells", "Vortex particle radius", "", 2.0, 0.5, 8.0, "Solver",
         "the clamped Gaussian's control radius r, in cells", K::Real},
        {"particles", "Vortex particles", "", d(1100, 400, 600), 0, 100000, "Source",
         "born at the source over its duration (thesis: 1,100 in the demo, 400 in EVH)", K::Integer},
        {"source_rate_mg_s", "Smoke emission", "mg/s", d(50.0, 0.1, 1.0), 0.0, 1e4, "Source",
         "particulate mass the cautery releases (an assumption: published rates vary widely)", K::Real},
        {"source_temperature_k", "Plume temperature", "K", 60.0, 0.0, 1000.0, "Source",
         "the plume's rise above the ambient at the source", K::Real},
        {"source_speed_m_s", "Plume speed", "m/s", d(0.5, 0.3, 0.05), 0.0, 20.0, "Source",
         "initial velocity of the plume, along gravity's up (liver ablation: lower, thesis)", K::Real},
        {"source_onset_s", "Smoke onset", "s", d(0.0, 9.0, 0.0), 0.0, 600.0, "Source",
         "when the smoke starts after the tool's contact (EVH: 9 s, thesis)", K::Real},
        {"source_duration_s", "Smoke duration", "s", d(3.0, 5.0, 8.0), 0.0, 600.0, "Source", "how long it emits", K::Real},
        {"cooling_per_s", "Plume cooling", "1/s", 0.5, 0.0, 100.0, "Source",
         "rate at which the plume's temperature rise relaxes (mixing, walls)", K::Real},
        {"suction_l_min", "Suction", "l/min", d(0.0, 0.0, 20.0), 0.0, 100.0, "Suction",
         "smoke evacuation flow at the suction port (scenes with a port); liver-ablation's 20 l/min is calibrated to "
         "remove 85 % of the smoke in 10 s (Chou 2024) in the box phantom at 64 cells", K::Real},
        {"suction_on_s", "Suction on", "s", d(0.0, 0.0, 10.0), 0.0, 600.0, "Suction", "when the suction starts", K::Real},
        {"suction_off_s", "Suction off", "s", 600.0, 0.0, 600.0, "Suction", "when it stops", K::Real},
        {"mass_extinction_m2_g", "Mass extinction coefficient", "m^2/g", 8.7, 0.1, 50.0, "View",
         "Beer-Lambert's K_m (8.7 m^2/g: Mulholland & Croarkin 2000)", K::Real},
        {"visible_transmittance", "Visibility threshold", "", 0.5, 0.01, 0.99, "View",
         "a pixel is obscured below this transmittance", K::Real},
        {"obscuration_every_s", "Obscuration sampling", "s", 0.1, 0.001, 10.0, "View",
         "interval of the obscuration curve", K::Real},
    };
}

SmokeSolver::SmokeSolver(SmokeScene scene) : m_scene(std::move(scene)) {}

void SmokeSolver::initialize(const SimulationInput&, const ParameterSet& parameters)
{
    SmokeSettings settings;
    settings.scheme = parameters.get("advection") > 0.5 ? AdvectionScheme::MacCormack : AdvectionScheme::SemiLagrangian;
    settings.buoyancyAlpha = kGravity / kAirDensity;
    settings.buoyancyBeta = kGravity / kAmbientK;
    settings.up = m_scene.up;
    settings.coolingPerS = parameters.get("cooling_per_s");
    settings.confinement = parameters.get("confinement");
    settings.particleStrength = parameters.get("particle_strength");
    settings.particleRadius = parameters.get("particle_radius_cells") * m_scene.grid.h;
    settings.tolerance = parameters.get("tolerance");
    settings.maxIterations = int(parameters.get("max_iterations"));
    settings.cfl = parameters.get("cfl");
    m_endTimeS = parameters.get("end_time_s");
    m_maxStepS = parameters.get("max_step_s");
    m_extinction = parameters.get("mass_extinction_m2_g") * 1e3; // m^2/kg
    m_tolerance = settings.tolerance, m_maxIterations = settings.maxIterations;
    m_suctionOnS = -1.0;
    m_visible = parameters.get("visible_transmittance");
    m_sampleEveryS = parameters.get("obscuration_every_s");
    m_simulation = std::make_unique<SmokeSimulation>(m_scene.grid, settings,
                                                     m_backendFactory ? m_backendFactory(m_scene.grid) : nullptr);
    SmokeSource source = m_scene.source;
    const double duration = parameters.get("source_duration_s");
    source.onsetS = parameters.get("source_onset_s");
    source.endS = source.onsetS + duration;
    source.temperatureK = parameters.get("source_temperature_k");
    source.velocity = parameters.get("source_speed_m_s") * m_scene.up;
    // The emission (kg/s) spread over the source's cells as a density rate (kg/m^3/s).
    const double volume = 4.0 / 3.0 * 3.141592653589793 * std::pow(source.radius, 3);
    source.densityRate = parameters.get("source_rate_mg_s") * 1e-6 / volume;
    source.particlesPerSecond = duration > 0.0 ? parameters.get("particles") / duration : 0.0;
    m_simulation->addSource(source);
    if (m_scene.ball)
        m_simulation->setSphere(*m_scene.ball);
    if (m_scene.suction && parameters.get("suction_l_min") > 0.0)
    {
        SmokeSuction suction = *m_scene.suction;
        suction.flowM3S = parameters.get("suction_l_min") / 60000.0;
        suction.onS = parameters.get("suction_on_s");
        suction.offS = parameters.get("suction_off_s");
        m_simulation->setSuction(suction);
        m_suctionOnS = suction.onS;
    }
    m_curve.clear();
    m_nextSampleS = 0.0;
    m_projections = m_iterations = 0;
    m_worstResidual = m_worstDivergence = 0.0;
    m_massAtSuctionMg = m_massAfter10sMg = -1.0;
    m_released = false;
    m_curve.emplace_back(0.0, view().obscuredFraction);
    m_nextSampleS = m_sampleEveryS;
}

double SmokeSolver::position() const
{
    return m_simulation ? m_simulation->time() : 0.0;
}

ObscurationView SmokeSolver::view() const
{
    return obscuration(m_simulation->grid(), m_scene.camera, m_extinction, m_visible);
}

StepOutcome SmokeSolver::step(RunStatus& status, const Progress&)
{
    SmokeSimulation& simulation = *m_simulation;
    if (m_scene.ball && !m_released && simulation.time() >= m_scene.ballReleaseS)
    {
        MovingSphere ball = *simulation.sphere();
        ball.falls = true;
        simulation.setSphere(ball);
        m_released = true;
    }
    const double dt = std::min(simulation.stableStep(m_maxStepS), m_endTimeS - simulation.time());
    const SmokeStepReport report = simulation.step(std::max(dt, 1e-9));
    m_lastStepS = report.dt;
    status.recordSolve(report.projection.iterations, report.projection.relativeResidual, m_tolerance, m_maxIterations);
    ++m_projections, m_iterations += report.projection.iterations;
    m_worstResidual = std::max(m_worstResidual, report.projection.relativeResidual);
    m_worstDivergence = std::max(m_worstDivergence, report.projection.divergenceRatio);
    if (!report.guard.empty())
        return StepOutcome::guard(report.guard);
    // The smoke present when the suction starts and 10 s later (Chou 2024's measure: the share removed in 10 s).
    const double massMg = m_suctionOnS >= 0.0 ? simulation.grid().smokeMass() * 1e6 : 0.0;
    if (m_suctionOnS >= 0.0 && m_massAtSuctionMg < 0.0 && simulation.time() >= m_suctionOnS)
        m_massAtSuctionMg = massMg;
    if (m_suctionOnS >= 0.0 && m_massAfter10sMg < 0.0 && simulation.time() >= m_suctionOnS + 10.0)
        m_massAfter10sMg = massMg;
    if (simulation.time() >= m_nextSampleS - 1e-9 || simulation.time() >= m_endTimeS - 1e-9)
    {
        m_curve.emplace_back(simulation.time(), view().obscuredFraction);
        m_nextSampleS += m_sampleEveryS;
    }
    return {};
}

SimulationData SmokeSolver::snapshot() const
{
    const SmokeGrid& grid = m_simulation->grid();
    GridFields frame;
    frame.geometry.dims = {grid.nx, grid.ny, grid.nz};
    frame.geometry.spacing = Eigen::Vector3d::Constant(grid.h * 1e3);
    frame.geometry.origin = (grid.origin + Eigen::Vector3d::Constant(0.5 * grid.h)) * 1e3; // the first cell's centre, mm
    RealVolume density(frame.geometry), temperature(frame.geometry);
    for (int k = 0; k < grid.nz; ++k)
        for (int j = 0; j < grid.ny; ++j)
            for (int i = 0; i < grid.nx; ++i)
            {
                const std::size_t c = grid.cell(i, j, k);
                density.at(i, j, k) = grid.density[c] * 1e6f; // kg/m^3 -> mg/m^3
                temperature.at(i, j, k) = grid.temperature[c];
            }
    frame.fields.emplace("smoke_density_mg_m3", std::move(density));
    frame.fields.emplace("temperature_rise_k", std::move(temperature));
    return frame;
}

std::map<std::string, double> SmokeSolver::metrics() const
{
    const SmokeGrid& grid = m_simulation->grid();
    std::map<std::string, double> m;
    m["smoke_mass_mg"] = grid.smokeMass() * 1e6;
    m["peak_density_mg_m3"] = 1e6 * double(*std::max_element(grid.density.begin(), grid.density.end()));
    m["vortex_particles"] = double(m_simulation->particles().size());
    m["obscured_fraction"] = m_curve.empty() ? 0.0 : m_curve.back().second;
    double peak = 0.0;
    for (const auto& sample : m_curve)
        peak = std::max(peak, sample.second);
    m["peak_obscured_fraction"] = peak;
    m["time_to_50_percent_obscuration_s"] = firstTimeReaching(m_curve, 0.5);
    m["time_to_90_percent_obscuration_s"] = firstTimeReaching(m_curve, 0.9);
    if (m_suctionOnS >= 0.0)
    {
        // Cleared: after the suction starts, the first sample under kClearLevel once the view was worse.
        double cleared = -1.0;
        bool wasObscured = false;
        for (const auto& [time, fraction] : m_curve)
        {
            if (time < m_suctionOnS)
                continue;
            wasObscured = wasObscured || fraction >= kClearLevel;
            if (wasObscured && fraction < kClearLevel)
            {
                cleared = time - m_suctionOnS;
                break;
            }
        }
        m["time_to_clear_s"] = cleared;
        if (m_massAtSuctionMg > 0.0 && m_massAfter10sMg >= 0.0)
            m["smoke_removed_in_10s_percent"] = 100.0 * (1.0 - m_massAfter10sMg / m_massAtSuctionMg);
    }
    m["mean_projection_iterations"] = m_projections ? double(m_iterations) / double(m_projections) : 0.0;
    m["worst_relative_residual"] = m_worstResidual;
    m["worst_divergence_ratio"] = m_worstDivergence;
    m["time_step_s"] = m_lastStepS;
    return m;
}

} // namespace vsim::sim::smoke
