// Anatomical names of centerline segments: the tree rooted at its upstream end, vessels followed through their
// side branches, and each division matched against the usual aortic and hepatic patterns (VesselNames.h).

#include "vsim/imaging/VesselNames.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

namespace vsim::imaging {
namespace {

using Eigen::Vector3d;

constexpr double kAortaMinRadiusMm = 5.0;   // median lumen radius of the aorta's first segment
constexpr double kDirectionLengthMm = 15.0; // a branch's direction: its first 15 mm beyond the parent's lumen

struct Division
{
    std::vector<int> edges; ///< the vessel's edges, junction bridges included, upstream first
    std::vector<int> kids;  ///< the children where it ended (largest first); empty at a free end
    int last = -1;          ///< its last edge
};

class TreeNamer
{
public:
    explicit TreeNamer(const SkeletonGraph& graph) : g_(graph), names_(graph.edges.size(), kUnnamedSegment) {}

    std::vector<std::string> run()
    {
        if (g_.edges.empty())
            return names_;
        orient(rootNode());
        if (rootEdge_ < 0)
            return names_;
        // A wide root that is not aortic (a pulmonary trunk, a vein) leaves every segment unnamed.
        if (radius(rootEdge_) >= kAortaMinRadiusMm)
            nameAorta(rootEdge_);
        else
            nameTreeWithoutAorta(rootEdge_);
        return names_;
    }

private:
    // --- the tree -------------------------------------------------------------------------------------------

    /// The upstream end: of the endpoints whose segment is at least 0.6 x the widest end segment, the highest
    /// when that is aorta-wide (the aortic inlet, or the ascending aorta's root), else the widest (a branch tree).
    int rootNode() const
    {
        std::vector<int> ends = g_.endpoints();
        if (ends.empty())
            return g_.edges.front().from;
        std::vector<double> endRadius;
        for (int node : ends)
            for (std::size_t e = 0; e < g_.edges.size(); ++e)
                if (g_.edges[e].from == node || g_.edges[e].to == node)
                {
                    endRadius.push_back(median(g_.edges[e].radii, true));
                    break;
                }
        const double widest = *std::max_element(endRadius.begin(), endRadius.end());
        int best = -1;
        for (std::size_t i = 0; i < ends.size(); ++i)
        {
            if (widest < kAortaMinRadiusMm)
            {
                if (endRadius[i] == widest)
                    return ends[i];
                continue;
            }
            if (endRadius[i] >= 0.6 * widest &&
                (best < 0 || g_.nodes[std::size_t(ends[i])].position.z() > g_.nodes[std::size_t(best)].position.z()))
                best = ends[i];
        }
        return best;
    }

    /// Orients every edge away from the root along the widest paths (Dijkstra with the cost length / r^2 per
    /// edge, so that a path keeps to the wide lumen rather than to the skeleton's loops in a sac); an edge that
    /// closes a loop starts at its cheaper node and gets no children.
    void orient(int root)
    {
        const std::size_t edgeCount = g_.edges.size();
        std::vector<std::vector<int>> incident(g_.nodes.size());
        for (std::size_t e = 0; e < edgeCount; ++e)
        {
            incident[std::size_t(g_.edges[e].from)].push_back(int(e));
            if (g_.edges[e].to != g_.edges[e].from)
                incident[std::size_t(g_.edges[e].to)].push_back(int(e));
        }
        start_.assign(edgeCount, -1);
        parent_.assign(edgeCount, -1);
        children_.assign(edgeCount, {});
        radius_.resize(edgeCount);
        for (std::size_t e = 0; e < edgeCount; ++e)
            radius_[e] = median(g_.edges[e].radii, true);
        std::vector<double> cost(g_.nodes.size(), std::numeric_limits<double>::infinity());
        std::vector<int> via(g_.nodes.size(), -1);
        std::vector<bool> done(g_.nodes.size(), false);
        using Entry = std::pair<double, int>;
        std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
        cost[std::size_t(root)] = 0.0;
        queue.push({0.0, root});
        while (!queue.empty())
        {
            const auto [c, node] = queue.top();
            queue.pop();
            if (done[std::size_t(node)])
                continue;
            done[std::size_t(node)] = true;
            for (int e : incident[std::size_t(node)])
            {
                const auto& edge = g_.edges[std::size_t(e)];
                const int far = edge.from == node ? edge.to : edge.from;
                const double r = std::max(radius(e), 0.3);
                const double next = c + length(e) / (r * r);
                if (!done[std::size_t(far)] && next < cost[std::size_t(far)])
                {
                    cost[std::size_t(far)] = next;
                    via[std::size_t(far)] = e;
                    queue.push({next, far});
                }
            }
        }
        for (std::size_t e = 0; e < edgeCount; ++e)
        {
            const auto& edge = g_.edges[e];
            if (!std::isfinite(cost[std::size_t(edge.from)]))
                continue; // another component
            const bool fromFirst = via[std::size_t(edge.to)] == int(e) ||
                                   (via[std::size_t(edge.from)] != int(e) && cost[std::size_t(edge.from)] <= cost[std::size_t(edge.to)]);
            start_[e] = fromFirst ? edge.from : edge.to;
        }
        for (std::size_t e = 0; e < edgeCount; ++e)
        {
            if (start_[e] < 0)
                continue;
            const int parent = via[std::size_t(start_[e])];
            if (parent >= 0 && parent != int(e))
            {
                children_[std::size_t(parent)].push_back(int(e));
                parent_[e] = parent;
            }
            else if (start_[e] == root && (rootEdge_ < 0 || radius(int(e)) > radius(rootEdge_)))
                rootEdge_ = int(e);
        }
    }

