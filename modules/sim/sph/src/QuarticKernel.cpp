#include "vsim/sim/sph/QuarticKernel.h"

#include "vsim/core/Error.h"

#include <cmath>
#include <numbers>

namespace vsim::sim::sph {

QuarticKernel::QuarticKernel(double smoothingLengthM)
    : m_h(smoothingLengthM),
      m_norm(315.0 / (208.0 * std::numbers::pi * smoothingLengthM * smoothingLengthM * smoothingLengthM))
{
    if (!(smoothingLengthM > 0.0) || !std::isfinite(smoothingLengthM))
        throw Error("the SPH smoothing length must be a positive length");
}

double QuarticKernel::value(double r) const
{
    const double q = r / m_h;
    if (q >= 2.0)
        return 0.0;
    // The factored form (QuarticKernel.h): exactly 0 at q = 2 and of the right (negative) sign just inside it. The
    // expanded polynomial cancels there to a rounding error of either sign, and a wall particle exactly 2h from the
    // fluid (a lattice's fourth layer) took the fluid's pressure or kept its own by that sign.
    const double a = 2.0 - q;
    return m_norm * a * a * (1.0 / 6.0 + q / 6.0 - 5.0 / 32.0 * q * q);
}

double QuarticKernel::derivative(double r) const
{
    const double q = r / m_h;
    if (q >= 2.0)
        return 0.0;
    return m_norm / m_h * q * 0.625 * (2.0 - q) * (q - 1.8); // -9/4 + 19/8 q - 5/8 q^2, factored: 0 at q = 2
}

Eigen::Vector3d QuarticKernel::gradient(const Eigen::Vector3d& rij) const
{
    const double r = rij.norm();
    if (r <= 0.0 || r >= 2.0 * m_h)
        return Eigen::Vector3d::Zero();
    return derivative(r) / r * rij;
}

double QuarticKernel::latticeSum(double spacingM) const
{
    const int reach = int(std::ceil(support() / spacingM));
    double sum = 0.0;
    for (int x = -reach; x <= reach; ++x)
        for (int y = -reach; y <= reach; ++y)
            for (int z = -reach; z <= reach; ++z)
                sum += value(spacingM * std::sqrt(double(x * x + y * y + z * z)));
    return sum;
}

} // namespace vsim::sim::sph
