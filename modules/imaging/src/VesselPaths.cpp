#include "VesselPaths.h"

#include "GuidedHelpers.h"
#include "ShellOffsets.h"
#include "WorkBox.h"

#include "vsim/core/Localized.h"
#include "vsim/interop/ItkImage.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <functional>
#include <limits>
#include <optional>
#include <queue>

namespace vsim::imaging::detail {
namespace {

using Eigen::Vector3d;

constexpr double kPlateauMm = 1.0;                        // the plateau: brightest smoothed HU this close
constexpr double kBackgroundInnerMm = 2.5, kBackgroundOuterMm = 4.0; // the background shell of a path voxel

/// The 26 neighbour offsets and their lengths (mm).
struct Neighbours
{
    std::vector<std::array<int, 3>> offsets;
    std::vector<double> lengths;
    explicit Neighbours(const Vector3d& s)
    {
        for (int dk = -1; dk <= 1; ++dk)
            for (int dj = -1; dj <= 1; ++dj)
                for (int di = -1; di <= 1; ++di)
                    if (di || dj || dk)
                        offsets.push_back({di, dj, dk}), lengths.push_back(Vector3d(di * s.x(), dj * s.y(), dk * s.z()).norm());
    }
};

class PathJoiner
{
public:
    PathJoiner(const CtVolume& ct, LabelVolume& label, const std::vector<FrontSeed>& seeds, const PathSettings& settings)
        : m_ct(ct), m_label(label), m_settings(settings), m_neighbours(ct.geometry().spacing)
    {
        std::vector<FrontSeed> around = seeds;
        for (FrontSeed& seed : around)
            seed.maxLengthMm = settings.marginMm;
        m_box = workBox(ct, around);
        m_joined.assign(m_box.count(), 0);
    }

    void computeCost(const Progress& progress)
    {
        const VolumeGeometry& g = m_ct.geometry();
        VolumeGeometry sub = g;
        sub.dims = m_box.size;
        sub.origin = g.indexToPatient(Vector3d(m_box.low[0], m_box.low[1], m_box.low[2]));
        RealVolume image = RealVolume::uninitialized(sub);
        for (std::uint32_t b = 0; b < m_box.count(); ++b)
        {
            const auto [i, j, k] = m_box.voxel(b);
            image.data()[b] = float(m_ct.at(i, j, k));
        }
        progress.report(0.0, localized("vsim::Progress", "vesselness"));
        const std::vector<float> vesselness = frangiVesselness(interop::toItk(image).GetPointer(), m_settings.scales);
        progress.throwIfCancelled();
        m_cost.resize(vesselness.size());
        for (std::size_t b = 0; b < vesselness.size(); ++b)
            m_cost[b] = float(1.0 / (double(vesselness[b]) + m_settings.costFloor));
    }

    std::optional<std::uint32_t> boxIndexOf(const Vector3d& pointMm) const
    {
        const Vector3d x = m_ct.geometry().patientToIndex(pointMm);
        const int i = int(std::lround(x.x())), j = int(std::lround(x.y())), k = int(std::lround(x.z()));
        for (int a = 0; a < 3; ++a)
            if (const int v = a == 0 ? i : a == 1 ? j : k; v < m_box.low[a] || v >= m_box.low[a] + m_box.size[a])
                return std::nullopt;
        return m_box.index(i, j, k);
    }

    bool labelled(std::uint32_t b) const
    {
        const auto [i, j, k] = m_box.voxel(b);
        return m_label.at(i, j, k) != 0;
    }

    /// Marks the label's 26-connected piece through `start` (within the box) as joined.
    void joinPiece(std::uint32_t start)
    {
        if (!labelled(start))
            return;
        std::vector<std::uint32_t> stack{start};
        m_joined[start] = 1;
        while (!stack.empty())
        {
            const std::uint32_t b = stack.back();
            stack.pop_back();
            forNeighbours(b, [&](std::uint32_t n, double) {
                if (!m_joined[n] && labelled(n))
                    m_joined[n] = 1, stack.push_back(n);
            });
        }
    }

    bool isJoined(std::uint32_t b) const { return m_joined[b] != 0; }

