#include "vsim/sim/sph/WallShear.h"

#include "vsim/core/Error.h"
#include "vsim/sim/sph/SphRates.h"

#include <Eigen/Dense>

#include <cmath>

namespace vsim::sim::sph {
namespace {

constexpr double kPressureDepthSpacings = 3.0; // the pressure's line reaches this deep into the fluid
constexpr double kLateralSpacings = 1.5;       // the columns' radius along the wall

} // namespace

WallLoad wallLoad(const ParticleState& particles, const NeighbourGrid& grid, const QuarticKernel& kernel,
                  const FluidModel& fluid, double spacingM, const WallPoint& point)
{
    // The friction over the column a support deep; the pressure's line p = p0 + c y (normal equations in (p0, c))
    // over its first 3 spacings.
    const double deepest = kernel.support(), pressureDepth = kPressureDepthSpacings * spacingM;
    const double widest = kLateralSpacings * spacingM;
    const Eigen::Vector3d& n = point.normal;
    Eigen::Vector3d friction = Eigen::Vector3d::Zero();
    double volume = 0.0;
    Eigen::Matrix2d pressureNormal = Eigen::Matrix2d::Zero();
    Eigen::Vector2d pressureRight = Eigen::Vector2d::Zero();
    grid.forEachNear(particles.position, grid.wrap(point.positionM + 0.5 * deepest * n), -1,
                     [&](int j, const Eigen::Vector3d& rij, double) {
                         const std::size_t k = std::size_t(j);
                         if (!particles.isFluid(k))
                             return;
                         const Eigen::Vector3d offset = 0.5 * deepest * n - rij; // x_j - the wall point
                         const double y = offset.dot(n);
                         if (!(y > 0.0) || y > deepest || (offset - y * n).norm() > widest)
                             return;
                         friction += particles.mass[k] * wallFrictionAcceleration(particles, grid, kernel, fluid, k);
                         volume += particles.mass[k] / particles.density[k];
                         if (y > pressureDepth)
                             return;
                         const Eigen::Vector2d affine(1.0, y / spacingM); // in spacings: well scaled
                         pressureNormal += affine * affine.transpose();
                         pressureRight +=
                             affine * fluid.reportedPressure(particles.density[k], particles.voidFraction[k]);
                     });
    WallLoad load;
    // The line needs particles at two depths at least (the lattice gives three layers).
    if (!(volume > 0.0) || !(std::abs(pressureNormal.determinant()) > 1e-12 * pressureNormal.squaredNorm()))
        return load;
    load.shearPa = -(friction - friction.dot(n) * n) / (volume / deepest);
    load.pressurePa = pressureNormal.ldlt().solve(pressureRight)[0];
    load.valid = true;
    return load;
}

void WallLoadSeries::sample(const ParticleState& particles, const NeighbourGrid& grid, const QuarticKernel& kernel,
                            const FluidModel& fluid, double spacingM, double timeS, double weightS)
{
    const double weight = m_points.empty() ? 0.0 : m_schedule.due(timeS, weightS);
    if (!(weight > 0.0))
        return;
    if (m_sums.empty())
        m_sums.resize(m_points.size());
#pragma omp parallel for schedule(dynamic, 16)
    for (std::ptrdiff_t k = 0; k < std::ptrdiff_t(m_points.size()); ++k)
    {
        const WallLoad load = wallLoad(particles, grid, kernel, fluid, spacingM, m_points[std::size_t(k)]);
        if (!load.valid)
            continue;
        WallLoadAverage& sum = m_sums[std::size_t(k)];
        sum.tawssPa += weight * load.shearPa.norm();
        sum.meanShearPa += weight * load.shearPa;
        sum.meanPressurePa += weight * load.pressurePa;
        sum.largestShearPa = std::max(sum.largestShearPa, load.shearPa.norm());
        sum.sampledTimeS += weight;
    }
}

std::vector<WallLoadAverage> WallLoadSeries::averages() const
{
    std::vector<WallLoadAverage> averages(m_points.size());
    for (std::size_t k = 0; k < m_sums.size(); ++k)
    {
        const WallLoadAverage& sum = m_sums[k];
        if (!(sum.sampledTimeS > 0.0))
            continue;
        WallLoadAverage& a = averages[k];
        a.sampledTimeS = sum.sampledTimeS;
        a.tawssPa = sum.tawssPa / sum.sampledTimeS;
        a.meanShearPa = sum.meanShearPa / sum.sampledTimeS;
        a.meanPressurePa = sum.meanPressurePa / sum.sampledTimeS;
        a.largestShearPa = sum.largestShearPa;
        a.osi = a.tawssPa > 0.0 ? 0.5 * (1.0 - a.meanShearPa.norm() / a.tawssPa) : 0.0;
    }
    return averages;
}

void WallLoadSeries::restore(Sums sums)
{
    if (!sums.points.empty() && sums.points.size() != m_points.size())
        throw Error(Pattern{"the saved wall-load averages are for %1 points, this run has %2",
                            {std::to_string(sums.points.size()), std::to_string(m_points.size())}});
    m_schedule.restore(sums.schedule);
    m_sums = std::move(sums.points);
}

} // namespace vsim::sim::sph
