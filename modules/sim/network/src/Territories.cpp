#include "vsim/sim/network/Territories.h"

#include "TerritoryGrid.h"

#include "vsim/core/DistanceTransform.h"
#include "vsim/core/Error.h"
#include "vsim/core/Localized.h"
#include "vsim/core/ParallelFor.h"
#include "vsim/core/Units.h"
#include "vsim/sim/network/TipOrientation.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <unordered_map>

namespace vsim::sim::network {
namespace {

using detail::liverVoxel;

constexpr double kSimplifyMm = 0.25; ///< a centerline simplified for the territories stays this near itself

/// Within `reachMm` of the liver: the voxels of the cube around the point searched on the liver's grid.
bool nearLiver(const LiverTerritories& t, const Eigen::Vector3d& pointMm, double reachMm)
{
    const Eigen::Vector3d centre = t.geometry.patientToIndex(pointMm);
    const Eigen::Vector3d half = (Eigen::Vector3d::Constant(reachMm).cwiseQuotient(t.geometry.spacing)).array().ceil();
    for (int k = int(centre.z() - half.z()); k <= int(centre.z() + half.z()) + 1; ++k)
        for (int j = int(centre.y() - half.y()); j <= int(centre.y() + half.y()) + 1; ++j)
            for (int i = int(centre.x() - half.x()); i <= int(centre.x() + half.x()) + 1; ++i)
                if (t.geometry.contains(i, j, k) &&
                    (t.geometry.indexToPatient(Eigen::Vector3d(i, j, k)) - pointMm).norm() <= reachMm &&
                    liverVoxel(t, t.geometry.linearIndex(i, j, k)) >= 0)
                    return true;
    return false;
}

double meanRadius(const VesselNetwork::Segment& s) { return 0.5 * (s.startRadiusMm + s.endRadiusMm); }

/// Douglas-Peucker: the vertices of `path` that keep every other vertex within `toleranceMm` of the result.
std::vector<Eigen::Vector3d> simplified(const std::vector<Eigen::Vector3d>& path, double toleranceMm)
{
    if (path.size() <= 2)
        return path;
    std::vector<char> keep(path.size(), 0);
    keep.front() = keep.back() = 1;
    std::vector<std::pair<std::size_t, std::size_t>> spans{{0, path.size() - 1}};
    while (!spans.empty())
    {
        const auto [a, b] = spans.back();
        spans.pop_back();
        const Eigen::Vector3d d = path[b] - path[a];
        double worst = -1.0;
        std::size_t at = a;
        for (std::size_t i = a + 1; i < b; ++i)
        {
            const double t = std::clamp((path[i] - path[a]).dot(d) / std::max(1e-300, d.squaredNorm()), 0.0, 1.0);
            if (const double e = (path[a] + t * d - path[i]).norm(); e > worst)
                worst = e, at = i;
        }
        if (worst > toleranceMm)
            keep[at] = 1, spans.push_back({a, at}), spans.push_back({at, b});
    }
    std::vector<Eigen::Vector3d> out;
    for (std::size_t i = 0; i < path.size(); ++i)
        if (keep[i])
            out.push_back(path[i]);
    return out;
}

/// A centerline as a polyline (simplified to within kSimplifyMm) with a bounding sphere, for nearest-vessel queries.
struct Polyline
{
    std::vector<Eigen::Vector3d> points;
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    double radius = 0.0;

