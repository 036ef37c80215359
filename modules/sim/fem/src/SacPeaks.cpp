#include "vsim/sim/fem/SacPeaks.h"

#include "vsim/core/Error.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <queue>

namespace vsim::sim::fem {
namespace {

/// The centerline's points as one graph: consecutive points of an edge joined, an edge's ends joined to its nodes.
struct PointGraph
{
    std::vector<Eigen::Vector3d> points;
    std::vector<std::vector<std::pair<std::size_t, double>>> links;

    explicit PointGraph(const SkeletonGraph& g)
    {
        for (const auto& node : g.nodes)
            points.push_back(node.position);
        links.resize(points.size());
        const auto add = [&](const Eigen::Vector3d& p) {
            points.push_back(p);
            links.emplace_back();
            return points.size() - 1;
        };
        const auto join = [&](std::size_t a, std::size_t b) {
            const double d = (points[a] - points[b]).norm();
            links[a].push_back({b, d});
            links[b].push_back({a, d});
        };
        for (const auto& edge : g.edges)
        {
            std::size_t previous = std::size_t(edge.from);
            for (const Eigen::Vector3d& p : edge.points)
            {
                const std::size_t here = add(p);
                join(previous, here);
                previous = here;
            }
            join(previous, std::size_t(edge.to));
        }
    }

    std::size_t nearest(const Eigen::Vector3d& p) const
    {
        std::size_t best = 0;
        for (std::size_t i = 1; i < points.size(); ++i)
            if ((points[i] - p).squaredNorm() < (points[best] - p).squaredNorm())
                best = i;
        return best;
    }
};

double percentile(std::vector<double> values, double fraction)
{
    const std::size_t k = std::min(values.size() - 1, std::size_t(std::ceil(fraction * double(values.size()))) - 1);
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(k), values.end());
    return values[k];
}

} // namespace

double distanceAlongCenterline(const SkeletonGraph& centerlines, const Eigen::Vector3d& fromMm, const Eigen::Vector3d& toMm)
{
    const PointGraph graph(centerlines);
    if (graph.points.empty())
        return -1.0;
    const std::size_t source = graph.nearest(fromMm), target = graph.nearest(toMm);
    std::vector<double> distance(graph.points.size(), 1e300);
    using Item = std::pair<double, std::size_t>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
    distance[source] = 0.0;
    queue.push({0.0, source});
    while (!queue.empty())
    {
        const auto [d, v] = queue.top();
        queue.pop();
        if (d > distance[v])
            continue;
        if (v == target)
            return d;
        for (const auto& [w, length] : graph.links[v])
            if (d + length < distance[w])
                distance[w] = d + length, queue.push({d + length, w});
    }
    return -1.0;
}

CenterlinePlace nearestCenterlinePlace(const SkeletonGraph& centerlines, const Eigen::Vector3d& pointMm)
{
    double best = 1e300;
    CenterlinePlace place;
    for (const auto& edge : centerlines.edges)
        for (std::size_t i = 0; i < edge.points.size(); ++i)
            if (const double d = (edge.points[i] - pointMm).squaredNorm(); d < best)
            {
                best = d;
                place.pointMm = edge.points[i];
                const std::size_t lo = i >= 2 ? i - 2 : 0, hi = std::min(edge.points.size() - 1, i + 2);
                if (hi > lo)
                    place.direction = (edge.points[hi] - edge.points[lo]).normalized();
            }
    return place;
}

double clockPosition(const SkeletonGraph& centerlines, const Eigen::Vector3d& pointMm)
{
    const CenterlinePlace place = nearestCenterlinePlace(centerlines, pointMm);
    Eigen::Vector3d offset = pointMm - place.pointMm;
    offset -= offset.dot(place.direction) * place.direction;
    // LPS: anterior is -y, the patient's left +x; from the feet anterior is up and the patient's left on the right.
    const double angle = std::atan2(offset.x(), -offset.y()); // 0 anterior, +pi/2 the patient's left
    double hours = angle * 6.0 / M_PI;
    if (hours <= 0.0)
        hours += 12.0;
    return hours;
}

SacPeak peakInSac(const TetMesh& frameMm, const std::vector<double>& elementValues, const SacRegion& sac,
                  const SkeletonGraph& centerlines)
{
    if (elementValues.size() != frameMm.tets.size())
        throw Error("the element field does not match the mesh");
    std::vector<double> inside;
    std::vector<double> nodalSum(frameMm.points.size(), 0.0), nodalVolume(frameMm.points.size(), 0.0);
    std::vector<char> sacNode(frameMm.points.size(), 0);
    const auto material = frameMm.cellFields.find("material"); // the wall's figures: thrombus (1) left out
    for (std::size_t t = 0; t < frameMm.tets.size(); ++t)
    {
        if (material != frameMm.cellFields.end() && material->second[t] > 0.5)
            continue;
        const auto& tet = frameMm.tets[t];
        const auto corner = [&](int k) { return frameMm.points[std::size_t(tet[std::size_t(k)])]; };
        const double volume = std::abs((corner(1) - corner(0)).cross(corner(2) - corner(0)).dot(corner(3) - corner(0))) / 6.0;
        for (int node : tet)
            nodalSum[std::size_t(node)] += volume * elementValues[t], nodalVolume[std::size_t(node)] += volume;
        if (sac.contains && sac.contains(0.25 * (corner(0) + corner(1) + corner(2) + corner(3))))
        {
            inside.push_back(elementValues[t]);
            for (int node : tet)
                sacNode[std::size_t(node)] = 1;
        }
    }
    if (inside.empty())
        throw Error("no element of the wall lies in the aneurysm sac: is the sac measured on the image this wall "
                    "was built from?");
    SacPeak peak;
    peak.elements = inside.size();
    peak.percentile99 = percentile(inside, 0.99);
    std::size_t where = 0;
    double largest = -1e300;
    for (std::size_t n = 0; n < frameMm.points.size(); ++n)
        if (sacNode[n] && nodalVolume[n] > 0.0 && nodalSum[n] / nodalVolume[n] > largest)
            largest = nodalSum[n] / nodalVolume[n], where = n;
    peak.nodalMax = largest;
    peak.whereMm = frameMm.points[where];
    peak.alongCenterlineMm = distanceAlongCenterline(centerlines, sac.referenceMm, peak.whereMm);
    peak.clockHours = clockPosition(centerlines, peak.whereMm);
    return peak;
}

} // namespace vsim::sim::fem
