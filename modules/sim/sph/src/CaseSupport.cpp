#include "SphCases.h"

#include "vsim/core/Error.h"

namespace vsim::sim::sph::detail {

ParameterSet caseParameters(double spacingMm, double density, double viscosity, double soundSpeed)
{
    ParameterSet parameters(sphParameters());
    parameters.set("spacing_mm", spacingMm);
    parameters.set("density_kg_m3", density);
    parameters.set("viscosity_pa_s", viscosity);
    parameters.set("sound_speed_m_s", soundSpeed);
    return parameters;
}

SolverRun runCase(const std::string& caseName, SphSolver& solver, ParticleSet particles, const ParameterSet& parameters,
                  const Progress& progress, RunControl control)
{
    SimulationInput input;
    input.data["particles"] = std::move(particles);
    control.keepFramesInMemory = false;
    SolverRun run = runSolver(solver, input, parameters, control, progress);
    if (!run.status.complete())
        throw Error(caseName + ": the run stopped: " + run.status.stopText());
    return run;
}

} // namespace vsim::sim::sph::detail
