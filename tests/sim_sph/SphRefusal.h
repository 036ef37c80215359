#pragma once

// What SphSolver::initialize says to a set of parameters on two fluid particles (and their fields besides
// 'wall'): the error's message, or "" when it takes them (the SPH tests' check that a combination of options,
// or an input, is refused with its reason).

#include "vsim/core/Error.h"
#include "vsim/sim/sph/SphSolver.h"

#include <map>
#include <string>
#include <vector>

namespace vsim::test {

inline std::string sphRefusal(const std::map<std::string, double>& settings,
                              const std::map<std::string, std::vector<double>>& moreFields = {})
{
    ParticleSet particles;
    particles.positionsMm = {Eigen::Vector3d::Zero(), Eigen::Vector3d(0.5, 0.0, 0.0)};
    particles.fields["wall"] = {0.0, 0.0};
    particles.fields.insert(moreFields.begin(), moreFields.end());
    ParameterSet parameters(sim::sph::sphParameters());
    for (const auto& [name, value] : settings)
        parameters.set(name, value);
    SimulationInput input;
    input.data["particles"] = particles;
    sim::sph::SphSolver solver;
    try
    {
        solver.initialize(input, parameters);
    }
    catch (const Error& error)
    {
        return error.message();
    }
    return {};
}

} // namespace vsim::test
