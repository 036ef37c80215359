#include "vsim/sim/network/ConicalPipe.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace vsim::sim::network {

double conicalResistance(double r1, double r2, double length, double viscosity)
{
    const double shape = (1.0 / (r1 * r2 * r2 * r2) + 1.0 / (r1 * r1 * r2 * r2) + 1.0 / (r1 * r1 * r1 * r2)) / 3.0;
    return 8.0 * viscosity * length / std::numbers::pi * shape;
}

namespace {

/// The integral over the cone's length of f(R(x)) (eq. 6.5: R linear in x), by composite 8-point Gauss-Legendre.
template <typename F> double alongCone(double r1, double r2, double length, int panels, F f)
{
    // 8-point Gauss-Legendre nodes and weights on [-1, 1].
    static constexpr std::array<double, 4> kNodes{0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                                  0.9602898564975363};
    static constexpr std::array<double, 4> kWeights{0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                                    0.1012285362903763};
    const double h = length / panels;
    double sum = 0.0;
    for (int p = 0; p < panels; ++p)
    {
        const double centre = (p + 0.5) * h;
        for (std::size_t k = 0; k < kNodes.size(); ++k)
            for (double side : {-1.0, 1.0})
            {
                const double x = centre + side * 0.5 * h * kNodes[k];
                sum += kWeights[k] * 0.5 * h * f(r1 + (r2 - r1) * x / length);
            }
    }
    return sum;
}

} // namespace

double integratedResistance(double r1, double r2, double length, double viscosity, int panels)
{
    return 8.0 * viscosity / std::numbers::pi * alongCone(r1, r2, length, panels, [](double r) { return 1.0 / (r * r * r * r); });
}

double annularResistance(double r1, double r2, double a, double length, double viscosity, int panels)
{
    if (!(a > 0.0))
        return conicalResistance(r1, r2, length, viscosity);
    if (a >= std::min(r1, r2))
        return std::numeric_limits<double>::infinity();
    const auto conductance = [a](double r) { // R^4 - a^4 - (R^2 - a^2)^2 / ln(R / a), in long double: the bracket
        const long double R2 = (long double)r * r, a2 = (long double)a * a; // cancels as the gap closes
        return double((R2 - a2) * ((R2 + a2) - (R2 - a2) / std::log((long double)r / a)));
    };
    return 8.0 * viscosity / std::numbers::pi * alongCone(r1, r2, length, panels, [&](double r) { return 1.0 / conductance(r); });
}

double conicalVolume(double r1, double r2, double length, double x)
{
    const double slope = (r2 - r1) / length;
    return std::numbers::pi * (r1 * r1 * x + r1 * slope * x * x + slope * slope * x * x * x / 3.0);
}

double filledLength(double r1, double r2, double length, double volume)
{
    const double total = conicalVolume(r1, r2, length, length);
    if (volume <= 0.0)
        return 0.0;
    if (volume >= total)
        return length;
    double x = length * volume / total; // exact for a cylinder
    for (int iteration = 0; iteration < 30; ++iteration)
    {
        const double r = r1 + (r2 - r1) * x / length;
        const double step = (conicalVolume(r1, r2, length, x) - volume) / (std::numbers::pi * r * r);
        x = std::clamp(x - step, 0.0, length);
        if (std::abs(step) <= 1e-14 * length)
            break;
    }
    return x;
}

} // namespace vsim::sim::network
