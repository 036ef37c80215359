#pragma once

// A stenosis's figures from the time-averaged flow through sections along the vessel's path (issue 18): the throat
// is the section of the smallest flow area (between the path's ends less the comparison distance), compared with the
// sections `distanceMm` upstream and downstream along the path (the thesis compares 6 mm in its hand case and 30 mm
// in its heart case):
//   peak velocity ratio  = peak(throat) / peak(upstream)   (the duplex peak-systolic velocity ratio's counterpart;
//                          also against downstream),
//   mean velocity ratio  = mean(throat) / mean(upstream)   (a mass check: the area ratio for an incompressible flow),
//   pressure drop        = p(upstream) - p(downstream)     (section means, Pa),
//   pressure ratio       = p(downstream) / p(upstream)     (distal / proximal, with the outlet's pressure as given).

#include "vsim/sim/sph/CrossSections.h"

#include <vector>

namespace vsim::sim::sph {

struct StenosisFigures
{
    std::size_t throat = 0, upstream = 0, downstream = 0; ///< section indices
    double throatArcMm = 0.0, distanceMm = 0.0;
    double areaRatio = 0.0;            ///< A(upstream) / A(throat), from the particles
    double peakRatio = 0.0, peakRatioDownstream = 0.0;
    double meanRatio = 0.0, meanRatioDownstream = 0.0;
    double pressureDropPa = 0.0, pressureRatio = 0.0;
    double flowRateRatio = 0.0; ///< Q(throat) / Q(upstream): 1 for a conserved, settled flow
};

/// `arcMm`: each section's position along the path (mm, increasing downstream); `flows`: their averages. Throws
/// vsim::Error when no section lies `distanceMm` from both ends or a compared section is empty.
StenosisFigures stenosisFigures(const std::vector<double>& arcMm, const std::vector<SectionFlow>& flows, double distanceMm);

} // namespace vsim::sim::sph