    int endNode(int e) const
    {
        const auto& edge = g_.edges[std::size_t(e)];
        return edge.from == start_[std::size_t(e)] ? edge.to : edge.from;
    }
    bool forward(int e) const { return g_.edges[std::size_t(e)].from == start_[std::size_t(e)]; }
    double radius(int e) const { return radius_[std::size_t(e)]; }
    double length(int e) const { return g_.edges[std::size_t(e)].length(); }

    /// Median of `values` (of the middle 60 % when `middle`, away from the junctions' widening).
    static double median(std::vector<double> values, bool middle)
    {
        if (values.empty())
            return 0.0;
        if (middle && values.size() >= 5)
            values = std::vector<double>(values.begin() + long(values.size() / 5), values.end() - long(values.size() / 5));
        std::nth_element(values.begin(), values.begin() + long(values.size() / 2), values.end());
        return values[values.size() / 2];
    }

    /// The lumen radius where edge `e` ends (its last five points), mm.
    double radiusAtEnd(int e) const
    {
        const auto& radii = g_.edges[std::size_t(e)].radii;
        const std::size_t n = std::min<std::size_t>(5, radii.size());
        std::vector<double> last = forward(e) ? std::vector<double>(radii.end() - long(n), radii.end())
                                              : std::vector<double>(radii.begin(), radii.begin() + long(n));
        return median(last, false);
    }

    /// How far `p` lies outside the aortic lumen (mm; the distance to the aortic centerline less its radius there;
    /// infinite before the aorta is found or without one).
    double outsideAorta(const Vector3d& p) const
    {
        double nearest = std::numeric_limits<double>::infinity();
        for (const auto& [q, r] : aortic_)
            nearest = std::min(nearest, (p - q).norm() - r);
        return nearest;
    }

    /// The longest path (mm) from the start of edge `e` down its subtree.
    double reach(int e) const
    {
        double deepest = 0.0;
        for (int c : children_[std::size_t(e)])
            deepest = std::max(deepest, reach(c));
        return length(e) + deepest;
    }

    /// Edge `e`'s points from its start (mm).
    std::vector<Vector3d> points(int e) const
    {
        std::vector<Vector3d> p = g_.edges[std::size_t(e)].points;
        if (!forward(e))
            std::reverse(p.begin(), p.end());
        return p;
    }

    /// The direction of the vessel starting with edge `e`: from `skipMm` along it (outside the parent's lumen) to
    /// kDirectionLengthMm (or `lengthMm`) further, carrying on into the widest child where the edge is shorter.
    Vector3d direction(int e, double skipMm, double lengthMm = kDirectionLengthMm) const
    {
        std::vector<Vector3d> path;
        double total = 0.0;
        for (int current = e; current >= 0 && total < skipMm + lengthMm;)
        {
            for (const Vector3d& p : points(current))
            {
                if (!path.empty())
                    total += (p - path.back()).norm();
                path.push_back(p);
            }
            int widest = -1;
            for (int child : children_[std::size_t(current)])
                if (widest < 0 || radius(child) > radius(widest))
                    widest = child;
            current = widest;
        }
        if (path.size() < 2)
            return Vector3d::Zero();
        const double from = total >= skipMm + 3.0 ? skipMm : 0.0;
        Vector3d a = path.front(), b = path.back();
        double s = 0.0;
        bool haveA = from == 0.0;
        for (std::size_t i = 1; i < path.size(); ++i)
        {
            s += (path[i] - path[i - 1]).norm();
            if (!haveA && s >= from)
                a = path[i], haveA = true;
            if (s >= from + lengthMm)
            {
                b = path[i];
                break;
            }
        }
        const Vector3d d = b - a;
        return d.norm() > 0 ? Vector3d(d.normalized()) : Vector3d::Zero();
    }