    /// The cheapest path from `start` to a joined voxel (that voxel left out), or empty.
    std::vector<std::uint32_t> minimalPath(std::uint32_t start, double boneHu, const Progress& progress) const
    {
        std::vector<float> distance(m_box.count(), std::numeric_limits<float>::infinity());
        std::vector<std::uint32_t> parent(m_box.count(), std::numeric_limits<std::uint32_t>::max());
        using Entry = std::pair<float, std::uint32_t>;
        std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
        distance[start] = 0.0f;
        open.push({0.0f, start});
        std::size_t popped = 0;
        while (!open.empty())
        {
            const auto [d, b] = open.top();
            open.pop();
            if (d > distance[b])
                continue;
            if (++popped % 200000 == 0)
                progress.throwIfCancelled();
            if (m_joined[b])
            {
                std::vector<std::uint32_t> path;
                for (std::uint32_t p = parent[b]; p != std::numeric_limits<std::uint32_t>::max(); p = parent[p])
                    path.push_back(p);
                std::reverse(path.begin(), path.end());
                return path;
            }
            forNeighbours(b, [&](std::uint32_t n, double length) {
                const auto [i, j, k] = m_box.voxel(n);
                if (m_ct.at(i, j, k) > boneHu)
                    return;
                const float next = d + float(length * 0.5 * (double(m_cost[b]) + double(m_cost[n])));
                if (next < distance[n])
                    distance[n] = next, parent[n] = b, open.push({next, n});
            });
        }
        return {};
    }

    /// Labels the path and its lumen; returns the voxels added and adds the dim length to `dimMm`.
    std::size_t giveLumen(const std::vector<std::uint32_t>& path, double boneHu, double& dimMm)
    {
        const VolumeGeometry& g = m_ct.geometry();
        const auto plateau = shellOffsets(g.spacing, 0.0, kPlateauMm);
        const auto background = shellOffsets(g.spacing, kBackgroundInnerMm, kBackgroundOuterMm);
        std::vector<double> level(path.size());
        for (std::size_t p = 0; p < path.size(); ++p)
        {
            const auto [i, j, k] = m_box.voxel(path[p]);
            double peak = -1e9;
            for (const auto& [di, dj, dk] : plateau)
                if (g.contains(i + di, j + dj, k + dk))
                    peak = std::max(peak, smoothedHu(m_ct, i + di, j + dj, k + dk));
            std::vector<double> around;
            for (const auto& [di, dj, dk] : background)
                if (g.contains(i + di, j + dj, k + dk))
                    around.push_back(m_ct.at(i + di, j + dj, k + dk));
            std::nth_element(around.begin(), around.begin() + std::ptrdiff_t(around.size() / 2), around.end());
            level[p] = 0.5 * (peak + (around.empty() ? peak : around[around.size() / 2]));
            if (smoothedHu(m_ct, i, j, k) < level[p])
                dimMm += p > 0 ? stepMm(path[p - 1], path[p]) : 0.0;
        }
        std::size_t added = 0;
        const auto take = [&](std::uint32_t b) {
            const auto [i, j, k] = m_box.voxel(b);
            m_joined[b] = 1;
            if (m_label.at(i, j, k) == 0)
                m_label.at(i, j, k) = 1, ++added;
        };
        std::deque<std::pair<std::uint32_t, std::uint32_t>> queue; // (voxel, the path voxel it grew from)
        for (std::size_t p = 0; p < path.size(); ++p)
            take(path[p]), queue.push_back({path[p], std::uint32_t(p)});
        while (!queue.empty())
        {
            const auto [b, origin] = queue.front();
            queue.pop_front();
            const auto [oi, oj, ok] = m_box.voxel(path[origin]);
            forNeighbours(b, [&](std::uint32_t n, double) {
                if (m_joined[n])
                    return;
                const auto [i, j, k] = m_box.voxel(n);
                const double hu = m_ct.at(i, j, k);
                const double away = Vector3d((i - oi) * g.spacing.x(), (j - oj) * g.spacing.y(), (k - ok) * g.spacing.z()).norm();
                if (m_label.at(i, j, k) != 0 || away > m_settings.tubeRadiusMm || hu < level[origin] || hu > boneHu)
                    return;
                take(n);
                queue.push_back({n, origin});
            });
        }
        return added;
    }

