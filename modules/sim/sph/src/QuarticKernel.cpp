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
    const double q2 = q * q;
    return m_norm * (2.0 / 3.0 - 9.0 / 8.0 * q2 + 19.0 / 24.0 * q2 * q - 5.0 / 32.0 * q2 * q2);
}

double QuarticKernel::derivative(double r) const
{
    const double q = r / m_h;
    if (q >= 2.0)
        return 0.0;
    return m_norm / m_h * q * (-9.0 / 4.0 + 19.0 / 8.0 * q - 5.0 / 8.0 * q * q);
}

Eigen::Vector3d QuarticKernel::gradient(const Eigen::Vector3d& rij) const
{
    const double r = rij.norm();
    if (r <= 0.0 || r >= 2.0 * m_h)
        return Eigen::Vector3d::Zero();
    return derivative(r) / r * rij;
}

} // namespace vsim::sim::sph
