#include "vsim/sim/sph/CrossSections.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vsim::sim::sph {

SectionFlow sectionFlow(const ParticleState& particles, const FluidModel& fluid, const CrossSection& section)
{
    SectionFlow flow;
    double volume = 0.0, flux = 0.0, pressure = 0.0, peak = -std::numeric_limits<double>::infinity();
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
        volume += v, flux += v * u, pressure += v * fluid.pressure(particles.density[i], particles.voidFraction[i]);
        peak = std::max(peak, u);
        ++flow.particles;
    }
    if (flow.particles == 0)
        return flow;
    flow.areaM2 = volume / section.thicknessM;
    flow.flowRateM3S = flux / section.thicknessM;
    flow.meanVelocityMS = flux / volume;
    flow.peakVelocityMS = peak;
    flow.meanPressurePa = pressure / volume;
    return flow;
}

} // namespace vsim::sim::sph
