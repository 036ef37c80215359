#include "vsim/sim/sph/StenosisFigures.h"

#include "vsim/core/Error.h"

#include <cmath>
#include <limits>

namespace vsim::sim::sph {
namespace {

std::size_t nearestSection(const std::vector<double>& arcMm, double at)
{
    std::size_t best = 0;
    for (std::size_t k = 1; k < arcMm.size(); ++k)
        if (std::abs(arcMm[k] - at) < std::abs(arcMm[best] - at))
            best = k;
    return best;
}

} // namespace

StenosisFigures stenosisFigures(const std::vector<double>& arcMm, const std::vector<SectionFlow>& flows, double distanceMm)
{
    if (arcMm.size() != flows.size() || arcMm.empty())
        throw Error("the stenosis figures need one averaged flow per section");
    StenosisFigures figures;
    figures.distanceMm = distanceMm;
    double smallest = std::numeric_limits<double>::infinity();
    bool found = false;
    for (std::size_t k = 0; k < arcMm.size(); ++k)
        if (arcMm[k] - distanceMm >= arcMm.front() - 1e-9 && arcMm[k] + distanceMm <= arcMm.back() + 1e-9 &&
            flows[k].particles > 0 && flows[k].areaM2 < smallest)
            smallest = flows[k].areaM2, figures.throat = k, found = true;
    if (!found)
        throw Error(Pattern{"no section lies %1 mm from both ends of the path to compare with",
                            {std::to_string(distanceMm)}});
    figures.throatArcMm = arcMm[figures.throat];
    figures.upstream = nearestSection(arcMm, figures.throatArcMm - distanceMm);
    figures.downstream = nearestSection(arcMm, figures.throatArcMm + distanceMm);
    const SectionFlow &t = flows[figures.throat], &u = flows[figures.upstream], &d = flows[figures.downstream];
    if (u.particles == 0 || d.particles == 0)
        throw Error("a section the stenosis is compared with holds no fluid");
    figures.areaRatio = u.areaM2 / t.areaM2;
    figures.peakRatio = t.peakVelocityMS / u.peakVelocityMS;
    figures.peakRatioDownstream = t.peakVelocityMS / d.peakVelocityMS;
    figures.meanRatio = t.meanVelocityMS / u.meanVelocityMS;
    figures.meanRatioDownstream = t.meanVelocityMS / d.meanVelocityMS;
    figures.pressureDropPa = u.meanPressurePa - d.meanPressurePa;
    figures.pressureRatio = d.meanPressurePa / u.meanPressurePa;
    figures.flowRateRatio = t.flowRateM3S / u.flowRateM3S;
    return figures;
}

} // namespace vsim::sim::sph
