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

double PhaseWindow::overlap(double timeS, double spanS) const
{
    if (empty())
        return 0.0;
    const double phase = timeS - periodS * std::floor(timeS / periodS);
    return std::max(0.0, std::min(phase, toS) - std::max(phase - spanS, fromS));
}

void addWeighted(SectionFlow& sum, const SectionFlow& flow, double weight)
{
    sum.areaM2 += weight * flow.areaM2;
    sum.flowRateM3S += weight * flow.flowRateM3S;
    sum.meanVelocityMS += weight * flow.meanVelocityMS;
    sum.peakVelocityMS += weight * flow.peakVelocityMS;
    sum.meanPressurePa += weight * flow.meanPressurePa;
    sum.particles = std::max(sum.particles, flow.particles);
}

std::vector<SectionFlow> averaged(std::vector<SectionFlow> sums, std::size_t sections, double weight)
{
    sums.resize(sections);
    if (!(weight > 0.0))
        return std::vector<SectionFlow>(sections);
    for (SectionFlow& average : sums)
        for (double* value : {&average.areaM2, &average.flowRateM3S, &average.meanVelocityMS, &average.peakVelocityMS,
                              &average.meanPressurePa})
            *value /= weight;
    return sums;
}

void SectionSeries::sample(const ParticleState& particles, const FluidModel& fluid, double timeS, double weightS)
{
    weightS = m_schedule.due(timeS, weightS);
    if (!(weightS > 0.0))
        return;
    // In the phase window: weighted by the part of the sample's time inside it.
    const double phaseWeightS = m_window.overlap(timeS, weightS);
    m_sums.resize(m_sections.size());
    m_largestPeak.resize(m_sections.size(), -INFINITY);
    if (phaseWeightS > 0.0)
        m_phaseSums.resize(m_sections.size());
    // Each section reads all particles and sums on its own: in parallel, the same sums in the same order.
#pragma omp parallel for schedule(dynamic, 1)
    for (std::ptrdiff_t sk = 0; sk < std::ptrdiff_t(m_sections.size()); ++sk)
    {
        const std::size_t k = std::size_t(sk);
        const SectionFlow flow = sectionFlow(particles, fluid, m_sections[k]);
        addWeighted(m_sums[k], flow, weightS);
        if (phaseWeightS > 0.0)
            addWeighted(m_phaseSums[k], flow, phaseWeightS);
        if (flow.particles > 0)
            m_largestPeak[k] = std::max(m_largestPeak[k], flow.peakVelocityMS);
    }
    m_weight += weightS;
    m_phaseWeight += phaseWeightS;
}

std::vector<SectionFlow> SectionSeries::averages() const
{
    return averaged(m_sums, m_sections.size(), m_weight);
}

std::vector<SectionFlow> SectionSeries::phaseAverages() const
{
    return averaged(m_phaseSums, m_sections.size(), m_phaseWeight);
}

void SectionSeries::restore(Sums sums)
{
    const bool none = sums.flows.empty() && sums.largestPeaks.empty();
    if ((!none && (sums.flows.size() != m_sections.size() || sums.largestPeaks.size() != m_sections.size())) ||
        (!sums.phaseFlows.empty() && sums.phaseFlows.size() != m_sections.size()))
        throw Error(Pattern{"the saved section averages are for %1 sections, this run has %2",
                            {std::to_string(sums.flows.size()), std::to_string(m_sections.size())}});
    m_schedule.restore(sums.schedule);
    m_weight = sums.weightS, m_sums = std::move(sums.flows), m_largestPeak = std::move(sums.largestPeaks);
    m_phaseWeight = sums.phaseWeightS, m_phaseSums = std::move(sums.phaseFlows);
}

} // namespace vsim::sim::sph
