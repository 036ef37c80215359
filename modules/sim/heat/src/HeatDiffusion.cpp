#include "vsim/sim/heat/HeatDiffusion.h"

#include "vsim/core/Error.h"
#include "vsim/core/StoredText.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vsim::sim::heat {

std::vector<ParameterSpec> heatParameters()
{
    using K = ParameterSpec::Kind;
    return {
        {"diffusivity_mm2_s", "Thermal diffusivity", "mm^2/s", 0.14, 1e-4, 100.0, "Tissue",
         "soft tissue about 0.14 mm^2/s (Duck 1990, Physical Properties of Tissue)", K::Real},
        {"box_mm", "Cube edge", "mm", 20.0, 1.0, 1000.0, "Domain", "faces held at body temperature", K::Real},
        {"cells", "Cells per edge", "", 32, 4, 512, "Domain", "the grid has cells + 1 nodes per edge", K::Integer},
        {"amplitude_k", "Initial rise", "K", 10.0, 0.0, 100.0, "Domain",
         "peak of the initial temperature rise (the slowest mode)", K::Real},
        {"end_time_s", "End time", "s", 60.0, 0.0, 1e6, "Time", "simulated time", K::Real},
        {"time_step_fraction", "Time step", "of h^2/(6D)", 0.9, 0.01, 2.0, "Time",
         "the step as a fraction of forward Euler's stability limit; above 1 the scheme is unstable and the guard "
         "stops the run", K::Real},
    };
}

void HeatDiffusionSolver::initialize(const SimulationInput& input, const ParameterSet& parameters)
{
    if (!input.data.empty())
        throw Error("the heat solver takes no input (its cube comes from the parameters)");
    const int cells = int(parameters.get("cells"));
    m_nodes = cells + 1;
    m_spacingM = parameters.get("box_mm") / cells * 1e-3;
    m_diffusivityM2S = parameters.get("diffusivity_mm2_s") * 1e-6;
    m_amplitudeK = parameters.get("amplitude_k");
    m_endTimeS = parameters.get("end_time_s");
    m_stepS = parameters.get("time_step_fraction") * m_spacingM * m_spacingM / (6.0 * m_diffusivityM2S);
    m_timeS = 0.0;
    m_rise.assign(std::size_t(m_nodes) * m_nodes * m_nodes, 0.0);
    for (int k = 0; k < m_nodes; ++k)
        for (int j = 0; j < m_nodes; ++j)
            for (int i = 0; i < m_nodes; ++i)
                m_rise[index(i, j, k)] = exact(i, j, k, 0.0);
    m_next = m_rise;
    m_limitK = *std::max_element(m_rise.begin(), m_rise.end());
}

double HeatDiffusionSolver::exact(int i, int j, int k, double timeS) const
{
    const double cells = m_nodes - 1, pi = std::numbers::pi;
    const double box = cells * m_spacingM;
    return m_amplitudeK * std::exp(-3.0 * pi * pi * m_diffusivityM2S * timeS / (box * box)) * std::sin(pi * i / cells) *
           std::sin(pi * j / cells) * std::sin(pi * k / cells);
}

StepOutcome HeatDiffusionSolver::step(RunStatus&, const Progress&)
{
    const double dt = std::min(m_stepS, m_endTimeS - m_timeS);
    const double c = dt * m_diffusivityM2S / (m_spacingM * m_spacingM);
    const int n = m_nodes;
    const std::ptrdiff_t sx = 1, sy = n, sz = std::ptrdiff_t(n) * n;
    double highest = 0.0;
    std::size_t where = 0;
    for (int k = 1; k < n - 1; ++k)
        for (int j = 1; j < n - 1; ++j)
            for (int i = 1; i < n - 1; ++i)
            {
                const std::size_t p = index(i, j, k);
                const double* t = m_rise.data() + p;
                const double laplacian = t[-sx] + t[sx] + t[-sy] + t[sy] + t[-sz] + t[sz] - 6.0 * t[0];
                m_next[p] = t[0] + c * laplacian;
                if (std::abs(m_next[p]) > highest || !std::isfinite(m_next[p]))
                    highest = std::isfinite(m_next[p]) ? std::abs(m_next[p]) : INFINITY, where = p;
            }
    if (!(highest <= m_limitK * (1.0 + 1e-9)))
    {
        const int i = int(where % std::size_t(n)), j = int(where / std::size_t(n) % std::size_t(n)),
                  k = int(where / (std::size_t(n) * std::size_t(n)));
        return StepOutcome::guard(storedText(Pattern{
            "at t = %1 s the temperature rise at node (%2, %3, %4) reached %5 K, above the initial maximum %6 K: the "
            "explicit step is unstable (time step %7 s; the stability limit is h^2/(6D) = %8 s)",
            {numberText(m_timeS + dt), std::to_string(i), std::to_string(j), std::to_string(k), numberText(highest),
             numberText(m_limitK), numberText(dt), numberText(m_spacingM * m_spacingM / (6.0 * m_diffusivityM2S))}}));
    }
    m_rise.swap(m_next);
    m_timeS += dt;
    return {};
}

SimulationData HeatDiffusionSolver::snapshot() const
{
    GridFields grid;
    grid.geometry.dims = {m_nodes, m_nodes, m_nodes};
    grid.geometry.spacing = Eigen::Vector3d::Constant(m_spacingM * 1e3);
    RealVolume rise(grid.geometry);
    std::transform(m_rise.begin(), m_rise.end(), rise.data(), [](double t) { return float(t); });
    grid.fields.emplace("temperature_rise_k", rise);
    return grid;
}

std::map<std::string, double> HeatDiffusionSolver::metrics() const
{
    double error = 0.0, norm = 0.0;
    for (int k = 0; k < m_nodes; ++k)
        for (int j = 0; j < m_nodes; ++j)
            for (int i = 0; i < m_nodes; ++i)
            {
                const double truth = exact(i, j, k, m_timeS);
                error += (m_rise[index(i, j, k)] - truth) * (m_rise[index(i, j, k)] - truth), norm += truth * truth;
            }
    return {{"peak_temperature_rise_k", *std::max_element(m_rise.begin(), m_rise.end())},
            {"analytic_peak_temperature_rise_k", exact(m_nodes / 2, m_nodes / 2, m_nodes / 2, m_timeS)},
            {"relative_l2_error", norm > 0.0 ? std::sqrt(error / norm) : 0.0},
            {"time_step_s", m_stepS}};
}

} // namespace vsim::sim::heat
