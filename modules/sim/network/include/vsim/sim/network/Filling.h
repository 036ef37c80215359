#pragma once

// How the injected drug fills the tree (thesis ch. 6.2: "the partial length of each segment that is filled at each
// time step"): with the steady flow split, the front in each segment moves as a plug, so the filled volume of a
// segment grows at its flow rate from the moment the front reaches its upstream end, and the filled length is where
// the cone's volume equals it. A segment whose flow runs towards the tip (fed by another inlet) never fills.

#include "vsim/core/VesselNetwork.h"
#include "vsim/sim/network/FlowSolver.h"

#include <limits>
#include <map>
#include <vector>

namespace vsim::sim::network {

inline constexpr double kNever = std::numeric_limits<double>::infinity();

struct FillingTimes
{
    std::vector<double> enter;        ///< s: the front reaches the segment's upstream end (kNever: not reached)
    std::vector<double> leave;        ///< s: the segment is full
    std::map<int, double> arrival;    ///< s: the front reaches each outlet (kNever: not reached)
    double lastArrival = 0.0;         ///< s: the latest finite outlet arrival
};

/// When the front reaches `outlet` (kNever for an outlet it does not reach, or one not downstream of the tip).
double arrivalAt(const FillingTimes& times, int outlet);

FillingTimes fillingTimes(const VesselNetwork& network, const FlowSolution& flow);

/// Filled length (mm, from the upstream end) of every segment at `timeS`, into `lengthsMm` (resized).
void filledLengths(const VesselNetwork& network, const FlowSolution& flow, const FillingTimes& times, double timeS,
                   std::vector<double>& lengthsMm);

} // namespace vsim::sim::network
