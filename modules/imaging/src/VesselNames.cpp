// Anatomical names of centerline segments: the tree rooted at its upstream end, vessels followed through their
// side branches, and each division matched against the usual aortic and hepatic patterns (VesselNames.h).

#include "vsim/imaging/VesselNames.h"

#include "vsim/core/StoredText.h"

#include "VesselTree.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace vsim::imaging {
namespace {

using detail::Division;
using detail::kAortaMinRadiusMm;
using detail::kDirectionLengthMm;
using Eigen::Vector3d;

class TreeNamer : private detail::VesselTree
{
public:
    explicit TreeNamer(const SkeletonGraph& graph) : VesselTree(graph), names_(graph.edges.size(), kUnnamedSegment) {}

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
        name(path.edges, storedText("aorta"));
        if (path.leftIliac >= 0)
        {
            nameVessel(path.leftIliac, storedText("left common iliac artery"), 0.5);
            nameVessel(path.rightIliac, storedText("right common iliac artery"), 0.5);
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
            nameVessel((*side)[0].edge, side == &left ? storedText("left renal artery") : storedText("right renal artery"),
                       0.7);
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
            nameVessel(anterior[1].edge, storedText("superior mesenteric artery"), 0.7);
        }
        else if (anterior.size() == 1 && !nameCeliac(anterior[0].edge, false))
        {
            const Division walk = follow(anterior[0].edge, divisionAt(*this, 0.7));
            if (walk.kids.empty() && direction(anterior[0].edge, 20.0, 40.0).z() <= -0.5)
                name(walk.edges, storedText("superior mesenteric artery"));
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
        name(walk.edges, storedText("celiac trunk"));
        if (splenic >= 0)
            nameVessel(splenic, storedText("splenic artery"), 0.7);
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
        name(walk.edges, storedText("common hepatic artery"));
        if (gda >= 0)
        {
            nameVessel(gda, storedText("gastroduodenal artery"), 0.7);
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
                name(walk.edges, storedText("proper hepatic artery"));
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
        name(walk.edges, storedText("proper hepatic artery"));
        if (rightAndLeft)
        {
            nameHepaticBranch(first, storedText("right hepatic artery"));
            nameHepaticBranch(second, storedText("left hepatic artery"));
        }
        return true;
    }

    /// The right or left hepatic to its first division; everything beyond is segmental.
    void nameHepaticBranch(int e, const std::string& name)
    {
        const Division walk = follow(e, [](int, const std::vector<int>&) { return true; });
        this->name(walk.edges, name);
        for (int k : walk.kids)
            nameSubtree(k, storedText("segmental hepatic artery"));
    }

    /// A tree whose root is narrower than an aorta: a celiac, a common or a proper hepatic, by their divisions.
    void nameTreeWithoutAorta(int e)
    {
        if (!nameCeliac(e, false) && !nameCommonHepatic(e, false))
            nameProperHepatic(e, false);
    }

    std::vector<std::string> names_;
};

} // namespace

std::vector<std::string> nameVesselSegments(const SkeletonGraph& centerlines, NamingScope scope)
{
    if (scope == NamingScope::None)
        return std::vector<std::string>(centerlines.edges.size(), kUnnamedSegment);
    return TreeNamer(centerlines).run();
}

} // namespace vsim::imaging