    explicit Polyline(const std::vector<Eigen::Vector3d>& path) : points(simplified(path, kSimplifyMm))
    {
        Eigen::Vector3d lower = points.front(), upper = points.front();
        for (const Eigen::Vector3d& p : points)
            lower = lower.cwiseMin(p), upper = upper.cwiseMax(p);
        centre = 0.5 * (lower + upper);
        radius = 0.5 * (upper - lower).norm();
    }
    double distance(const Eigen::Vector3d& q) const
    {
        double best = (q - points.front()).squaredNorm();
        for (std::size_t i = 0; i + 1 < points.size(); ++i)
        {
            const Eigen::Vector3d d = points[i + 1] - points[i];
            const double t = std::clamp((q - points[i]).dot(d) / std::max(1e-300, d.squaredNorm()), 0.0, 1.0);
            best = std::min(best, (points[i] + t * d - q).squaredNorm());
        }
        return std::sqrt(best);
    }
};

/// For every liver voxel, the index of the nearest polyline (exact). Voxels in blocks of 4 x 4 x 4: only the
/// polylines within twice the block's half-diagonal of the nearest to its centre can be nearest to one of its
/// voxels (the triangle inequality), and the voxels are tested against those alone.
std::vector<int> nearestPolylines(const LiverTerritories& t, const std::vector<Polyline>& lines, const Progress& progress)
{
    constexpr int kBlock = 4;
    const VolumeGeometry& g = t.geometry;
    const std::size_t nx = std::size_t(g.dims[0]), nxy = nx * std::size_t(g.dims[1]);
    std::array<int, 3> lower{g.dims[0], g.dims[1], g.dims[2]}, upper{0, 0, 0};
    for (std::size_t linear : t.voxels)
    {
        const std::array<int, 3> ijk{int(linear % nx), int((linear / nx) % std::size_t(g.dims[1])), int(linear / nxy)};
        for (int a = 0; a < 3; ++a)
            lower[std::size_t(a)] = std::min(lower[std::size_t(a)], ijk[std::size_t(a)]),
            upper[std::size_t(a)] = std::max(upper[std::size_t(a)], ijk[std::size_t(a)]);
    }
    std::array<int, 3> blocks{};
    for (int a = 0; a < 3; ++a)
        blocks[std::size_t(a)] = (upper[std::size_t(a)] - lower[std::size_t(a)]) / kBlock + 1;
    const double halfDiagonal = 0.5 * (g.spacing * double(kBlock - 1)).norm();
    std::vector<int> nearest(t.voxels.size(), -1);
    const std::size_t rows = std::size_t(blocks[1]) * std::size_t(blocks[2]);
    parallelFor(
        rows,
        [&](std::size_t row) {
            const int bj = int(row % std::size_t(blocks[1])), bk = int(row / std::size_t(blocks[1]));
            std::vector<double> toCentre(lines.size());
            std::vector<int> candidates;
            for (int bi = 0; bi < blocks[0]; ++bi)
            {
                const Eigen::Vector3i first(lower[0] + bi * kBlock, lower[1] + bj * kBlock, lower[2] + bk * kBlock);
                std::vector<std::pair<std::size_t, Eigen::Vector3d>> members; // liver voxel, position
                for (int k = first.z(); k < std::min(first.z() + kBlock, upper[2] + 1); ++k)
                    for (int j = first.y(); j < std::min(first.y() + kBlock, upper[1] + 1); ++j)
                        for (int i = first.x(); i < std::min(first.x() + kBlock, upper[0] + 1); ++i)
                            if (const long v = liverVoxel(t, g.linearIndex(i, j, k)); v >= 0)
                                members.emplace_back(std::size_t(v), g.indexToPatient(Eigen::Vector3d(i, j, k)));
                if (members.empty())
                    continue;
                const Eigen::Vector3d centre = g.indexToPatient(first.cast<double>() + Eigen::Vector3d::Constant(0.5 * (kBlock - 1)));
                double least = 1e300;
                for (std::size_t l = 0; l < lines.size(); ++l) // bounding spheres first: a lower bound
                    toCentre[l] = std::max(0.0, (centre - lines[l].centre).norm() - lines[l].radius);
                for (std::size_t l = 0; l < lines.size(); ++l)
                    if (toCentre[l] <= least + 2.0 * halfDiagonal)
                    {
                        toCentre[l] = lines[l].distance(centre);
                        least = std::min(least, toCentre[l]);
                    }
                    else
                        toCentre[l] = 1e300;
                candidates.clear();
                for (std::size_t l = 0; l < lines.size(); ++l)
                    if (toCentre[l] <= least + 2.0 * halfDiagonal)
                        candidates.push_back(int(l));
                for (const auto& [v, p] : members)
                {
                    double best = 1e300;
                    for (int l : candidates)
                        if (const double d = lines[std::size_t(l)].distance(p); d < best)
                            best = d, nearest[v] = l;
                }
            }
        },
        [&](std::size_t done) {
            progress.throwIfCancelled();
            progress.report(double(done) / double(rows), localized("vsim::Progress", "perfusion territories"));
        });
    return nearest;
}

} // namespace

bool LabelRegion::contains(const Eigen::Vector3d& pointMm) const
{
    const long linear = detail::nearestLinear(label->geometry(), pointMm);
    return linear >= 0 && holds(label->data()[linear]);
}

Eigen::Vector3d LiverTerritories::position(std::size_t v) const
{
    const std::size_t linear = voxels[v], nx = std::size_t(geometry.dims[0]), ny = std::size_t(geometry.dims[1]);
    return geometry.indexToPatient(Eigen::Vector3d(double(linear % nx), double((linear / nx) % ny), double(linear / (nx * ny))));
}

std::vector<ParameterSpec> territoryParameters()
{
    return {
        {"hepatic_reach_mm", "Hepatic outlet reach", "mm", 5.0, 0.0, 30.0, "Territories",
         "An outlet whose end lies this near the liver feeds liver tissue; the others (gastroduodenal, gastric) feed "
         "none."},
        {"tumour_perfusion_factor", "Tumour perfusion factor", "", 3.0, 0.2, 20.0, "Territories",
         "Arterial perfusion of tumour tissue per volume over the liver's: a hypervascular HCC draws several times "
         "the surrounding liver's arterial flow (CT perfusion series report about 3-5 times)."},
        {"outlet_model", "Outlets from territories", "", 1.0, 0.0, 1.0, "Territories",
         "1: with a liver label, an outlet's resistance follows the tissue it feeds; 0: Murray's law of the terminal "
         "radius alone.", ParameterSpec::Kind::Integer},
    };
}

LiverTerritories liverTerritories(const VesselNetwork& network, const LabelRegion& liver, const LabelRegion* tumour,
                                  const ParameterSet& parameters, const Progress& progress,
                                  const std::function<bool(const Eigen::Vector3d&)>& tumourShape)
{
    LiverTerritories t;
    t.geometry = liver.label->geometry();
    t.voxelMl = t.geometry.spacing.prod() * 1e-3;
    t.tumourPerfusionFactor = parameters.get("tumour_perfusion_factor");
    const bool sameGrid = tumour && tumour->label->geometry().isClose(t.geometry, 1e-6);
    const std::uint8_t* l = liver.label->data();
    const std::uint8_t* u = sameGrid ? tumour->label->data() : nullptr;
    for (std::size_t i = 0; i < t.geometry.voxelCount(); ++i)
        if (liver.holds(l[i]) || (u && tumour->holds(u[i])))
            t.voxels.push_back(i);
    if (t.voxels.empty())
        throw Error("the liver label has no voxel of the liver's value");
    t.tumour.assign(t.voxels.size(), 0);
    if (tumour || tumourShape)
        for (std::size_t v = 0; v < t.voxels.size(); ++v)
            t.tumour[v] = u ? tumour->holds(u[t.voxels[v]]) : tumour ? tumour->contains(t.position(v)) : tumourShape(t.position(v));
    progress.report(0.1, localized("vsim::Progress", "liver voxels"));

    // The hepatic outlets, and the segments that lead to one: the vessels whose tissue is liver.
    const TipOrientation fromRoot = orientFromTip(network, network.root);
    std::vector<char> leadsToLiver(network.segments.size(), 0);
    for (int node : network.endNodes())
    {
        if (node == network.root)
            continue;
        if (!nearLiver(t, network.nodes[std::size_t(node)].positionMm, parameters.get("hepatic_reach_mm")))
        {
            t.extrahepatic.push_back(node);
            continue;
        }
        t.outlets.push_back(node);
        for (int n = node; n != network.root;)
        {
            const int s = fromRoot.parentSegment[std::size_t(n)];
            leadsToLiver[std::size_t(s)] = 1;
            n = fromRoot.upstreamNode[std::size_t(s)];
        }
    }
    if (t.outlets.empty())
        throw Error("no end of the vessel tree lies in the liver: there is no territory to share out");
    std::vector<Polyline> lines;
    std::vector<int> lineSegment;
    for (std::size_t s = 0; s < network.segments.size(); ++s)
        if (leadsToLiver[s])
            lines.emplace_back(network.segmentPath(s)), lineSegment.push_back(int(s));
    const std::vector<int> nearest = nearestPolylines(t, lines, progress.subRange(0.1, 1.0));
    t.fedBy.resize(t.voxels.size());
    t.volumeMl.assign(network.segments.size(), 0.0);
    t.tumourVolumeMl.assign(network.segments.size(), 0.0);
    for (std::size_t v = 0; v < t.voxels.size(); ++v)
    {
        const int s = lineSegment[std::size_t(nearest[v])];
        t.fedBy[v] = s;
        t.volumeMl[std::size_t(s)] += t.voxelMl;
        t.tumourVolumeMl[std::size_t(s)] += t.tumour[v] ? t.voxelMl : 0.0;
    }

    // The tissue dealt to the outlets: each segment's own, and what its ancestors pass down, shared among its
    // children by their subtrees' weights (V + (f - 1) V_tumour; an outlet's at least one voxel's).
    const double f = t.tumourPerfusionFactor;
    std::vector<double> subtree(network.segments.size(), 0.0);
    std::vector<std::vector<int>> children(network.nodes.size());
    for (std::size_t s = 0; s < network.segments.size(); ++s)
        if (fromRoot.active(int(s)))
            children[std::size_t(fromRoot.upstreamNode[s])].push_back(int(s));
    auto lowerEnd = [&](int s) {
        const auto& segment = network.segments[std::size_t(s)];
        return segment.from == fromRoot.upstreamNode[std::size_t(s)] ? segment.to : segment.from;
    };
    std::map<int, int> outletOf; // node -> index into t.outlets
    for (std::size_t o = 0; o < t.outlets.size(); ++o)
        outletOf[t.outlets[o]] = int(o);
    for (auto node = fromRoot.order.rbegin(); node != fromRoot.order.rend(); ++node)
        if (*node != network.root)
        {
            const int s = fromRoot.parentSegment[std::size_t(*node)];
            double w = t.volumeMl[std::size_t(s)] + (f - 1.0) * t.tumourVolumeMl[std::size_t(s)];
            for (int c : children[std::size_t(*node)])
                w += subtree[std::size_t(c)];
            if (outletOf.count(*node))
                w = std::max(w, t.voxelMl);
            subtree[std::size_t(s)] = w;
        }
    t.outletVolumeMl.assign(t.outlets.size(), 0.0);
    t.outletTumourVolumeMl.assign(t.outlets.size(), 0.0);
    std::vector<std::array<double, 2>> carried(network.segments.size(), {0.0, 0.0}); // liver, tumour ml passed down
    for (int node : fromRoot.order)
        if (node != network.root)
        {
            const int s = fromRoot.parentSegment[std::size_t(node)];
            const std::array<double, 2> total{carried[std::size_t(s)][0] + t.volumeMl[std::size_t(s)],
                                              carried[std::size_t(s)][1] + t.tumourVolumeMl[std::size_t(s)]};
            if (const auto outlet = outletOf.find(lowerEnd(s)); outlet != outletOf.end())
            {
                t.outletVolumeMl[std::size_t(outlet->second)] += total[0];
                t.outletTumourVolumeMl[std::size_t(outlet->second)] += total[1];
                continue;
            }
            double below = 0.0;
            for (int c : children[std::size_t(node)])
                below += subtree[std::size_t(c)];
            for (int c : children[std::size_t(node)])
                if (below > 0.0)
                    for (int k = 0; k < 2; ++k)
                        carried[std::size_t(c)][std::size_t(k)] += total[std::size_t(k)] * subtree[std::size_t(c)] / below;
        }
    return t;
}

void addTerritoryOutlets(VesselNetwork& network, const LiverTerritories& t, const ParameterSet& p)
{
    const std::vector<std::vector<int>> incident = network.incidentSegments();
    std::map<int, double> murray; // node -> radius cubed
    double cubes = 0.0;
    for (int node : network.endNodes())
        if (node != network.root)
        {
            const double r = meanRadius(network.segments[std::size_t(incident[std::size_t(node)].front())]);
            cubes += murray[node] = r * r * r;
        }
    double hepaticShare = 0.0, perfused = 0.0;
    std::vector<double> weight(t.outlets.size());
    for (std::size_t o = 0; o < t.outlets.size(); ++o)
    {
        hepaticShare += murray.at(t.outlets[o]) / cubes;
        weight[o] = std::max(t.voxelMl, t.outletVolumeMl[o] + (t.tumourPerfusionFactor - 1.0) * t.outletTumourVolumeMl[o]);
        perfused += weight[o];
    }
    std::map<int, double> share; // node -> share of the reference inflow
    for (const auto& [node, cube] : murray)
        share[node] = cube / cubes;
    for (std::size_t o = 0; o < t.outlets.size(); ++o)
        share[t.outlets[o]] = hepaticShare * weight[o] / perfused;
    std::map<int, bool> explicitNode;
    for (const VesselNetwork::Outlet& outlet : network.outlets)
        explicitNode[outlet.node] = true;
    const double inflow = units::mlPerMinToM3PerS(p.get("reference_inflow_ml_min"));
    const double drop = units::mmHgToPa(p.get("reference_pressure_drop_mmhg"));
    for (const auto& [node, s] : share)
        if (!explicitNode.count(node))
            network.outlets.push_back({node, VesselNetwork::Outlet::Type::Resistance,
                                       units::mmHgToPa(p.get("outlet_pressure_mmhg")), drop / (inflow * s)});
}

PerfusedTerritory perfusedTerritory(const LiverTerritories& t, const FlowSolution& flow)
{
    PerfusedTerritory p;
    const double injected = flow.injectedFlow;
    auto drugShare = [&](int node) {
        const auto found = flow.outletInjectate.find(node);
        return found == flow.outletInjectate.end() || !(injected > 0.0) ? 0.0 : found->second / injected;
    };
    for (std::size_t o = 0; o < t.outlets.size(); ++o) // the outlet's drug shared within its tissue by perfusion
    {
        const double drug = drugShare(t.outlets[o]);
        const double tumourWeight = t.tumourPerfusionFactor * t.outletTumourVolumeMl[o];
        const double weight = (t.outletVolumeMl[o] - t.outletTumourVolumeMl[o]) + tumourWeight;
        const double toTumour = weight > 0.0 ? drug * tumourWeight / weight : 0.0;
        p.drugToTumour += toTumour;
        p.drugToLiver += drug - toTumour;
    }
    for (int node : t.extrahepatic)
    {
        p.extrahepaticDrug.emplace_back(node, drugShare(node));
        p.drugExtrahepatic += drugShare(node);
    }
    p.drugElsewhere = std::max(0.0, 1.0 - p.drugToTumour - p.drugToLiver - p.drugExtrahepatic);
    // Segments carrying the drug: its fraction (1 downstream of the tip when the drug flows alone) in a flow.
    std::vector<double> fraction(flow.segmentFlow.size(), 0.0);
    for (std::size_t s = 0; s < flow.segmentFlow.size(); ++s)
        fraction[s] = flow.injectateFraction.empty() ? (flow.orientation.active(int(s)) ? 1.0 : 0.0) : flow.injectateFraction[s];
    const double largest = fraction.empty() ? 0.0 : *std::max_element(fraction.begin(), fraction.end());
    std::vector<char> carries(flow.segmentFlow.size(), 0);
    for (std::size_t s = 0; s < flow.segmentFlow.size(); ++s)
        if (largest > 0.0 && flow.segmentFlow[s] != 0.0 && fraction[s] >= kPerfusedShare * largest)
            carries[s] = 1, p.segments.push_back(int(s));
    p.perfused.assign(t.voxels.size(), 0);
    for (std::size_t v = 0; v < t.voxels.size(); ++v)
        if (std::size_t(t.fedBy[v]) < carries.size() && carries[std::size_t(t.fedBy[v])])
        {
            p.perfused[v] = 1;
            p.volumeMl += t.voxelMl;
            p.tumourVolumeMl += t.tumour[v] ? t.voxelMl : 0.0;
        }
    return p;
}

} // namespace vsim::sim::network
