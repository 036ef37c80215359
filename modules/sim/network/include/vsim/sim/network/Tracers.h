#pragma once

// Tracers for the filling display (thesis ch. 6.3: "virtual tubelets" trail each tracer): tracers leave the tip at
// a steady period, each bound for one outlet in proportion to the outlet flows, and move with the plug flow of
// Filling.h, so a tracer released at t0 stands where a front started at t0 would. A trail is the tracer's places
// over the last few moments, head first.

#include "vsim/core/VesselNetwork.h"
#include "vsim/sim/network/Filling.h"
#include "vsim/sim/network/FlowSolver.h"

#include <vector>

namespace vsim::sim::network {

struct TracerSettings
{
    double releaseEveryS = 1.0;   ///< one tracer leaves the tip this often
    int trailPoints = 8;          ///< places per trail (head included)
    double trailSpacingS = 0.5;   ///< time between a trail's places
};

/// Where a tracer released `elapsedS` ago on the path to `outlet` is (mm); false once it has left the network.
bool tracerPosition(const VesselNetwork& network, const FlowSolution& flow, int outlet, double elapsedS,
                    Eigen::Vector3d& positionMm);

/// The trails (mm, head first) of every tracer in the network at `timeS`.
std::vector<std::vector<Eigen::Vector3d>> tracerTrails(const VesselNetwork& network, const FlowSolution& flow,
                                                       double timeS, const TracerSettings& settings);

} // namespace vsim::sim::network
