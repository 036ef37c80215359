#include "vsim/sim/sph/FluidModel.h"

#include <cmath>

namespace vsim::sim::sph {

double FluidModel::pressure(double density) const
{
    return stiffness() * (std::pow(density / restDensity, gamma) - 1.0);
}

double FluidModel::densityAt(double pressurePa) const
{
    return restDensity * std::pow(1.0 + pressurePa / stiffness(), 1.0 / gamma);
}

} // namespace vsim::sim::sph
