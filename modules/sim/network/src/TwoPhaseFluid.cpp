#include "vsim/sim/network/TwoPhaseFluid.h"

#include "vsim/core/Error.h"

#include <cmath>
#include <string>

namespace vsim::sim::network {

double TwoPhaseMixture::density() const
{
    return phases.liquidDensity * (1.0 - voidFraction) + phases.gasDensity * voidFraction;
}

double TwoPhaseMixture::viscosity() const
{
    return voidFraction * phases.gasViscosity + (1.0 - voidFraction) * phases.liquidViscosity;
}

void TwoPhaseMixture::validate() const
{
    if (!(voidFraction >= 0.0 && voidFraction < 1.0))
        throw Error(Pattern{"the void fraction must be in [0, 1), not %1", {std::to_string(voidFraction)}},
                    {{"parameter", "void_fraction"}});
    for (double value : {phases.liquidDensity, phases.gasDensity, phases.liquidViscosity, phases.gasViscosity})
        if (!(value > 0.0) || !std::isfinite(value))
            throw Error("phase densities and viscosities must be positive");
}

} // namespace vsim::sim::network