    /// The direction in which edge `e` arrives at its end (its last 15 mm).
    Vector3d directionAtEnd(int e) const
    {
        const std::vector<Vector3d> p = points(e);
        double s = 0.0;
        std::size_t i = p.size() - 1;
        while (i > 0 && s < kDirectionLengthMm)
            s += (p[i] - p[i - 1]).norm(), --i;
        const Vector3d d = p.back() - p[i];
        return d.norm() > 0 ? Vector3d(d.normalized()) : Vector3d::Zero();
    }

    /// The children of `e` that are vessels, widest first: a short edge between two junctions is read as part of
    /// the junction (its children taken instead; the bridge added to `bridges`); a free end that stays within the
    /// parent's lumen (ends within its radius + 2 mm of where it starts or within 5 mm of the aortic lumen, or is under 4 mm
    /// long) is a spur.
    std::vector<int> kids(int e, std::vector<int>& bridges) const
    {
        std::vector<int> result;
        const double parentRadius = radiusAtEnd(e);
        std::function<void(int)> collect = [&](int parent) {
            for (int c : children_[std::size_t(parent)])
            {
                const bool free = children_[std::size_t(c)].empty();
                const std::vector<Vector3d> p = points(c);
                if (!free && length(c) < std::max(3.0, 0.75 * radius(e)))
                {
                    bridges.push_back(c);
                    collect(c);
                }
                else if (!(free && (length(c) < 4.0 || (p.back() - p.front()).norm() < parentRadius + 2.0 ||
                                    outsideAorta(p.back()) < 5.0)))
                    result.push_back(c);
            }
        };
        collect(e);
        std::sort(result.begin(), result.end(), [&](int a, int b) { return radius(a) > radius(b); });
        return result;
    }

    /// Follows the vessel from `e` through its side branches (the widest child goes on) until `endsHere` says
    /// that its children are a division, or it ends.
    Division follow(int e, const std::function<bool(int, const std::vector<int>&)>& endsHere) const
    {
        Division walk;
        for (std::size_t guard = 0; guard <= g_.edges.size(); ++guard)
        {
            walk.edges.push_back(e);
            walk.last = e;
            std::vector<int> k = kids(e, walk.edges);
            if (k.empty())
                return walk;
            if (k.size() >= 2 && endsHere(e, k))
            {
                walk.kids = k;
                return walk;
            }
            e = k.front();
        }
        return walk;
    }

    /// A division: the second widest child reaches 15 mm or more and is at least `ratio` x as wide as the widest,
    /// or (the radii of small segmented vessels, under 2 mm, are a voxel or two: too coarse to compare) reaches
    /// 0.3 x as far.
    static std::function<bool(int, const std::vector<int>&)> divisionAt(const TreeNamer& namer, double ratio)
    {
        return [&namer, ratio](int, const std::vector<int>& k) {
            if (namer.reach(k[1]) < 15.0)
                return false;
            return namer.radius(k[1]) >= ratio * namer.radius(k[0]) ||
                   (namer.radius(k[0]) < 2.0 && namer.reach(k[1]) >= 0.3 * namer.reach(k[0]));
        };
    }

    void name(const std::vector<int>& edges, const std::string& name)
    {
        for (int e : edges)
            names_[std::size_t(e)] = name;
    }

    void nameSubtree(int e, const std::string& name)
    {
        names_[std::size_t(e)] = name;
        for (int c : children_[std::size_t(e)])
            nameSubtree(c, name);
    }

    /// A vessel that ends at its first division (radius ratio >= `ratio`), whatever lies beyond unnamed.
    void nameVessel(int e, const std::string& name, double ratio)
    {
        this->name(follow(e, divisionAt(*this, ratio)).edges, name);
    }

    // --- the aorta and its branches -------------------------------------------------------------------------

    struct Branch
    {
        int edge, parent;
    };

