#include "BlurredDisc.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace vsim::imaging::detail {
namespace {

constexpr double kStep = 0.05;       // table spacing in r / sigma and rho / sigma
constexpr double kLargestRadius = 30.0; // r / sigma beyond this: the plane edge
constexpr double kLargestRho = kLargestRadius + 8.0;
constexpr int kRadii = int(kLargestRadius / kStep) + 1, kRhos = int(kLargestRho / kStep) + 1;

/// exp(-z) I0(z), the exponentially scaled modified Bessel function of order 0 (Abramowitz & Stegun 9.7.1 beyond 40).
double scaledBesselI0(double z)
{
    if (z < 40.0)
        return std::exp(-z) * std::cyl_bessel_i(0.0, z);
    const double inverse = 1.0 / (8.0 * z);
    return (1.0 + inverse * (1.0 + 4.5 * inverse * (1.0 + 25.0 / 3.0 * inverse))) / std::sqrt(2.0 * std::numbers::pi * z);
}

/// The Rice density at x for nu = b (both in units of sigma): x exp(-(x - b)^2 / 2) I0e(x b).
double riceDensity(double x, double b)
{
    return x * std::exp(-0.5 * (x - b) * (x - b)) * scaledBesselI0(x * b);
}

/// F[b][a]: the Rice distribution's cumulative at a for nu = b, on the kStep grid (Simpson on half steps, summed
/// along a).
std::vector<double> buildTable()
{
    std::vector<double> table(std::size_t(kRadii) * std::size_t(kRhos));
    for (int ib = 0; ib < kRhos; ++ib)
    {
        const double b = ib * kStep;
        double* row = table.data() + std::size_t(ib) * std::size_t(kRadii);
        row[0] = 0.0;
        for (int ia = 1; ia < kRadii; ++ia)
        {
            const double a0 = (ia - 1) * kStep, a1 = ia * kStep;
            const double piece = kStep / 6.0 * (riceDensity(a0, b) + 4.0 * riceDensity(0.5 * (a0 + a1), b) + riceDensity(a1, b));
            row[ia] = std::min(1.0, row[ia - 1] + piece);
        }
    }
    return table;
}

} // namespace

double blurredDiscOccupancy(double rhoMm, double radiusMm, double sigmaMm)
{
    const double a = radiusMm / sigmaMm, b = rhoMm / sigmaMm;
    if (a >= kLargestRadius)
        return 0.5 * std::erfc((b - a) / std::numbers::sqrt2);
    if (b >= kLargestRho)
        return 0.0;
    static const std::vector<double> table = buildTable();
    const double fa = a / kStep, fb = b / kStep;
    const int ia = std::min(int(fa), kRadii - 2), ib = std::min(int(fb), kRhos - 2);
    const double ta = fa - ia, tb = fb - ib;
    const auto at = [&](int i, int j) { return table[std::size_t(j) * std::size_t(kRadii) + std::size_t(i)]; };
    return (1.0 - tb) * ((1.0 - ta) * at(ia, ib) + ta * at(ia + 1, ib)) + tb * ((1.0 - ta) * at(ia, ib + 1) + ta * at(ia + 1, ib + 1));
}

} // namespace vsim::imaging::detail
