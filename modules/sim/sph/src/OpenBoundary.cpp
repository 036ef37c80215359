#include "vsim/sim/sph/OpenBoundary.h"

#include "vsim/core/Error.h"
#include "vsim/core/Parameters.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vsim::sim::sph {

double Waveform::factorAt(double timeS) const
{
    if (points.empty())
        return 1.0;
    if (points.size() == 1 || !(period() > 0.0))
        return points.front().second;
    const double t = timeS - period() * std::floor(timeS / period());
    const auto after = std::upper_bound(points.begin(), points.end(), t,
                                        [](double value, const std::pair<double, double>& p) { return value < p.first; });
    if (after == points.begin())
        return after->second;
    if (after == points.end())
        return points.back().second;
    const auto before = after - 1;
    const double share = (t - before->first) / std::max(after->first - before->first, 1e-300);
    return before->second + share * (after->second - before->second);
}

long double MassLedger::totalInflow() const
{
    long double sum = 0.0;
    for (long double kg : inflowKg)
        sum += kg;
    return sum;
}

long double MassLedger::totalOutflow() const
{
    long double sum = 0.0;
    for (long double kg : outflowKg)
        sum += kg;
    return sum;
}

bool OpenBoundaries::withinDisk(std::size_t k, const Eigen::Vector3d& x) const
{
    const OpenBoundary& b = m_boundaries[k];
    const Eigen::Vector3d offset = x - b.centreM;
    return (offset - offset.dot(b.normal) * b.normal).squaredNorm() <= b.radiusM * b.radiusM;
}

double OpenBoundaries::shape(std::size_t k, const Eigen::Vector3d& x) const
{
    if (!m_boundaries[k].parabolic)
        return 1.0;
    const Eigen::Vector3d offset = x - m_boundaries[k].centreM;
    const double r2 = (offset - offset.dot(m_boundaries[k].normal) * m_boundaries[k].normal).squaredNorm();
    return std::max(0.0, 1.0 - r2 / (m_equivalentRadius[k] * m_equivalentRadius[k]));
}

double rampFactor(double timeS, double rampS)
{
    return rampS > 0.0 && timeS < rampS ? 0.5 * (1.0 - std::cos(std::numbers::pi * timeS / rampS)) : 1.0;
}

double OpenBoundaries::prescribedFlowRate(std::size_t k, double timeS) const
{
    const OpenBoundary& b = m_boundaries[k];
    return b.flowRateM3S * rampFactor(timeS, b.rampS) * b.waveform.factorAt(timeS);
}

double OpenBoundaries::prescribedPressure(std::size_t k, double timeS, double flowRate) const
{
    const OpenBoundary& b = m_boundaries[k];
    return b.pressurePa * b.waveform.factorAt(timeS) + b.resistancePaSM3 * -flowRate - m_referencePa; // on the outflow
}

void OpenBoundaries::initialize(const ParticleState& particles, double depthM, double spacingM)
{
    const std::size_t count = m_boundaries.size();
    m_depthM = depthM;
    m_calibration.assign(count, 0.0);
    m_equivalentRadius.assign(count, 0.0);
    m_flowRate.assign(count, 0.0);
    m_pressure.assign(count, 0.0);
    for (const OpenBoundary& b : m_boundaries)
        if (std::abs(b.normal.norm() - 1.0) > 1e-9 || !(b.radiusM > 0.0))
            throw Error(Pattern{"the open boundary '%1' needs a unit normal and a positive radius", {b.name}});
    const double volume = spacingM * spacingM * spacingM;
    std::vector<double> buffered(count, 0.0);
    for (std::size_t i = 0; i < particles.size(); ++i)
        if (particles.boundary[i])
        {
            if (particles.boundary[i] > count)
                throw Error(Pattern{"a buffer particle names open boundary %1 of %2",
                                    {std::to_string(particles.boundary[i]), std::to_string(count)}});
            buffered[particles.boundary[i] - 1u] += 1.0;
        }
    for (std::size_t k = 0; k < count; ++k)
    {
        if (buffered[k] == 0.0)
            throw Error(Pattern{"the open boundary '%1' has no buffer particles behind it", {m_boundaries[k].name}});
        m_equivalentRadius[k] = std::sqrt(buffered[k] * volume / depthM / std::numbers::pi);
    }
    for (std::size_t i = 0; i < particles.size(); ++i)
        if (particles.boundary[i])
            m_calibration[particles.boundary[i] - 1u] += shape(particles.boundary[i] - 1u, particles.position[i]) * volume / depthM;
}

void OpenBoundaries::checkBufferDepths(const ParticleState& particles, double depthM, double spacingM) const
{
    // The calibration divides the buffer's volume by the depth: a buffer of another depth than the kernel's support
    // (seeded for another smoothing ratio) would scale the imposed inflow by their ratio. A buffer seeded a support
    // deep on a lattice has its deepest particle within a spacing of that depth.
    std::vector<double> deepest(m_boundaries.size(), 0.0);
    for (std::size_t i = 0; i < particles.size(); ++i)
        if (particles.boundary[i] && particles.boundary[i] <= m_boundaries.size())
        {
            const std::size_t k = particles.boundary[i] - 1u;
            deepest[k] = std::max(deepest[k], -signedDistance(k, particles.position[i]));
        }
    for (std::size_t k = 0; k < m_boundaries.size(); ++k)
        if (deepest[k] > depthM + 1e-9 * depthM || deepest[k] < depthM - spacingM - 1e-9 * depthM)
            throw Error(Pattern{"the open boundary '%1' has buffer particles down to %2 mm behind its plane, and its "
                                "buffer must be as deep as the kernel's support, %3 mm (2 x the smoothing ratio x "
                                "the spacing): seed it for this smoothing ratio",
                                {m_boundaries[k].name, numberText(1e3 * deepest[k]), numberText(1e3 * depthM)}});
}