    /// The aorta from the root edge: its edges (bridges included), its side branches with the aortic edge they
    /// leave, and the common iliacs (-1 when it does not end in the bifurcation).
    struct AorticPath
    {
        std::vector<int> edges;
        std::vector<Branch> branches;
        int leftIliac = -1, rightIliac = -1;
    };

    /// The path of tree edges from the root down to edge `e`, `e` included.
    std::vector<int> pathTo(int e) const
    {
        std::vector<int> path{e};
        while (parent_[std::size_t(path.back())] >= 0)
            path.push_back(parent_[std::size_t(path.back())]);
        std::reverse(path.begin(), path.end());
        return path;
    }

    /// The aorta from the root edge `e` along the widest path to the lowest wide end (median radius >= 3 mm, 40 mm
    /// below the root), ending where it divides into the common iliacs: the lowest junction on that path from which
    /// another wide end's path leaves, both continuing inferiorly at least 10 mm, to opposite sides.
    AorticPath followAorta(int e) const
    {
        AorticPath path;
        const double rootZ = points(e).front().z();
        int lowest = -1;
        std::vector<int> wideEnds;
        for (std::size_t c = 0; c < g_.edges.size(); ++c)
            if (start_[c] >= 0 && children_[c].empty() && radius(int(c)) >= 3.0 && points(int(c)).back().z() < rootZ - 40.0)
            {
                wideEnds.push_back(int(c));
                if (lowest < 0 || points(int(c)).back().z() < points(lowest).back().z())
                    lowest = int(c);
            }
        if (lowest < 0)
        {
            path.edges.push_back(e);
            return path;
        }
        const std::vector<int> main = pathTo(lowest);
        std::size_t split = main.size(); // index in `main` of the first edge past the bifurcation
        for (int other : wideEnds)
        {
            if (other == lowest)
                continue;
            const std::vector<int> second = pathTo(other);
            std::size_t common = 0;
            while (common < main.size() && common < second.size() && main[common] == second[common])
                ++common;
            if (common == 0 || common >= main.size() || common >= second.size() || common >= split)
                continue;
            const int a = main[common], b = second[common];
            const double skip = radiusAtEnd(main[common - 1]);
            const Vector3d da = direction(a, skip), db = direction(b, skip);
            if (reachAlong(main, common) >= 10.0 && reachAlong(second, common) >= 10.0 && radius(a) >= 3.0 &&
                radius(b) >= 3.0 && std::min(radius(a), radius(b)) >= 0.6 * std::max(radius(a), radius(b)) &&
                da.z() < -0.3 && db.z() < -0.3 && std::abs(da.x() - db.x()) >= 0.3)
            {
                split = common;
                path.leftIliac = da.x() > db.x() ? a : b;
                path.rightIliac = da.x() > db.x() ? b : a;
            }
        }
        path.edges.assign(main.begin(), main.begin() + long(split));
        for (int aortic : path.edges)
            for (int c : children_[std::size_t(aortic)])
                if (std::find(main.begin(), main.end(), c) == main.end() && c != path.leftIliac && c != path.rightIliac)
                    path.branches.push_back({c, aortic});
        return path;
    }

    /// Length of `path` from its edge `from` on (mm).
    double reachAlong(const std::vector<int>& path, std::size_t from) const
    {
        double total = 0.0;
        for (std::size_t i = from; i < path.size(); ++i)
            total += length(path[i]);
        return total;
    }

    /// An aorta runs craniocaudally: at least 40 mm, its ends apart mostly along z (a pulmonary trunk does not).
    bool looksAortic(const AorticPath& path) const
    {
        double along = 0.0;
        for (int e : path.edges)
            along += length(e);
        const Vector3d chord = points(path.edges.back()).back() - points(path.edges.front()).front();
        return along >= 40.0 && chord.norm() > 0 && std::abs(chord.z()) >= 0.7 * chord.norm();
    }

