#include "vsim/sim/sph/CrossSections.h"

#include "vsim/core/Error.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace vsim::sim::sph {

SectionFlow sectionFlow(const ParticleState& particles, const FluidModel& fluid, const CrossSection& section)
{
    SectionFlow flow;
    double volume = 0.0, flux = 0.0, pressure = 0.0;
    std::vector<double> speeds;
    for (std::size_t i = 0; i < particles.size(); ++i)
    {
        if (!particles.isFluid(i))
            continue;
        const Eigen::Vector3d offset = particles.position[i] - section.centreM;
        const double along = offset.dot(section.normal);
        if (std::abs(along) > 0.5 * section.thicknessM ||
            (offset - along * section.normal).squaredNorm() > section.radiusM * section.radiusM)
            continue;
        const double v = particles.mass[i] / particles.density[i], u = particles.velocity[i].dot(section.normal);
        volume += v, flux += v * u;
        pressure += v * fluid.reportedPressure(particles.density[i], particles.voidFraction[i]);
        speeds.push_back(u);
    }
    flow.particles = int(speeds.size());
    if (speeds.empty())
        return flow;
    const std::size_t fastest = std::min(speeds.size(), std::max<std::size_t>(3, speeds.size() / 20));
    std::partial_sort(speeds.begin(), speeds.begin() + long(fastest), speeds.end(), std::greater<>());
    double top = 0.0;
    for (std::size_t k = 0; k < fastest; ++k)
        top += speeds[k];
    flow.areaM2 = volume / section.thicknessM;
    flow.flowRateM3S = flux / section.thicknessM;
    flow.meanVelocityMS = flux / volume;
    flow.peakVelocityMS = top / double(fastest);
    flow.meanPressurePa = pressure / volume;
    return flow;
}

void SectionSeries::sample(const ParticleState& particles, const FluidModel& fluid, double timeS, double weightS)
{
    weightS = m_schedule.due(timeS, weightS);
    if (!(weightS > 0.0))
        return;
    m_sums.resize(m_sections.size());
    m_largestPeak.resize(m_sections.size(), -INFINITY);
    for (std::size_t k = 0; k < m_sections.size(); ++k)
    {
        const SectionFlow flow = sectionFlow(particles, fluid, m_sections[k]);
        SectionFlow& sum = m_sums[k];
        sum.areaM2 += weightS * flow.areaM2;
        sum.flowRateM3S += weightS * flow.flowRateM3S;
        sum.meanVelocityMS += weightS * flow.meanVelocityMS;
        sum.peakVelocityMS += weightS * flow.peakVelocityMS;
        sum.meanPressurePa += weightS * flow.meanPressurePa;
        sum.particles = std::max(sum.particles, flow.particles);
        if (flow.particles > 0)
            m_largestPeak[k] = std::max(m_largestPeak[k], flow.peakVelocityMS);
    }
    m_weight += weightS;
}

std::vector<SectionFlow> SectionSeries::averages() const
{
    std::vector<SectionFlow> averages(m_sections.size());
    if (!(m_weight > 0.0))
        return averages;
    for (std::size_t k = 0; k < m_sums.size(); ++k)
    {
        averages[k] = m_sums[k];
        for (double* value : {&averages[k].areaM2, &averages[k].flowRateM3S, &averages[k].meanVelocityMS,
                              &averages[k].peakVelocityMS, &averages[k].meanPressurePa})
            *value /= m_weight;
    }
    return averages;
}

void SectionSeries::restore(Sums sums)
{
    const bool none = sums.flows.empty() && sums.largestPeaks.empty();
    if (!none && (sums.flows.size() != m_sections.size() || sums.largestPeaks.size() != m_sections.size()))
        throw Error(Pattern{"the saved section averages are for %1 sections, this run has %2",
                            {std::to_string(sums.flows.size()), std::to_string(m_sections.size())}});
    m_schedule.restore(sums.schedule);
    m_weight = sums.weightS, m_sums = std::move(sums.flows), m_largestPeak = std::move(sums.largestPeaks);
}

} // namespace vsim::sim::sph
