#include "vsim/sim/sph/FluidModel.h"

#include <cmath>
#include <numbers>

namespace vsim::sim::sph {

double FluidModel::pressure(double density, double voidFraction) const
{
    const double tait = stiffness(voidFraction) * (std::pow(density / mixtureDensity(voidFraction), gamma) - 1.0);
    return tension ? tait : std::max(tait, 0.0);
}

double FluidModel::densityAt(double pressurePa, double voidFraction) const
{
    return mixtureDensity(voidFraction) * std::pow(1.0 + pressurePa / stiffness(voidFraction), 1.0 / gamma);
}

Eigen::Vector3d FluidModel::externalAcceleration(double timeS) const
{
    const double oscillation = bodyForceFrequency > 0.0 ? std::cos(2.0 * std::numbers::pi * bodyForceFrequency * timeS) : 1.0;
    return gravity + oscillation * bodyForce;
}

} // namespace vsim::sim::sph