    /// Names the aorta and its branches; false (nothing named) when the wide root vessel does not look aortic.
    bool nameAorta(int e)
    {
        const AorticPath path = followAorta(e);
        if (!looksAortic(path))
            return false;
        name(path.edges, "aorta");
        if (path.leftIliac >= 0)
        {
            nameVessel(path.leftIliac, "left common iliac artery", 0.5);
            nameVessel(path.rightIliac, "right common iliac artery", 0.5);
        }
        for (int a : path.edges)
        {
            const auto& edge = g_.edges[std::size_t(a)];
            for (std::size_t i = 0; i < edge.points.size(); ++i)
                aortic_.push_back({edge.points[i], edge.radii[i]});
        }
        const auto outsideBy = [this](const Vector3d& p) { return outsideAorta(p); };
        struct Candidate
        {
            int edge;
            Vector3d d;
            double z, r;
        };
        std::vector<Candidate> left, right, anterior;
        for (const Branch& b : path.branches)
        {
            // Down the branch's deepest path: its radius and direction beyond the aortic lumen.
            std::vector<Vector3d> points;
            std::vector<double> radii;
            for (int c = b.edge; c >= 0;)
            {
                const auto& edge = g_.edges[std::size_t(c)];
                std::vector<double> r = edge.radii;
                std::vector<Vector3d> p = edge.points;
                if (!forward(c))
                    std::reverse(p.begin(), p.end()), std::reverse(r.begin(), r.end());
                points.insert(points.end(), p.begin(), p.end());
                radii.insert(radii.end(), r.begin(), r.end());
                int deepest = -1;
                for (int k : children_[std::size_t(c)])
                    if (deepest < 0 || reach(k) > reach(deepest))
                        deepest = k;
                c = deepest;
            }
            std::size_t exit = 0;
            while (exit < points.size() && outsideBy(points[exit]) < 2.0)
                ++exit;
            if (exit + 2 >= points.size() || outsideBy(points.back()) < 2.5)
                continue;
            std::size_t to = exit;
            for (double s = 0.0; to + 1 < points.size() && s < kDirectionLengthMm; ++to)
                s += (points[to + 1] - points[to]).norm();
            const double r = median(std::vector<double>(radii.begin() + long(exit), radii.end()), false);
            if ((points[to] - points[exit]).norm() <= 0)
                continue;
            const Vector3d d = (points[to] - points[exit]).normalized();
            const Candidate c{b.edge, d, g_.nodes[std::size_t(start_[std::size_t(b.edge)])].position.z(), r};
            if (std::abs(d.x()) >= 0.5 && std::abs(d.x()) >= 0.8 * std::abs(d.y()))
                (d.x() > 0 ? left : right).push_back(c);
            else if (-d.y() >= 0.5 && -d.y() >= std::abs(d.x()))
                anterior.push_back(c);
        }
        double lowestRenalZ = std::numeric_limits<double>::infinity();
        for (auto* side : {&left, &right})
        {
            std::sort(side->begin(), side->end(), [](const Candidate& a, const Candidate& b) { return a.r > b.r; });
            if (side->empty() || (side->size() > 1 && (*side)[0].r < 1.3 * (*side)[1].r))
                continue; // none, or two of about the same calibre: which is the main renal is not guessed
            nameVessel((*side)[0].edge, side == &left ? "left renal artery" : "right renal artery", 0.7);
            lowestRenalZ = std::min(lowestRenalZ, (*side)[0].z);
        }
        // The celiac and the SMA arise above the renal arteries (the SMA at most about a centimetre below the
        // highest); an anterior branch well below the lowest renal is the inferior mesenteric (not named here).
        std::sort(anterior.begin(), anterior.end(), [](const Candidate& a, const Candidate& b) { return a.z > b.z; });
        anterior.erase(std::remove_if(anterior.begin(), anterior.end(),
                                      [&](const Candidate& c) { return std::isfinite(lowestRenalZ) && c.z < lowestRenalZ - 10.0; }),
                       anterior.end());
        if (anterior.size() >= 2)
        {
            nameCeliac(anterior[0].edge, true);
            nameVessel(anterior[1].edge, "superior mesenteric artery", 0.7);
        }
        else if (anterior.size() == 1 && !nameCeliac(anterior[0].edge, false))
        {
            const Division walk = follow(anterior[0].edge, divisionAt(*this, 0.7));
            if (walk.kids.empty() && direction(anterior[0].edge, 20.0, 40.0).z() <= -0.5)
                name(walk.edges, "superior mesenteric artery");
        }
        return true;
    }

    // --- the celiac and hepatic tree ------------------------------------------------------------------------

    /// The celiac trunk from `e` when it divides into a right- and a left-going child (or `known`: the position
    /// says it is the celiac, the division names what it can). Returns whether it was named.
    bool nameCeliac(int e, bool known)
    {
        const Division walk = follow(e, divisionAt(*this, 0.5));
        const double skip = radiusAtEnd(walk.last);
        int hepatic = -1, splenic = -1;
        for (int k : walk.kids)
        {
            const Vector3d d = direction(k, skip);
            if (d.x() <= -0.3 && hepatic < 0)
                hepatic = k;
            else if (d.x() >= 0.3 && splenic < 0)
                splenic = k;
        }
        if (!known && (hepatic < 0 || splenic < 0))
            return false;
        name(walk.edges, "celiac trunk");
        if (splenic >= 0)
            nameVessel(splenic, "splenic artery", 0.7);
        if (hepatic >= 0)
            nameCommonHepatic(hepatic, true);
        return true;
    }

