#include "vsim/sim/smoke/PressureWarmStart.h"

namespace vsim::sim::smoke {
namespace {

constexpr double kLargestRatio = 2.0; // consecutive steps' lengths within this factor: extrapolate

bool comparable(double ratio)
{
    return ratio >= 1.0 / kLargestRatio && ratio <= kLargestRatio;
}

} // namespace

PressureWarmStart::Weights PressureWarmStart::weights(double stepS) const
{
    if (stepS <= 0.0 || m_lastS <= 0.0 || m_previousS <= 0.0)
        return {};
    const double s = stepS / m_lastS, sPrevious = m_lastS / m_previousS;
    if (!comparable(s) || !comparable(sPrevious))
        return {};
    return {float(s * (1.0 + s)), float(-s * s * sPrevious)};
}

void PressureWarmStart::record(double stepS)
{
    m_previousS = stepS > 0.0 ? m_lastS : 0.0;
    m_lastS = stepS > 0.0 ? stepS : 0.0;
}

} // namespace vsim::sim::smoke
