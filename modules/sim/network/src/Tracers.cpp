#include "vsim/sim/network/Tracers.h"

#include "vsim/core/Units.h"
#include "vsim/sim/network/ConicalPipe.h"

#include <algorithm>
#include <cmath>

namespace vsim::sim::network {
namespace {

/// The point `fraction` (0..1) of the way along a polyline.
Eigen::Vector3d alongPath(const std::vector<Eigen::Vector3d>& path, double fraction)
{
    double total = 0.0;
    for (std::size_t i = 1; i < path.size(); ++i)
        total += (path[i] - path[i - 1]).norm();
    double remaining = std::clamp(fraction, 0.0, 1.0) * total;
    for (std::size_t i = 1; i < path.size(); ++i)
    {
        const double length = (path[i] - path[i - 1]).norm();
        if (remaining <= length && length > 0.0)
            return path[i - 1] + remaining / length * (path[i] - path[i - 1]);
        remaining -= length;
    }
    return path.back();
}

/// Segments from the tip to `outlet`, in order.
std::vector<int> pathSegments(const FlowSolution& flow, int outlet)
{
    std::vector<int> segments;
    for (int node = outlet; node != flow.orientation.tip;)
    {
        const int s = flow.orientation.parentSegment[std::size_t(node)];
        if (s < 0)
            return {};
        segments.push_back(s);
        node = flow.orientation.upstreamNode[std::size_t(s)];
    }
    std::reverse(segments.begin(), segments.end());
    return segments;
}

} // namespace

bool tracerPosition(const VesselNetwork& network, const FlowSolution& flow, int outlet, double elapsedS,
                    Eigen::Vector3d& positionMm)
{
    if (elapsedS < 0.0)
        return false;
    double remaining = elapsedS;
    for (int s : pathSegments(flow, outlet))
    {
        const auto& segment = network.segments[std::size_t(s)];
        const bool forward = flow.orientation.upstreamNode[std::size_t(s)] == segment.from;
        const double q = forward ? flow.segmentFlow[std::size_t(s)] : -flow.segmentFlow[std::size_t(s)];
        if (!(q > 0.0))
            return false;
        const double r1 = units::mmToM(forward ? segment.startRadiusMm : segment.endRadiusMm);
        const double r2 = units::mmToM(forward ? segment.endRadiusMm : segment.startRadiusMm);
        const double length = units::mmToM(segment.lengthMm), volume = conicalVolume(r1, r2, length, length);
        if (q * remaining < volume)
        {
            const double fraction = filledLength(r1, r2, length, q * remaining) / length;
            std::vector<Eigen::Vector3d> path = network.segmentPath(std::size_t(s));
            if (!forward)
                std::reverse(path.begin(), path.end());
            positionMm = alongPath(path, fraction);
            return true;
        }
        remaining -= volume / q;
    }
    return false;
}

std::vector<std::vector<Eigen::Vector3d>> tracerTrails(const VesselNetwork& network, const FlowSolution& flow,
                                                       double timeS, const TracerSettings& settings)
{
    // Outlets in proportion to the injected fluid they drain: each release goes to the outlet furthest behind its
    // share.
    std::vector<std::pair<int, double>> shares;
    double total = 0.0;
    for (const auto& [node, q] : flow.outletInjectate)
        if (q > 0.0)
            shares.emplace_back(node, q), total += q;
    std::vector<std::vector<Eigen::Vector3d>> trails;
    if (shares.empty() || !(settings.releaseEveryS > 0.0))
        return trails;
    std::vector<double> sent(shares.size(), 0.0);
    const int releases = int(std::floor(timeS / settings.releaseEveryS)) + 1;
    for (int k = 0; k < releases; ++k)
    {
        std::size_t pick = 0;
        double worst = 1e300;
        for (std::size_t i = 0; i < shares.size(); ++i)
        {
            const double ahead = sent[i] - (k + 1) * shares[i].second / total;
            if (ahead < worst)
                worst = ahead, pick = i;
        }
        sent[pick] += 1.0;
        const double elapsed = timeS - k * settings.releaseEveryS;
        std::vector<Eigen::Vector3d> trail;
        Eigen::Vector3d position;
        for (int j = 0; j < settings.trailPoints; ++j)
            if (tracerPosition(network, flow, shares[pick].first, elapsed - j * settings.trailSpacingS, position))
                trail.push_back(position);
            else if (j == 0)
                break; // not in the network (not yet released or already out)
        if (trail.size() >= 2)
            trails.push_back(std::move(trail));
    }
    return trails;
}

} // namespace vsim::sim::network