    double stepMm(std::uint32_t a, std::uint32_t b) const
    {
        const auto [ai, aj, ak] = m_box.voxel(a);
        const auto [bi, bj, bk] = m_box.voxel(b);
        const Vector3d s = m_ct.geometry().spacing;
        return Vector3d((ai - bi) * s.x(), (aj - bj) * s.y(), (ak - bk) * s.z()).norm();
    }

private:
    template <typename Visit>
    void forNeighbours(std::uint32_t b, const Visit& visit) const
    {
        const auto [i, j, k] = m_box.voxel(b);
        for (std::size_t n = 0; n < m_neighbours.offsets.size(); ++n)
        {
            const auto& [di, dj, dk] = m_neighbours.offsets[n];
            const int ii = i + di, jj = j + dj, kk = k + dk;
            if (ii < m_box.low[0] || jj < m_box.low[1] || kk < m_box.low[2] || ii >= m_box.low[0] + m_box.size[0] ||
                jj >= m_box.low[1] + m_box.size[1] || kk >= m_box.low[2] + m_box.size[2])
                continue;
            visit(m_box.index(ii, jj, kk), m_neighbours.lengths[n]);
        }
    }

    const CtVolume& m_ct;
    LabelVolume& m_label;
    const PathSettings& m_settings;
    Neighbours m_neighbours;
    WorkBox m_box;
    std::vector<std::uint8_t> m_joined;
    std::vector<float> m_cost;
};

} // namespace

PathResult joinByMinimalPaths(const CtVolume& ct, LabelVolume& label, const FrontSeed& trunk,
                              const std::vector<FrontSeed>& points, const PathSettings& settings, const Progress& progress)
{
    PathResult result;
    std::vector<FrontSeed> all = points;
    all.push_back(trunk);
    PathJoiner joiner(ct, label, all, settings);
    const auto trunkVoxel = joiner.boxIndexOf(trunk.pointMm);
    if (!trunkVoxel || !joiner.labelled(*trunkVoxel))
        return result;
    joiner.joinPiece(*trunkVoxel);
    // The points nearest the trunk first: a farther point's path may then end on a nearer one's.
    std::vector<std::size_t> order(points.size());
    for (std::size_t n = 0; n < points.size(); ++n)
        order[n] = n;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return (points[a].pointMm - trunk.pointMm).norm() < (points[b].pointMm - trunk.pointMm).norm();
    });
    bool costed = false;
    for (std::size_t step = 0; step < order.size(); ++step)
    {
        const FrontSeed& seed = points[order[step]];
        const auto start = joiner.boxIndexOf(seed.pointMm);
        if (!start)
            continue;
        if (joiner.isJoined(*start)) // its front met the trunk's piece, or an earlier path did
            continue;
        if (!costed)
            joiner.computeCost(progress.subRange(0.0, 0.6)), costed = true;
        const std::vector<std::uint32_t> path = joiner.minimalPath(*start, seed.boneHu, progress);
        progress.report(0.6 + 0.4 * double(step + 1) / double(order.size()), localized("vsim::Progress", "minimal paths"));
        if (path.empty())
        {
            result.notes.push_back("the point " + mmText(seed.pointMm) +
                                   " could not be joined to the trunk within the search box: add a point between them");
            continue;
        }
        double dimMm = 0.0;
        for (std::size_t p = 1; p < path.size(); ++p)
            result.pathMm += joiner.stepMm(path[p - 1], path[p]);
        result.voxelsAdded += joiner.giveLumen(path, seed.boneHu, dimMm);
        result.dimPathMm += dimMm;
        ++result.joined;
        // The point's own front joins too (it may have grown on beyond the point).
        if (joiner.labelled(*start))
            joiner.joinPiece(*start);
    }
    if (result.dimPathMm > 5.0)
    {
        char text[200];
        std::snprintf(text, sizeof text,
                      "%.0f mm of the minimal paths between the points run below their half level: check the path on "
                      "the images (a point in another vessel?)",
                      result.dimPathMm);
        result.notes.push_back(text);
    }
    return result;
}

} // namespace vsim::imaging::detail
