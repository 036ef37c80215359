#include "vsim/imaging/Skeletonization.h"

#include "LabelGeometry.h"
#include "SkeletonGrid.h"
#include "vsim/core/Localized.h"

#include <algorithm>
#include <functional>
#include <cmath>
#include <map>
#include <queue>
#include <optional>
#include <set>

namespace vsim::imaging {
namespace {

/// Face directions of the six thinning sub-iterations, as indices into SkeletonGrid::step.
std::array<int, 6> faceDirections(const SkeletonGrid& grid)
{
    std::array<int, 6> faces{};
    int f = 0;
    for (int n = 0; n < 26; ++n)
        if (std::abs(grid.step[n][0]) + std::abs(grid.step[n][1]) + std::abs(grid.step[n][2]) == 1)
            faces[std::size_t(f++)] = n;
    return faces;
}

void thin(SkeletonGrid& grid, const Progress& progress)
{
    std::vector<std::size_t> objects;
    for (std::size_t index = 0; index < grid.voxels.size(); ++index)
        if (grid.voxels[index])
            objects.push_back(index);
    const std::array<int, 6> faces = faceDirections(grid);
    const std::size_t initial = objects.size();
    bool changed = true;
    std::vector<std::size_t> candidates;
    while (changed)
    {
        changed = false;
        for (int face : faces)
        {
            const std::ptrdiff_t outward = grid.neighbour[std::size_t(face)];
            candidates.clear();
            auto removable = [&](std::size_t index) {
                const std::uint32_t neighbours = grid.neighbourhood(index);
                return __builtin_popcount(neighbours) > 1 && SkeletonGrid::isSimpleNeighbourhood(neighbours);
            };
            for (std::size_t index : objects)
                if (grid.voxels[index] && !grid.voxels[std::size_t(std::ptrdiff_t(index) + outward)] && removable(index))
                    candidates.push_back(index);
            for (std::size_t index : candidates) // sequential re-check keeps the topology
                if (removable(index))
                {
                    grid.voxels[index] = 0;
                    changed = true;
                }
        }
        objects.erase(std::remove_if(objects.begin(), objects.end(), [&](std::size_t i) { return !grid.voxels[i]; }),
                      objects.end());
        progress.report(1.0 - double(objects.size()) / double(initial), localized("vsim::Progress", "thinning"));
    }
}

bool isCrowded(const SkeletonGrid& grid, std::size_t index)
{
    if (!grid.voxels[index] || grid.degree(index) <= 2)
        return false;
    for (std::ptrdiff_t offset : grid.neighbour)
    {
        const std::size_t next = std::size_t(std::ptrdiff_t(index) + offset);
        if (grid.voxels[next] && grid.degree(next) > 2)
            return true;
    }
    return false;
}

Eigen::Vector3d millimetres(const SkeletonGrid& grid, std::size_t index, const Eigen::Vector3d& spacing)
{
    const auto v = grid.voxelOf(index);
    return Eigen::Vector3d(v[0], v[1], v[2]).cwiseProduct(spacing);
}

/// The region voxel with the least summed distance to the others (spatial median).
std::size_t spatialMedian(const SkeletonGrid& grid, const std::vector<std::size_t>& region, const Eigen::Vector3d& spacing)
{
    std::size_t best = region.front();
    double bestSum = 1e300;
    for (std::size_t candidate : region)
    {
        double sum = 0;
        for (std::size_t other : region)
            sum += (millimetres(grid, candidate, spacing) - millimetres(grid, other, spacing)).norm();
        if (sum < bestSum)
            bestSum = sum, best = candidate;
    }
    return best;
}

bool adjacent(const SkeletonGrid& grid, std::size_t a, std::size_t b)
{
    for (std::ptrdiff_t offset : grid.neighbour)
        if (std::size_t(std::ptrdiff_t(a) + offset) == b)
            return true;
    return false;
}

/// Shortest path (26-connected, mm weights) through `allowed` from `from` to a voxel next to `exit`, avoiding
/// voxels for which `blocked` holds. Returns the path from its last voxel back to `from`; empty when none.
std::vector<std::size_t> shortestPathTo(const SkeletonGrid& grid, const std::set<std::size_t>& allowed, std::size_t from,
                                        std::size_t exit, const Eigen::Vector3d& spacing,
                                        const std::function<bool(std::size_t)>& blocked)
{
    std::map<std::size_t, double> distance{{from, 0.0}};
    std::map<std::size_t, std::size_t> previous;
    using Entry = std::pair<double, std::size_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
    queue.push({0.0, from});
    while (!queue.empty())
    {
        const auto [d, current] = queue.top();
        queue.pop();
        if (d > distance[current])
            continue;
        if (adjacent(grid, current, exit))
        {
            std::vector<std::size_t> path{current};
            while (path.back() != from)
                path.push_back(previous[path.back()]);
            return path;
        }
        for (std::size_t n = 0; n < 26; ++n)
        {
            const std::size_t next = std::size_t(std::ptrdiff_t(current) + grid.neighbour[n]);
            if (!allowed.count(next) || blocked(next))
                continue;
            const double step = Eigen::Vector3d(grid.step[n][0], grid.step[n][1], grid.step[n][2]).cwiseProduct(spacing).norm();
            const auto known = distance.find(next);
            if (known == distance.end() || d + step < known->second)
            {
                distance[next] = d + step;
                previous[next] = current;
                queue.push({d + step, next});
            }
        }
    }
    return {};
}

/// Routes paths from `centre` to every exit so that voxels of different paths never touch (except through the
/// centre) and no path voxel touches another path's exit. Paths are routed one after the other, so the order
/// matters: up to 24 orders of the exits are tried. Returns the union of the paths (with the centre), or nothing
/// when no order separates them; `fallback` then receives the first order's routing, where an exit without a
/// separated route took its plain shortest path (every exit stays connected).
std::optional<std::set<std::size_t>> routeStar(const SkeletonGrid& grid, const std::set<std::size_t>& allowed,
                                               std::size_t centre, const std::set<std::size_t>& exits,
                                               const Eigen::Vector3d& spacing, std::set<std::size_t>* fallback)
{
    std::vector<std::size_t> order(exits.begin(), exits.end());
    for (int attempt = 0; attempt < 24; ++attempt)
    {
        std::set<std::size_t> routed{centre};
        bool clean = true;
        for (std::size_t exit : order)
        {
            auto blocked = [&](std::size_t v) {
                for (std::size_t other : exits)
                    if (other != exit && adjacent(grid, v, other))
                        return true;
                for (std::size_t voxel : routed)
                    if (voxel != centre && adjacent(grid, v, voxel))
                        return true;
                return false;
            };
            std::vector<std::size_t> path = shortestPathTo(grid, allowed, centre, exit, spacing, blocked);
            if (path.empty())
            {
                clean = false;
                if (attempt > 0)
                    break;
                path = shortestPathTo(grid, allowed, centre, exit, spacing, [](std::size_t) { return false; });
            }
            routed.insert(path.begin(), path.end());
        }
        if (clean)
            return routed;
        if (attempt == 0)
            *fallback = routed;
        if (!std::next_permutation(order.begin(), order.end()))
            break;
    }
    return std::nullopt;
}

/// One VDSM pass (see removeCrowdedPoints). Paths from the centre to the exits are routed so that voxels of
/// different paths never touch (except through the centre), which is what makes the result unit-width; they run
/// through the crowded region and, where it has no such route, through lumen voxels next to it (`lumen`, same
/// grid; empty: the region only). Returns the number of voxels changed.
std::size_t vdsmPass(SkeletonGrid& grid, const Eigen::Vector3d& spacing, const std::vector<std::uint8_t>& lumen)
{
    std::vector<std::uint8_t> crowded(grid.voxels.size(), 0);
    for (std::size_t index = 0; index < grid.voxels.size(); ++index)
        crowded[index] = isCrowded(grid, index);
    std::vector<std::uint8_t> visited(grid.voxels.size(), 0);
    std::size_t changed = 0;
    for (std::size_t seed = 0; seed < grid.voxels.size(); ++seed)
    {
        if (!crowded[seed] || visited[seed])
            continue;
        // The crowded region (26-connected) and its exit points.
        std::vector<std::size_t> region{seed};
        visited[seed] = 1;
        for (std::size_t r = 0; r < region.size(); ++r)
            for (std::ptrdiff_t offset : grid.neighbour)
            {
                const std::size_t next = std::size_t(std::ptrdiff_t(region[r]) + offset);
                if (crowded[next] && !visited[next])
                    visited[next] = 1, region.push_back(next);
            }
        // Route a star from the centre to every exit; where the region is too tight for separated paths, take
        // the exits into the region (the next skeleton voxels become the exits) and try again, up to 3 times.
        std::set<std::size_t> exits, routed, firstRouted;
        const std::vector<std::size_t> firstRegion = region;
        // Growing helps where the vessel is a few voxels wide (no room for separated paths); in a wide one the
        // first routing is kept. Thin: under half of the 5 x 5 x 5 block around the region's first voxel is lumen.
        bool thin = !lumen.empty();
        if (thin)
        {
            int inside = 0;
            const auto v = grid.voxelOf(region.front());
            for (int dk = -2; dk <= 2; ++dk)
                for (int dj = -2; dj <= 2; ++dj)
                    for (int di = -2; di <= 2; ++di)
                    {
                        const std::array<int, 3> u{v[0] + di, v[1] + dj, v[2] + dk};
                        bool within = true;
                        for (int a = 0; a < 3; ++a)
                            within = within && u[a] >= grid.start[a] && u[a] < grid.start[a] + grid.dims[a];
                        inside += within && lumen[grid.indexOf(u)];
                    }
            thin = inside < 63;
        }
        for (int growth = 0; growth <= 3; ++growth)
        {
            const std::set<std::size_t> members(region.begin(), region.end());
            exits.clear();
            for (std::size_t member : region)
                for (std::ptrdiff_t offset : grid.neighbour)
                {
                    const std::size_t next = std::size_t(std::ptrdiff_t(member) + offset);
                    if (grid.voxels[next] && !members.count(next))
                        exits.insert(next);
                }
            std::set<std::size_t> allowed(members);
            if (!lumen.empty())
                for (std::size_t member : region)
                    for (std::ptrdiff_t offset : grid.neighbour)
                    {
                        const std::size_t next = std::size_t(std::ptrdiff_t(member) + offset);
                        if (lumen[next] && !grid.voxels[next])
                            allowed.insert(next);
                    }
            const std::size_t centre = spatialMedian(grid, region, spacing);
            const std::optional<std::set<std::size_t>> star = routeStar(grid, allowed, centre, exits, spacing, &routed);
            const bool clean = star.has_value();
            if (clean)
                routed = *star;
            if (growth == 0)
                firstRouted = routed;
            if (clean)
                break;
            if (growth == 3 || !thin) // never separated (or a wide vessel): keep the first, smallest change
            {
                region = firstRegion;
                routed = firstRouted;
                break;
            }
            for (std::size_t exit : exits) // grow: the exits join the region
            {
                region.push_back(exit);
                visited[exit] = 1;
            }
        }
        for (std::size_t member : region)
            if (!routed.count(member))
                grid.voxels[member] = 0, ++changed;
        for (std::size_t voxel : routed)
            if (!grid.voxels[voxel])
                grid.voxels[voxel] = 1, ++changed;
    }
    return changed;
}

/// What VDSM's routing could not separate: crowded voxels that are simple points of the skeleton (deleting one
/// keeps every component, tunnel and cavity) are deleted, one at a time, until none is left.
std::size_t deleteSimpleCrowdedVoxels(SkeletonGrid& grid)
{
    std::size_t deleted = 0;
    bool changed = true;
    while (changed)
    {
        changed = false;
        for (std::size_t index = 0; index < grid.voxels.size(); ++index)
            if (isCrowded(grid, index) && grid.isSimple(index))
            {
                grid.voxels[index] = 0;
                ++deleted;
                changed = true;
            }
    }
    return deleted;
}

std::size_t countCrowded(const SkeletonGrid& grid)
{
    std::size_t count = 0;
    for (std::size_t index = 0; index < grid.voxels.size(); ++index)
        count += isCrowded(grid, index);
    return count;
}

/// One traced skeleton branch between two nodes (voxels of degree != 2), grid indices, both ends included.
struct Branch
{
    std::vector<std::size_t> path;
};

std::vector<Branch> traceBranches(const SkeletonGrid& grid)
{
    std::vector<Branch> branches;
    std::set<std::pair<std::size_t, std::size_t>> used; // (node, first step) pairs already traced
    for (std::size_t node = 0; node < grid.voxels.size(); ++node)
    {
        if (!grid.voxels[node] || grid.degree(node) == 2)
            continue;
        for (std::ptrdiff_t offset : grid.neighbour)
        {
            const std::size_t first = std::size_t(std::ptrdiff_t(node) + offset);
            if (!grid.voxels[first] || used.count({node, first}))
                continue;
            Branch branch{{node, first}};
            std::size_t previous = node, current = first;
            while (grid.degree(current) == 2)
            {
                std::size_t next = current;
                for (std::ptrdiff_t o : grid.neighbour)
                {
                    const std::size_t candidate = std::size_t(std::ptrdiff_t(current) + o);
                    if (grid.voxels[candidate] && candidate != previous)
                        next = candidate;
                }
                if (next == current || next == branch.path.front())
                    break;
                branch.path.push_back(next);
                previous = current;
                current = next;
            }
            used.insert({node, first});
            used.insert({branch.path.back(), branch.path[branch.path.size() - 2]});
            branches.push_back(std::move(branch));
        }
    }
    return branches;
}

double pathLength(const SkeletonGrid& grid, const std::vector<std::size_t>& path, const Eigen::Vector3d& spacing)
{
    double length = 0;
    for (std::size_t p = 1; p < path.size(); ++p)
        length += (millimetres(grid, path[p], spacing) - millimetres(grid, path[p - 1], spacing)).norm();
    return length;
}

} // namespace

std::vector<ParameterSpec> skeletonParameters()
{
    const std::string group = "Skeleton";
    return {
        {"prune_factor", "Spur length / radius", "", 1.5, 0, 10, group,
         "End branches shorter than this many lumen radii at their junction are spurs of the thinning."},
        {"min_branch_mm", "Shortest end branch", "mm", 2.0, 0, 50, group, "End branches shorter than this are spurs."},
    };
}

LabelVolume thinToCurves(const LabelVolume& label, std::uint8_t value, const Progress& progress)
{
    SkeletonGrid grid = SkeletonGrid::fromLabel(label, value);
    thin(grid, progress);
    return grid.toLabel(label.geometry());
}

std::size_t countCrowdedVoxels(const LabelVolume& skeleton)
{
    return countCrowded(SkeletonGrid::fromLabel(skeleton, 1));
}

std::size_t removeCrowdedPoints(LabelVolume& skeleton, const LabelVolume* lumen)
{
    SkeletonGrid grid = SkeletonGrid::fromLabel(skeleton, 1);
    const std::vector<std::uint8_t> inside = lumen ? grid.maskOf(*lumen, 1) : std::vector<std::uint8_t>{};
    std::size_t changed = 0;
    for (int pass = 0; pass < 10 && countCrowded(grid) > 0; ++pass)
    {
        const std::size_t now = vdsmPass(grid, skeleton.geometry().spacing, inside);
        changed += now;
        if (now == 0)
            break;
    }
    changed += deleteSimpleCrowdedVoxels(grid);
    skeleton = grid.toLabel(skeleton.geometry());
    return changed;
}

SkeletonResult extractSkeleton(const LabelVolume& label, std::uint8_t value, const ParameterSet& p,
                               const Progress& progress)
{
    const VolumeGeometry& geometry = label.geometry();
    const Eigen::Vector3d spacing = geometry.spacing;
    SkeletonResult result;
    SkeletonGrid grid = SkeletonGrid::fromLabel(label, value);
    thin(grid, progress.subRange(0.0, 0.7));
    result.thinnedVoxels = std::size_t(std::count(grid.voxels.begin(), grid.voxels.end(), 1));
    result.crowdedAfterThinning = countCrowded(grid);
    const std::vector<std::uint8_t> lumen = grid.maskOf(label, value);
    for (int pass = 0; pass < 10 && countCrowded(grid) > 0; ++pass)
        if (vdsmPass(grid, spacing, lumen) == 0)
            break;
    deleteSimpleCrowdedVoxels(grid);
    progress.report(0.8, localized("vsim::Progress", "pruning"));
    // One voxel of margin holds the background nearest to the lumen (the volume's border is not background).
    const CroppedDistance distance = croppedInsideDistanceMm(label, value, 1);
    auto radiusAt = [&](std::size_t index) {
        return std::max(double(distance.at(grid.voxelOf(index))), 0.5 * spacing.minCoeff());
    };

    // Spur pruning: end branches short against the lumen radius where they leave a junction.
    bool pruned = true;
    while (pruned)
    {
        pruned = false;
        for (const Branch& branch : traceBranches(grid))
        {
            const std::size_t a = branch.path.front(), b = branch.path.back();
            const int degreeA = grid.degree(a), degreeB = grid.degree(b);
            if (!((degreeA == 1 && degreeB >= 3) || (degreeB == 1 && degreeA >= 3)))
                continue;
            const std::size_t junction = degreeA >= 3 ? a : b;
            const double limit = std::max(p.get("min_branch_mm"), p.get("prune_factor") * radiusAt(junction));
            if (pathLength(grid, branch.path, spacing) >= limit)
                continue;
            for (std::size_t voxel : branch.path)
                if (voxel != junction)
                    grid.voxels[voxel] = 0;
            ++result.prunedBranches;
            pruned = true;
            break; // degrees changed: trace again
        }
    }
    result.crowdedAfterVdsm = countCrowded(grid);

    // The graph.
    std::map<std::size_t, int> nodeOf;
    auto node = [&](std::size_t index) {
        const auto found = nodeOf.find(index);
        if (found != nodeOf.end())
            return found->second;
        const auto v = grid.voxelOf(index);
        result.graph.nodes.push_back({geometry.indexToPatient(Eigen::Vector3d(v[0], v[1], v[2])), v});
        return nodeOf[index] = int(result.graph.nodes.size()) - 1;
    };
    for (const Branch& branch : traceBranches(grid))
    {
        SkeletonGraph::Edge edge;
        edge.from = node(branch.path.front());
        edge.to = node(branch.path.back());
        for (std::size_t index : branch.path)
        {
            const auto v = grid.voxelOf(index);
            edge.voxels.push_back(v);
            edge.points.push_back(geometry.indexToPatient(Eigen::Vector3d(v[0], v[1], v[2])));
            edge.radii.push_back(radiusAt(index));
        }
        result.graph.edges.push_back(std::move(edge));
    }
    result.skeleton = grid.toLabel(geometry);
    progress.report(1.0, localized("vsim::Progress", "skeleton"));
    return result;
}

} // namespace vsim::imaging
