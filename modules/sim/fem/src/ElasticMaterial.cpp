#include "vsim/sim/fem/ElasticMaterial.h"

#include "vsim/core/Error.h"

#include <cmath>
#include <string>

namespace vsim::sim::fem {

double ElasticMaterial::lambda() const
{
    return youngModulusPa * poissonRatio / ((1.0 + poissonRatio) * (1.0 - 2.0 * poissonRatio));
}

double ElasticMaterial::mu() const { return youngModulusPa / (2.0 * (1.0 + poissonRatio)); }

Eigen::Matrix<double, 6, 6> ElasticMaterial::elasticityMatrix() const
{
    const double l = lambda(), m = mu();
    Eigen::Matrix<double, 6, 6> d = Eigen::Matrix<double, 6, 6>::Zero();
    d.topLeftCorner<3, 3>().setConstant(l);
    for (int i = 0; i < 3; ++i)
    {
        d(i, i) = l + 2.0 * m;
        d(i + 3, i + 3) = m;
    }
    return d;
}

void ElasticMaterial::validate() const
{
    if (!(youngModulusPa > 0.0) || !std::isfinite(youngModulusPa))
        throw Error(Pattern{"Young's modulus must be positive (%1 Pa given)", {std::to_string(youngModulusPa)}});
    if (!(poissonRatio > -1.0 && poissonRatio < 0.5))
        throw Error(Pattern{"Poisson's ratio must lie in (-1, 0.5) (%1 given)", {std::to_string(poissonRatio)}});
    if (!(densityKgPerM3 > 0.0) || !std::isfinite(densityKgPerM3))
        throw Error(Pattern{"the density must be positive (%1 kg/m^3 given)", {std::to_string(densityKgPerM3)}});
}

} // namespace vsim::sim::fem