    /// At a junction of the common hepatic: the gastroduodenal (running inferiorly, reaching 10 mm or more
    /// child) and the proper hepatic (the widest child running above it), or {-1, -1}.
    std::pair<int, int> gastroduodenalAndProper(int e, const std::vector<int>& k) const
    {
        const double skip = radiusAtEnd(e);
        int gda = -1;
        double gdaZ = -0.4;
        for (int c : k)
        {
            const double z = direction(c, skip).z();
            if (reach(c) >= 10.0 && z <= gdaZ)
                gda = c, gdaZ = z;
        }
        if (gda < 0)
            return {-1, -1};
        for (int c : k) // widest first
            if (c != gda && direction(c, skip).z() >= gdaZ + 0.4)
                return {gda, c};
        return {-1, -1};
    }

    /// The common hepatic from `e` to the gastroduodenal's origin, the proper hepatic beyond. Unless `known` (it
    /// came from the celiac's division), nothing is named when the gastroduodenal pattern is not found.
    bool nameCommonHepatic(int e, bool known)
    {
        const Division walk = follow(e, [this](int at, const std::vector<int>& k) {
            return gastroduodenalAndProper(at, k).first >= 0 || divisionAt(*this, 0.7)(at, k);
        });
        const auto [gda, proper] = walk.kids.empty() ? std::pair{-1, -1} : gastroduodenalAndProper(walk.last, walk.kids);
        if (!known && gda < 0)
            return false;
        name(walk.edges, "common hepatic artery");
        if (gda >= 0)
        {
            nameVessel(gda, "gastroduodenal artery", 0.7);
            nameProperHepatic(proper, true);
        }
        return true;
    }

    /// The proper hepatic to its division into the right hepatic (the right-going child) and the left hepatic.
    bool nameProperHepatic(int e, bool known)
    {
        const Division walk = follow(e, divisionAt(*this, 0.5));
        if (walk.kids.empty())
        {
            if (known)
                name(walk.edges, "proper hepatic artery");
            return known;
        }
        const double skip = radiusAtEnd(walk.last);
        int first = walk.kids[0], second = walk.kids[1];
        Vector3d d1 = direction(first, skip), d2 = direction(second, skip);
        if (d1.x() > d2.x())
            std::swap(first, second), std::swap(d1, d2);
        const bool rightAndLeft = d2.x() - d1.x() >= 0.3;
        if (!known && !rightAndLeft)
            return false;
        name(walk.edges, "proper hepatic artery");
        if (rightAndLeft)
        {
            nameHepaticBranch(first, "right hepatic artery");
            nameHepaticBranch(second, "left hepatic artery");
        }
        return true;
    }

    /// The right or left hepatic to its first division; everything beyond is segmental.
    void nameHepaticBranch(int e, const std::string& name)
    {
        const Division walk = follow(e, [](int, const std::vector<int>&) { return true; });
        this->name(walk.edges, name);
        for (int k : walk.kids)
            nameSubtree(k, "segmental hepatic artery");
    }

    /// A tree whose root is narrower than an aorta: a celiac, a common or a proper hepatic, by their divisions.
    void nameTreeWithoutAorta(int e)
    {
        if (!nameCeliac(e, false) && !nameCommonHepatic(e, false))
            nameProperHepatic(e, false);
    }

    const SkeletonGraph& g_;
    std::vector<std::string> names_;
    std::vector<int> start_;
    std::vector<int> parent_;
    std::vector<std::vector<int>> children_;
    std::vector<double> radius_;
    std::vector<std::pair<Vector3d, double>> aortic_; ///< the aorta's centerline points and lumen radii (mm)
    int rootEdge_ = -1;
};

} // namespace

std::vector<std::string> nameVesselSegments(const SkeletonGraph& centerlines, NamingScope scope)
{
    if (scope == NamingScope::None)
        return std::vector<std::string>(centerlines.edges.size(), kUnnamedSegment);
    return TreeNamer(centerlines).run();
}

} // namespace vsim::imaging