void OpenBoundaries::exchange(ParticleState& particles, int& nextId, MassLedger& ledger) const
{
    const std::size_t n = particles.size();
    std::vector<std::uint8_t> keep(n, 1);
    for (std::size_t i = 0; i < n; ++i)
    {
        if (particles.wall[i])
            continue;
        if (particles.boundary[i])
        {
            const std::size_t k = particles.boundary[i] - 1u;
            const double s = signedDistance(k, particles.position[i]);
            if (s >= 0.0) // into the domain: fluid now, and the buffer refilled a depth behind it
            {
                particles.boundary[i] = 0;
                ledger.inflowKg[k] += particles.mass[i];
                particles.appendCopy(i, particles.position[i] - m_depthM * m_boundaries[k].normal, nextId++);
                particles.boundary.back() = std::uint8_t(k + 1);
                particles.tracer.back() = m_boundaries[k].tracer ? 1 : 0;
                keep.push_back(1);
            }
            else if (s < -m_depthM) // out of the buffer's far end: it left the domain when it entered the buffer
                keep[i] = 0;
            continue;
        }
        for (std::size_t k = 0; k < m_boundaries.size(); ++k)
            if (signedDistance(k, particles.position[i]) < 0.0 && withinDisk(k, particles.position[i]))
            {
                const OpenBoundary& b = m_boundaries[k];
                const bool joins = b.prescribed == OpenBoundary::Prescribed::Pressure || b.flowRateM3S < 0.0;
                if (joins)
                    particles.boundary[i] = std::uint8_t(k + 1);
                else
                    keep[i] = 0;
                ledger.outflowKg[k] += particles.mass[i];
                break;
            }
    }
    if (std::find(keep.begin(), keep.end(), 0) != keep.end())
        particles.keepOnly(keep);
}

void OpenBoundaries::impose(ParticleState& particles, const NeighbourGrid& grid, const QuarticKernel& kernel,
                            const FluidModel& fluid, double timeS)
{
    const std::size_t count = m_boundaries.size();
    std::vector<double> speedScale(count, 0.0), pressure(count, 0.0);
    for (std::size_t k = 0; k < count; ++k)
    {
        const OpenBoundary& b = m_boundaries[k];
        if (b.prescribed == OpenBoundary::Prescribed::Velocity)
            speedScale[k] = prescribedFlowRate(k, timeS) / m_calibration[k];
        else // the resistance acts on the last step's outflow
            pressure[k] = prescribedPressure(k, timeS, m_flowRate[k]);
    }
    const int n = int(particles.size());
#pragma omp parallel for schedule(dynamic, 256)
    for (int i = 0; i < n; ++i)
    {
        const std::size_t si = std::size_t(i);
        if (!particles.boundary[si])
            continue;
        const std::size_t k = particles.boundary[si] - 1u;
        const OpenBoundary& b = m_boundaries[k];
        const Eigen::Vector3d mirror = particles.position[si] - 2.0 * signedDistance(k, particles.position[si]) * b.normal;
        double weight = 0.0, relative = 0.0;
        Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
        grid.forEachNear(particles.position, mirror, i,
                         [&](int j, const Eigen::Vector3d&, double r)
                         {
                             const std::size_t sj = std::size_t(j);
                             if (!particles.isFluid(sj))
                                 return;
                             const double w = kernel.interpolationWeight(r) * particles.mass[sj] / particles.density[sj];
                             weight += w;
                             relative += w * particles.density[sj] / fluid.mixtureDensity(particles.voidFraction[sj]);
                             velocity += w * particles.velocity[sj];
                         });
        const bool extrapolated = weight > 0.05; // else the values stay (no fluid near the mirror point yet)
        const double rest = fluid.mixtureDensity(particles.voidFraction[si]);
        if (b.prescribed == OpenBoundary::Prescribed::Velocity)
        {
            particles.velocity[si] = speedScale[k] * shape(k, particles.position[si]) * b.normal;
            if (extrapolated)
                particles.density[si] = rest * relative / weight;
        }
        else
        {
            particles.density[si] = fluid.densityAt(pressure[k], particles.voidFraction[si]);
            if (extrapolated)
                particles.velocity[si] = velocity / weight;
        }
    }
    // What the boundaries pass now: the flux of their buffers' particles and their mean pressure.
    std::vector<double> flux(count, 0.0), pressureSum(count, 0.0), members(count, 0.0);
    for (std::size_t i = 0; i < particles.size(); ++i)
        if (particles.boundary[i])
        {
            const std::size_t k = particles.boundary[i] - 1u;
            flux[k] += particles.mass[i] / particles.density[i] * particles.velocity[i].dot(m_boundaries[k].normal) / m_depthM;
            pressureSum[k] += fluid.pressure(particles.density[i], particles.voidFraction[i]);
            members[k] += 1.0;
        }
    for (std::size_t k = 0; k < count; ++k)
    {
        m_flowRate[k] = flux[k];
        m_pressure[k] = members[k] > 0.0 ? pressureSum[k] / members[k] : pressure[k];
    }
}

void OpenBoundaries::restoreLast(std::vector<double> flowRatesM3S, std::vector<double> pressuresPa)
{
    if (flowRatesM3S.size() != m_boundaries.size() || pressuresPa.size() != m_boundaries.size())
        throw Error(Pattern{"the saved run has %1 open boundaries, this run %2: the checkpoint belongs to another "
                            "problem",
                            {std::to_string(flowRatesM3S.size()), std::to_string(m_boundaries.size())}});
    m_flowRate = std::move(flowRatesM3S), m_pressure = std::move(pressuresPa);
}

} // namespace vsim::sim::sph
