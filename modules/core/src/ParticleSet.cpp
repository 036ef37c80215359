#include "vsim/core/ParticleSet.h"

#include "vsim/core/Error.h"

#include <cmath>
#include <numeric>
#include <string>

namespace vsim {

void ParticleSet::resize(std::size_t count)
{
    positions.resize(count, Eigen::Vector3d::Zero());
    velocities.resize(count, Eigen::Vector3d::Zero());
    masses.resize(count, 0.0);
    densities.resize(count, 0.0);
}

double ParticleSet::totalMass() const
{
    return std::accumulate(masses.begin(), masses.end(), 0.0);
}

void ParticleSet::validate() const
{
    const std::size_t count = positions.size();
    if (velocities.size() != count || masses.size() != count || densities.size() != count)
        throw Error("particle arrays differ in length");
    for (std::size_t p = 0; p < count; ++p)
        if (!positions[p].allFinite() || !velocities[p].allFinite() || !std::isfinite(masses[p]) || masses[p] < 0.0 ||
            !std::isfinite(densities[p]))
            throw Error("particle has a non-finite or negative value", {{"particle", std::to_string(p)}});
}

} // namespace vsim
