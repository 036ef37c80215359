#include "vsim/sim/network/Lesions.h"

#include "TerritoryGrid.h"
#include "vsim/core/DistanceTransform.h"
#include "vsim/core/Error.h"
#include "vsim/core/Localized.h"
#include "vsim/sim/network/TipOrientation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <unordered_map>

namespace vsim::sim::network {

using detail::kSampleMm;
using detail::liverVoxel;
using detail::nearestLinear;
using detail::sampled;

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
        progress.report(double(l + 1) / double(lesions.size()), localized("vsim::Progress", "lesions and margins"));
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

std::vector<Feeder> editFeeders(std::vector<Feeder> found, const VesselNetwork& network, const std::vector<Lesion>& lesions,
                                const FeederEdits& edits)
{
    for (const std::vector<int>* list : {&edits.added, &edits.removed})
        for (int s : *list)
            if (s < 0 || std::size_t(s) >= network.segments.size())
                throw Error(Pattern{"feeder edit: segment %1 is not in the network (%2 segments)",
                                    {std::to_string(s), std::to_string(network.segments.size())}});
    for (int s : edits.added)
        if (std::find(edits.removed.begin(), edits.removed.end(), s) != edits.removed.end())
            throw Error(Pattern{"feeder edit: segment %1 is both added and removed", {std::to_string(s)}});
    std::erase_if(found, [&](const Feeder& f) {
        return std::find(edits.removed.begin(), edits.removed.end(), f.segment) != edits.removed.end();
    });
    if (lesions.empty() && !edits.added.empty())
        throw Error("feeder edit: there is no lesion for a feeder to feed");
    const TipOrientation fromRoot = orientFromTip(network, network.root);
    for (int s : edits.added)
    {
        if (std::any_of(found.begin(), found.end(), [&](const Feeder& f) { return f.segment == s; }))
            continue;
        Feeder f;
        f.segment = s;
        f.byHand = true;
        double best = 1e300;
        for (std::size_t l = 0; l < lesions.size(); ++l)
            for (const Eigen::Vector3d& p : sampled(network.segmentPath(std::size_t(s)), kSampleMm))
                if (const double d = (p - lesions[l].centreMm).norm(); d < best)
                    best = d, f.lesion = int(l), f.entryMm = p;
        const auto& segment = network.segments[std::size_t(s)];
        f.radiusMm = segment.from == fromRoot.upstreamNode[std::size_t(s)] ? segment.startRadiusMm : segment.endRadiusMm;
        found.push_back(f);
    }
    std::sort(found.begin(), found.end(), [](const Feeder& a, const Feeder& b) { return a.segment < b.segment; });
    return found;
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
        progress.report(double(i + 1) / double(ranking.size()), localized("vsim::Progress", "ranking catheter positions by coverage"));
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
