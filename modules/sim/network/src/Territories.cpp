#include "vsim/sim/network/Territories.h"

#include "vsim/core/DistanceTransform.h"
#include "vsim/core/Error.h"
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

constexpr double kSampleMm = 0.5;   ///< spacing of the points sampled along centerlines
constexpr double kSimplifyMm = 0.25; ///< a centerline simplified for the territories stays this near itself

/// Points along a polyline no further apart than `step` (mm), its vertices included.
std::vector<Eigen::Vector3d> sampled(const std::vector<Eigen::Vector3d>& path, double step)
{
    std::vector<Eigen::Vector3d> points;
    for (std::size_t i = 0; i + 1 < path.size(); ++i)
    {
        const int pieces = std::max(1, int(std::ceil((path[i + 1] - path[i]).norm() / step)));
        for (int k = 0; k < pieces; ++k)
            points.push_back(path[i] + (path[i + 1] - path[i]) * (double(k) / pieces));
    }
    if (!path.empty())
        points.push_back(path.back());
    return points;
}

/// The liver voxel (an index into territories.voxels) of a linear index; -1 when it is not liver.
long liverVoxel(const LiverTerritories& t, std::size_t linear)
{
    const auto found = std::lower_bound(t.voxels.begin(), t.voxels.end(), linear);
    return found != t.voxels.end() && *found == linear ? long(found - t.voxels.begin()) : -1;
}

/// The linear index of the voxel nearest a point; -1 off the grid.
long nearestLinear(const VolumeGeometry& g, const Eigen::Vector3d& pointMm)
{
    const Eigen::Vector3d index = g.patientToIndex(pointMm);
    const int i = int(std::lround(index.x())), j = int(std::lround(index.y())), k = int(std::lround(index.z()));
    return g.contains(i, j, k) ? long(g.linearIndex(i, j, k)) : -1;
}

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
            progress.report(double(done) / double(rows), "perfusion territories");
        });
    return nearest;
}

} // namespace

