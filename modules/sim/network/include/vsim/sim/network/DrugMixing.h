#pragma once

// The injected fluid carried by the flow (issue 19): at every node the streams that enter mix completely, the
// fraction leaving being the flow-weighted mean of those entering plus the injection made there, and each segment
// carries the fraction of the node its flow comes from. Flow runs from higher to lower pressure, so taking the
// nodes in order of falling pressure meets every stream after its source: one exact pass, no iteration.
// Fractions are of volume: the injected mixture's share of a segment's volume flow.

#include "vsim/core/VesselNetwork.h"
#include "vsim/sim/network/FlowSolver.h"

#include <vector>

namespace vsim::sim::network {

struct InjectateBalance
{
    double injected = 0.0;         ///< m^3/s of injected fluid entering (the injection source's flow, if positive)
    double leftAtOutlets = 0.0;    ///< m^3/s leaving through the outlets
    double leftAtSources = 0.0;    ///< m^3/s pushed back out through the other sources (reflux out of an inlet)
    /// |injected - left| / injected: the check of the pass (a direct solve leaves ~1e-15).
    double relativeError() const;
};

/// Fills flow.injectateFraction (per segment) and flow.outletInjectate from the flow's segment and source flows;
/// the fluid entering at sources[injection] is the injected one, every other source brings blood (fraction 0),
/// as does an outlet whose flow runs into the network. Returns the balance of the injected fluid.
InjectateBalance mixInjectate(const VesselNetwork& network, FlowSolution& flow, const std::vector<NodeSource>& sources,
                              std::size_t injection);

} // namespace vsim::sim::network
