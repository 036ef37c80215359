#include "SphCases.h"

#include "vsim/core/Error.h"
#include "vsim/core/StoredText.h"
#include "vsim/sim/sph/FiniteParticleMethod.h"
#include "vsim/sim/sph/NeighbourGrid.h"
#include "vsim/sim/sph/QuarticKernel.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace vsim::sim::sph::detail {
namespace {

constexpr double kSpacingM = 1e-3;      // particle spacing of the cases (1 mm)
constexpr double kSmoothingRatio = 2.0; // h / spacing, as the solver's default

/// 4 pi integral_0^2h W(r) r^2 dr by 8-point Gauss-Legendre on [0, 2h] (exact for the degree-6 integrand).
double kernelIntegral(const QuarticKernel& kernel)
{
    static const double nodes[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290,
                                    -0.1834346424956498, 0.1834346424956498,  0.5255324099163290,
                                    0.7966664774136267,  0.9602898564975363};
    static const double weights[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873,
                                      0.3626837833783620, 0.3626837833783620, 0.3137066458778873,
                                      0.2223810344533745, 0.1012285362903763};
    const double half = kernel.smoothingLength(); // [0, 2h] = h (1 + t)
    double sum = 0.0;
    for (int k = 0; k < 8; ++k)
    {
        const double r = half * (1.0 + nodes[k]);
        sum += weights[k] * kernel.value(r) * r * r;
    }
    return 4.0 * std::numbers::pi * half * sum;
}

/// Largest |dW/dr - central difference| relative to max |dW/dr|, over r in (0, 2h).
double derivativeError(const QuarticKernel& kernel)
{
    const double h = kernel.smoothingLength(), step = 1e-6 * h;
    double worst = 0.0, largest = 0.0;
    for (int k = 1; k < 200; ++k)
    {
        const double r = 2.0 * h * k / 200.0;
        const double difference = (kernel.value(r + step) - kernel.value(r - step)) / (2.0 * step);
        worst = std::max(worst, std::abs(kernel.derivative(r) - difference));
        largest = std::max(largest, std::abs(kernel.derivative(r)));
    }
    return worst / largest;
}

/// Largest entry of |sum_j V_j (x_j - x_i) (x) grad_i W_ij - I| at a particle inside a cubic lattice.
double latticeMomentError(const QuarticKernel& kernel)
{
    const int reach = int(std::ceil(kernel.support() / kSpacingM)) + 1;
    Eigen::Matrix3d moment = Eigen::Matrix3d::Zero();
    const double volume = kSpacingM * kSpacingM * kSpacingM;
    for (int i = -reach; i <= reach; ++i)
        for (int j = -reach; j <= reach; ++j)
            for (int k = -reach; k <= reach; ++k)
            {
                const Eigen::Vector3d xj = kSpacingM * Eigen::Vector3d(i, j, k); // x_i at the origin
                moment += volume * xj * kernel.gradient(-xj).transpose();
            }
    return (moment - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
}

} // namespace

ValidationResult kernelCase()
{
    ValidationResult result;
    result.name = "sph-kernel";
    result.description = storedText("the 3D quartic kernel (h = 2 mm): its integral, W(2h), dW/dr against a central "
                                    "difference, and its first moment on a 1 mm particle lattice against the identity");
    const QuarticKernel kernel(kSmoothingRatio * kSpacingM);
    result.figures.push_back({"integral of W over space", kernelIntegral(kernel), 1.0, 1e-6, ""});
    result.figures.push_back(
        {"W(2h) / W(0)", kernel.value(kernel.support()) / kernel.value(0.0), 0.0, 1e-12, ""});
    result.figures.push_back({"W(2h - 1e-9 h) / W(0) (continuous at the support)",
                              kernel.value(kernel.support() * (1.0 - 5e-10)) / kernel.value(0.0), 0.0, 1e-12,
                              ""});
    result.figures.push_back(
        {"dW/dr against a central difference (relative)", derivativeError(kernel), 0.0, 1e-6, ""});
    result.figures.push_back(
        {"lattice first moment - identity (largest entry)", latticeMomentError(kernel), 0.0, 0.005, ""});
    return result;
}

namespace {

struct FpmErrors
{
    double fpmValue = 0.0, fpmGradient = 0.0, plainGradient = 0.0; ///< largest relative errors
    int evaluated = 0;
};

/// Jittered particles filling z >= 0 (the wall at z = 0: nothing below), the linear field f = 3 + g . x,
/// evaluated at the particles within 1 h of the wall and away from the block's other faces.
FpmErrors fpmNearWall(unsigned seed)
{
    const QuarticKernel kernel(kSmoothingRatio * kSpacingM);
    const Eigen::Vector3d g(200.0, -500.0, 700.0); // per m
    auto field = [&](const Eigen::Vector3d& x) { return 3.0 + g.dot(x); };
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> jitter(-0.2 * kSpacingM, 0.2 * kSpacingM);
    std::vector<Eigen::Vector3d> positions;
    const int n = 16; // across; half as deep: the evaluated particles see no other face within the support
    for (int k = 0; k < n / 2; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
            {
                Eigen::Vector3d x = kSpacingM * Eigen::Vector3d(i, j, k + 0.5);
                x += Eigen::Vector3d(jitter(random), jitter(random), jitter(random));
                x.z() = std::max(x.z(), 0.05 * kSpacingM); // stays on the fluid side of the wall
                positions.push_back(x);
            }
    NeighbourGrid grid(kernel.support());
    grid.build(positions);
    const double volume = kSpacingM * kSpacingM * kSpacingM;
    const double centre = 0.5 * (n - 1) * kSpacingM;
    FpmErrors errors;
    for (int i = 0; i < int(positions.size()); ++i)
    {
        const Eigen::Vector3d& xi = positions[std::size_t(i)];
        const bool nearWall = xi.z() < kernel.smoothingLength();
        const bool awayFromSides =
            std::max(std::abs(xi.x() - centre), std::abs(xi.y() - centre)) < centre - kernel.support();
        if (!nearWall || !awayFromSides)
            continue;
        FpmSystem fpm(kernel);
        PlainGradient plain(kernel, field(xi));
        fpm.add(Eigen::Vector3d::Zero(), volume, field(xi));
        grid.forEachNeighbour(positions, i,
                              [&](int j, const Eigen::Vector3d& rij, double)
                              {
                                  const double fj = field(positions[std::size_t(j)]);
                                  fpm.add(rij, volume, fj);
                                  plain.add(rij, volume, fj);
                              });
        const std::optional<CorrectedField> corrected = fpm.solve();
        if (!corrected)
            throw Error("sph-fpm: the moment matrix is singular at a particle next to the wall");
        errors.fpmValue =
            std::max(errors.fpmValue, std::abs(corrected->value - field(xi)) / std::abs(field(xi)));
        errors.fpmGradient = std::max(errors.fpmGradient, (corrected->gradient - g).norm() / g.norm());
        errors.plainGradient = std::max(errors.plainGradient, (plain.gradient() - g).norm() / g.norm());
        ++errors.evaluated;
    }
    if (errors.evaluated == 0)
        throw Error("sph-fpm: no particle next to the wall was evaluated");
    return errors;
}

} // namespace

ValidationResult fpmCase(const Progress& progress)
{
    ValidationResult result;
    result.name = "sph-fpm";
    const std::string description =
        storedText("the gradient of a linear field at jittered particles (1 mm, +-0.2 mm) within h of a wall, three "
                   "seeds: the first-order Finite Particle Method against the exact gradient, and plain SPH's error "
                   "beside it");
    FpmErrors worst;
    const unsigned seeds[] = {1, 2, 3};
    for (std::size_t s = 0; s < 3; ++s)
    {
        const FpmErrors errors = fpmNearWall(seeds[s]);
        worst.fpmValue = std::max(worst.fpmValue, errors.fpmValue);
        worst.fpmGradient = std::max(worst.fpmGradient, errors.fpmGradient);
        worst.plainGradient = std::max(worst.plainGradient, errors.plainGradient);
        worst.evaluated += errors.evaluated;
        progress.report(double(s + 1) / 3.0);
    }
    result.figures.push_back({"FPM gradient, largest relative error", worst.fpmGradient, 0.0, 1e-8, ""});
    result.figures.push_back({"FPM value, largest relative error", worst.fpmValue, 0.0, 1e-8, ""});
    // Plain SPH misses the cut-away half of the support: its error must be large (0.1 .. 1.9) for the case to
    // show anything.
    result.figures.push_back(
        {"plain SPH gradient, largest relative error (must be large)", worst.plainGradient, 1.0, 0.9, ""});
    result.description =
        storedText(Pattern{"%1 (%2 particles evaluated)", {description, std::to_string(worst.evaluated)}});
    return result;
}

} // namespace vsim::sim::sph::detail
