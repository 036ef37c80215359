#include "vsim/sim/network/Filling.h"

#include "vsim/core/Units.h"
#include "vsim/sim/network/ConicalPipe.h"

#include <algorithm>
#include <cmath>

namespace vsim::sim::network {
namespace {

/// The segment's radii (m) from its upstream end on, and its length (m).
struct Oriented
{
    double r1, r2, length;
};

Oriented oriented(const VesselNetwork::Segment& segment, int upstream)
{
    const double a = units::mmToM(segment.startRadiusMm), b = units::mmToM(segment.endRadiusMm);
    return upstream == segment.from ? Oriented{a, b, units::mmToM(segment.lengthMm)}
                                    : Oriented{b, a, units::mmToM(segment.lengthMm)};
}

/// Flow away from the tip (m^3/s), <= 0 when the segment is fed from its far end.
double downstreamFlow(const VesselNetwork::Segment& segment, const FlowSolution& flow, int s)
{
    const int upstream = flow.orientation.upstreamNode[std::size_t(s)];
    return upstream == segment.from ? flow.segmentFlow[std::size_t(s)] : -flow.segmentFlow[std::size_t(s)];
}

} // namespace

FillingTimes fillingTimes(const VesselNetwork& network, const FlowSolution& flow)
{
    FillingTimes times;
    times.enter.assign(network.segments.size(), kNever);
    times.leave.assign(network.segments.size(), kNever);
    std::vector<double> reached(network.nodes.size(), kNever);
    const TipOrientation& o = flow.orientation;
    reached[std::size_t(o.tip)] = 0.0;
    for (int node : o.order) // parents before children
    {
        const int s = o.parentSegment[std::size_t(node)];
        if (s < 0)
            continue;
        const auto& segment = network.segments[std::size_t(s)];
        const double q = downstreamFlow(segment, flow, s);
        const double start = reached[std::size_t(o.upstreamNode[std::size_t(s)])];
        if (!(q > 0.0) || start == kNever)
            continue;
        const Oriented shape = oriented(segment, o.upstreamNode[std::size_t(s)]);
        times.enter[std::size_t(s)] = start;
        times.leave[std::size_t(s)] = start + conicalVolume(shape.r1, shape.r2, shape.length, shape.length) / q;
        reached[std::size_t(node)] = times.leave[std::size_t(s)];
    }
    for (int outlet : o.outlets)
    {
        times.arrival[outlet] = reached[std::size_t(outlet)];
        if (reached[std::size_t(outlet)] != kNever)
            times.lastArrival = std::max(times.lastArrival, reached[std::size_t(outlet)]);
    }
    return times;
}

void filledLengths(const VesselNetwork& network, const FlowSolution& flow, const FillingTimes& times, double timeS,
                   std::vector<double>& lengthsMm)
{
    lengthsMm.assign(network.segments.size(), 0.0);
    for (std::size_t s = 0; s < network.segments.size(); ++s)
    {
        if (!(timeS > times.enter[s]))
            continue;
        const auto& segment = network.segments[s];
        if (timeS >= times.leave[s])
        {
            lengthsMm[s] = segment.lengthMm;
            continue;
        }
        const Oriented shape = oriented(segment, flow.orientation.upstreamNode[s]);
        const double volume = downstreamFlow(segment, flow, int(s)) * (timeS - times.enter[s]);
        lengthsMm[s] = units::mToMm(filledLength(shape.r1, shape.r2, shape.length, volume));
    }
}

double arrivalAt(const FillingTimes& times, int outlet)
{
    const auto found = times.arrival.find(outlet);
    return found == times.arrival.end() ? kNever : found->second;
}

} // namespace vsim::sim::network