bool LabelRegion::contains(const Eigen::Vector3d& pointMm) const
{
    const long linear = nearestLinear(label->geometry(), pointMm);
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
    progress.report(0.1, "liver voxels");

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

std::vector<Lesion> findLesions(const LiverTerritories& t, const Progress& progress)
{
    const std::size_t nx = std::size_t(t.geometry.dims[0]), nxy = nx * std::size_t(t.geometry.dims[1]);
    const std::size_t count = t.geometry.voxelCount();
    auto tumourAt = [&](long linear) { // the liver voxel of a tumour voxel at a linear index; -1 when none
        if (linear < 0 || std::size_t(linear) >= count)
            return -1L;
        const long v = liverVoxel(t, std::size_t(linear));
        return v >= 0 && t.tumour[std::size_t(v)] ? v : -1L;
    };
    std::vector<int> component(t.voxels.size(), -1);
    std::vector<Lesion> lesions;
    std::vector<std::vector<std::size_t>> surfaces;
    for (std::size_t seed = 0; seed < t.voxels.size(); ++seed)
    {
        if (!t.tumour[seed] || component[seed] >= 0)
            continue;
        Lesion lesion;
        std::vector<std::size_t> surface;
        const int id = int(lesions.size());
        component[seed] = id;
        lesion.voxels.push_back(seed);
        for (std::size_t head = 0; head < lesion.voxels.size(); ++head)
        {
            const std::size_t v = lesion.voxels[head], linear = t.voxels[v];
            const std::size_t i = linear % nx, j = (linear / nx) % std::size_t(t.geometry.dims[1]), k = linear / nxy;
            const long neighbours[6] = {
                i > 0 ? long(linear - 1) : -1L, i + 1 < nx ? long(linear + 1) : -1L,
                j > 0 ? long(linear - nx) : -1L, j + 1 < std::size_t(t.geometry.dims[1]) ? long(linear + nx) : -1L,
                k > 0 ? long(linear - nxy) : -1L, k + 1 < std::size_t(t.geometry.dims[2]) ? long(linear + nxy) : -1L};
            bool onSurface = false;
            for (long n : neighbours)
            {
                const long w = tumourAt(n);
                if (w < 0)
                {
                    onSurface = true;
                    continue;
                }
                if (component[std::size_t(w)] < 0)
                    component[std::size_t(w)] = id, lesion.voxels.push_back(std::size_t(w));
            }
            if (onSurface)
                surface.push_back(v);
        }
        lesions.push_back(std::move(lesion));
        surfaces.push_back(std::move(surface));
    }
    for (std::size_t l = 0; l < lesions.size(); ++l)
    {
        progress.throwIfCancelled();
        Lesion& lesion = lesions[l];
        lesion.volumeMl = double(lesion.voxels.size()) * t.voxelMl;
        for (std::size_t v : lesion.voxels)
            lesion.centreMm += t.position(v) / double(lesion.voxels.size());
        // Longest diameter over (at most 3,000) surface voxels' centres.
        const std::vector<std::size_t>& surface = surfaces[l];
        const std::size_t stride = std::max<std::size_t>(1, surface.size() / 3000);
        std::vector<Eigen::Vector3d> points;
        for (std::size_t s = 0; s < surface.size(); s += stride)
            points.push_back(t.position(surface[s]));
        for (std::size_t a = 0; a < points.size(); ++a)
            for (std::size_t b = a + 1; b < points.size(); ++b)
                lesion.diameterMm = std::max(lesion.diameterMm, (points[a] - points[b]).norm());
        lesion.marginMm = lesion.diameterMm < 25.0 ? 5.0 : 10.0;
        // The margin: liver voxels outside every lesion within marginMm of this one (a distance transform on the
        // lesion's box grown by the margin).
        std::array<int, 3> lo{t.geometry.dims[0], t.geometry.dims[1], t.geometry.dims[2]}, hi{0, 0, 0};
        for (std::size_t v : surface)
        {
            const std::size_t linear = t.voxels[v];
            const std::array<int, 3> ijk{int(linear % nx), int((linear / nx) % std::size_t(t.geometry.dims[1])), int(linear / nxy)};
            for (int a = 0; a < 3; ++a)
                lo[std::size_t(a)] = std::min(lo[std::size_t(a)], ijk[std::size_t(a)]),
                hi[std::size_t(a)] = std::max(hi[std::size_t(a)], ijk[std::size_t(a)]);
        }
        std::array<int, 3> dims{};
        std::array<double, 3> spacing{};
        for (int a = 0; a < 3; ++a)
        {
            const int reach = int(std::ceil(lesion.marginMm / t.geometry.spacing[a]));
            lo[std::size_t(a)] = std::max(0, lo[std::size_t(a)] - reach);
            hi[std::size_t(a)] = std::min(t.geometry.dims[std::size_t(a)] - 1, hi[std::size_t(a)] + reach);
            dims[std::size_t(a)] = hi[std::size_t(a)] - lo[std::size_t(a)] + 1;
            spacing[std::size_t(a)] = t.geometry.spacing[a];
        }
        const std::size_t boxVoxels = std::size_t(dims[0]) * std::size_t(dims[1]) * std::size_t(dims[2]);
        std::vector<double> distance(boxVoxels, 1.0);
        auto boxIndex = [&](int i, int j, int k) {
            return std::size_t(i - lo[0]) + std::size_t(dims[0]) * (std::size_t(j - lo[1]) + std::size_t(dims[1]) * std::size_t(k - lo[2]));
        };
        for (std::size_t v : lesion.voxels)
        {
            const std::size_t linear = t.voxels[v];
            distance[boxIndex(int(linear % nx), int((linear / nx) % std::size_t(t.geometry.dims[1])), int(linear / nxy))] = 0.0;
        }
        squaredDistanceTransform(distance, dims, spacing);
        const double reachSquared = lesion.marginMm * lesion.marginMm;
        for (int k = lo[2]; k <= hi[2]; ++k)
            for (int j = lo[1]; j <= hi[1]; ++j)
                for (int i = lo[0]; i <= hi[0]; ++i)
                    if (distance[boxIndex(i, j, k)] <= reachSquared)
                        if (const long v = liverVoxel(t, t.geometry.linearIndex(i, j, k)); v >= 0 && !t.tumour[std::size_t(v)])
                            lesion.margin.push_back(std::size_t(v));
        progress.report(double(l + 1) / double(lesions.size()), "lesions and margins");
    }
    std::stable_sort(lesions.begin(), lesions.end(), [](const Lesion& a, const Lesion& b) { return a.voxels.size() > b.voxels.size(); });
    return lesions;
}

Coverage tumourCoverage(const std::vector<Lesion>& lesions, const PerfusedTerritory& perfused)
{
    Coverage coverage;
    coverage.grade = lesions.empty() ? '-' : 'A';
    auto covered = [&](const std::vector<std::size_t>& voxels) {
        if (voxels.empty())
            return 1.0;
        std::size_t n = 0;
        for (std::size_t v : voxels)
            n += perfused.perfused[v] ? 1 : 0;
        return double(n) / double(voxels.size());
    };
    for (const Lesion& lesion : lesions)
    {
        LesionCoverage c;
        const double tumour = covered(lesion.voxels), margin = covered(lesion.margin);
        c.coveredPercent = 100.0 * tumour;
        c.marginCoveredPercent = 100.0 * margin;
        c.grade = tumour < kCoveredShare ? 'C' : margin < kCoveredShare ? 'B' : 'A';
        coverage.grade = std::max(coverage.grade, c.grade);
        coverage.lesions.push_back(c);
    }
    return coverage;
}

std::vector<Feeder> findFeeders(const VesselNetwork& network, const LiverTerritories& t, const std::vector<Lesion>& lesions)
{
    std::unordered_map<std::size_t, int> target; // linear index -> lesion (its voxels and its margin)
    for (std::size_t l = 0; l < lesions.size(); ++l)
    {
        for (std::size_t v : lesions[l].voxels)
            target.emplace(t.voxels[v], int(l));
        for (std::size_t v : lesions[l].margin)
            target.emplace(t.voxels[v], int(l));
    }
    auto lesionAt = [&](const Eigen::Vector3d& p) {
        const long linear = nearestLinear(t.geometry, p);
        const auto found = linear >= 0 ? target.find(std::size_t(linear)) : target.end();
        return found == target.end() ? -1 : found->second;
    };
    const TipOrientation fromRoot = orientFromTip(network, network.root);
    std::map<int, Feeder> feeders;
    for (std::size_t s = 0; s < network.segments.size(); ++s)
    {
        const int upstream = fromRoot.upstreamNode[s];
        if (upstream < 0 || lesionAt(network.nodes[std::size_t(upstream)].positionMm) >= 0)
            continue;
        for (const Eigen::Vector3d& p : sampled(network.segmentPath(s), kSampleMm))
            if (const int l = lesionAt(p); l >= 0)
            {
                const auto& segment = network.segments[s];
                feeders[int(s)] = {int(s), l, true, segment.from == upstream ? segment.startRadiusMm : segment.endRadiusMm, p};
                break;
            }
    }
    // Segments whose tissue holds 1 % of a lesion or more.
    std::vector<std::map<int, std::size_t>> held(network.segments.size()); // segment -> lesion -> voxels
    for (std::size_t l = 0; l < lesions.size(); ++l)
        for (std::size_t v : lesions[l].voxels)
            ++held[std::size_t(t.fedBy[v])][int(l)];
    for (std::size_t s = 0; s < network.segments.size(); ++s)
        for (const auto& [l, n] : held[s])
            if (double(n) >= 0.01 * double(lesions[std::size_t(l)].voxels.size()) && !feeders.count(int(s)))
            {
                const auto& segment = network.segments[s];
                const bool fromUpstream = segment.from == fromRoot.upstreamNode[s];
                const Eigen::Vector3d& a = network.nodes[std::size_t(segment.from)].positionMm;
                const Eigen::Vector3d& b = network.nodes[std::size_t(segment.to)].positionMm;
                const Eigen::Vector3d& centre = lesions[std::size_t(l)].centreMm;
                feeders[int(s)] = {int(s), l, false, fromUpstream ? segment.startRadiusMm : segment.endRadiusMm,
                                   (a - centre).norm() < (b - centre).norm() ? a : b};
                break;
            }
    std::vector<Feeder> list;
    for (const auto& [s, f] : feeders)
        list.push_back(f);
    return list;
}

LabelVolume territoryLabel(const LiverTerritories& t, const PerfusedTerritory& perfused, const std::vector<Lesion>& lesions)
{
    LabelVolume label(t.geometry);
    for (std::size_t v = 0; v < t.voxels.size(); ++v)
        label.data()[t.voxels[v]] = t.tumour[v] ? (perfused.perfused[v] ? kTumourPerfused : kTumourMissed)
                                                : (perfused.perfused[v] ? kLiverPerfused : kLiverNotPerfused);
    for (const Lesion& lesion : lesions)
        for (std::size_t v : lesion.margin)
            if (!perfused.perfused[v])
                label.data()[t.voxels[v]] = kMarginMissed;
    return label;
}

std::vector<TipCandidate> rankTipsByCoverage(const VesselNetwork& network, const LiverTerritories& territories,
                                             const std::vector<Lesion>& lesions, const TipSolve& solve,
                                             const Progress& progress)
{
    std::vector<TipCandidate> ranking = tipCandidates(network);
    std::size_t lesionVoxels = 0;
    for (const Lesion& lesion : lesions)
        lesionVoxels += lesion.voxels.size();
    for (std::size_t i = 0; i < ranking.size(); ++i)
    {
        progress.throwIfCancelled();
        const PerfusedTerritory perfused = perfusedTerritory(territories, solve(ranking[i].node));
        const Coverage coverage = tumourCoverage(lesions, perfused);
        TipCandidate& c = ranking[i];
        c.grade = coverage.grade;
        c.tumourFraction = perfused.drugToTumour;
        c.nonTargetMl = perfused.volumeMl - perfused.tumourVolumeMl;
        std::size_t covered = 0;
        for (const Lesion& lesion : lesions)
            for (std::size_t v : lesion.voxels)
                covered += perfused.perfused[v] ? 1 : 0;
        c.coveredPercent = lesionVoxels ? 100.0 * double(covered) / double(lesionVoxels) : 0.0;
        progress.report(double(i + 1) / double(ranking.size()), "ranking catheter positions by coverage");
    }
    std::stable_sort(ranking.begin(), ranking.end(), [](const TipCandidate& a, const TipCandidate& b) {
        if (a.grade != b.grade)
            return a.grade < b.grade;
        if (std::abs(a.coveredPercent - b.coveredPercent) > 1e-9)
            return a.coveredPercent > b.coveredPercent;
        if (std::abs(a.nonTargetMl - b.nonTargetMl) > 1e-9)
            return a.nonTargetMl < b.nonTargetMl;
        return a.depth < b.depth;
    });
    return ranking;
}

} // namespace vsim::sim::network
