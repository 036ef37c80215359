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
        throw Error("Young's modulus must be positive (" + std::to_string(youngModulusPa) + " Pa given)");
    if (!(poissonRatio > -1.0 && poissonRatio < 0.5))
        throw Error("Poisson's ratio must lie in (-1, 0.5) (" + std::to_string(poissonRatio) + " given)");
    if (!(densityKgPerM3 > 0.0) || !std::isfinite(densityKgPerM3))
        throw Error("the density must be positive (" + std::to_string(densityKgPerM3) + " kg/m^3 given)");
}

} // namespace vsim::sim::fem
