#include "vsim/mesh/SurfaceRemeshing.h"

#include "vsim/core/Error.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace vsim::mesh {
namespace {

using Edge = std::pair<int, int>;
Edge key(int a, int b) { return std::minmax(a, b); }

double angleAt(const Eigen::Vector3d& at, const Eigen::Vector3d& b, const Eigen::Vector3d& c)
{
    const Eigen::Vector3d u = (b - at).normalized(), v = (c - at).normalized();
    return std::acos(std::clamp(u.dot(v), -1.0, 1.0));
}

Eigen::Vector3d normalOf(const TriangleMesh& m, const std::array<int, 3>& t)
{
    return (m.points[std::size_t(t[1])] - m.points[std::size_t(t[0])])
        .cross(m.points[std::size_t(t[2])] - m.points[std::size_t(t[0])]);
}

/// One pass of red-green refinement: every edge longer than 4/3 of the sizing gets its midpoint; each triangle is cut by
/// the pattern of its marked edges (in its own vertex order, so orientation is kept). Returns whether any split.
bool splitLongEdges(TriangleMesh& m, const EdgeSizing& sizing)
{
    std::map<Edge, int> midpoint;
    for (const auto& t : m.triangles)
        for (int k = 0; k < 3; ++k)
        {
            const int a = t[std::size_t(k)], b = t[std::size_t((k + 1) % 3)];
            const Eigen::Vector3d middle = 0.5 * (m.points[std::size_t(a)] + m.points[std::size_t(b)]);
            if ((m.points[std::size_t(a)] - m.points[std::size_t(b)]).norm() > 4.0 / 3.0 * sizing(middle) &&
                !midpoint.count(key(a, b)))
            {
                midpoint[key(a, b)] = int(m.points.size());
                m.points.push_back(0.5 * (m.points[std::size_t(a)] + m.points[std::size_t(b)]));
            }
        }
    if (midpoint.empty())
        return false;
    std::vector<std::array<int, 3>> next;
    next.reserve(m.triangles.size() * 2);
    for (const auto& t : m.triangles)
    {
        // mid[k]: midpoint of edge (t[k], t[k+1]) or -1.
        std::array<int, 3> mid;
        int marked = 0;
        for (int k = 0; k < 3; ++k)
        {
            const auto found = midpoint.find(key(t[std::size_t(k)], t[std::size_t((k + 1) % 3)]));
            mid[std::size_t(k)] = found == midpoint.end() ? -1 : found->second;
            marked += mid[std::size_t(k)] >= 0;
        }
        if (marked == 0)
        {
            next.push_back(t);
            continue;
        }
        if (marked == 3)
        {
            next.push_back({t[0], mid[0], mid[2]});
            next.push_back({mid[0], t[1], mid[1]});
            next.push_back({mid[2], mid[1], t[2]});
            next.push_back({mid[0], mid[1], mid[2]});
            continue;
        }
        // Rotate so that edge 0 (v0 -> v1) is marked and, with two marks, edge 1 (v1 -> v2) is the other one.
        int r = 0;
        for (; r < 3; ++r)
        {
            const bool first = mid[std::size_t(r)] >= 0, second = mid[std::size_t((r + 1) % 3)] >= 0;
            if (first && (marked == 1 || second))
                break;
        }
        const int v0 = t[std::size_t(r)], v1 = t[std::size_t((r + 1) % 3)], v2 = t[std::size_t((r + 2) % 3)];
        const int m01 = mid[std::size_t(r)], m12 = mid[std::size_t((r + 1) % 3)];
        if (marked == 1)
        {
            next.push_back({v0, m01, v2});
            next.push_back({m01, v1, v2});
        }
        else
        {
            next.push_back({m01, v1, m12});
            // The quad v0, m01, m12, v2: cut along its shorter diagonal.
            if ((m.points[std::size_t(v0)] - m.points[std::size_t(m12)]).norm() <
                (m.points[std::size_t(m01)] - m.points[std::size_t(v2)]).norm())
            {
                next.push_back({v0, m01, m12});
                next.push_back({v0, m12, v2});
            }
            else
            {
                next.push_back({v0, m01, v2});
                next.push_back({m01, m12, v2});
            }
        }
    }
    m.triangles = std::move(next);
    return true;
}

/// Delaunay flips where the two triangles of an edge are nearly coplanar (normals within 35 degrees) and the new
/// edge does not exist yet; each triangle changes at most once per pass. Returns the number of flips.
std::size_t flipEdges(TriangleMesh& m)
{
    std::map<Edge, std::vector<int>> trianglesOf;
    for (std::size_t i = 0; i < m.triangles.size(); ++i)
        for (int k = 0; k < 3; ++k)
            trianglesOf[key(m.triangles[i][std::size_t(k)], m.triangles[i][std::size_t((k + 1) % 3)])].push_back(int(i));
    std::vector<char> changed(m.triangles.size(), 0);
    std::size_t flips = 0;
    const double coplanar = std::cos(35.0 * M_PI / 180.0);
    for (const auto& [edge, owners] : trianglesOf)
    {
        if (owners.size() != 2 || changed[std::size_t(owners[0])] || changed[std::size_t(owners[1])])
            continue;
        // Orient: t1 holds a -> b, t2 holds b -> a; c and d are the opposite corners.
        std::array<int, 3>& t1 = m.triangles[std::size_t(owners[0])];
        std::array<int, 3>& t2 = m.triangles[std::size_t(owners[1])];
        int a = -1, b = -1, c = -1, d = -1;
        for (int k = 0; k < 3; ++k)
            if (key(t1[std::size_t(k)], t1[std::size_t((k + 1) % 3)]) == edge)
                a = t1[std::size_t(k)], b = t1[std::size_t((k + 1) % 3)], c = t1[std::size_t((k + 2) % 3)];
        for (int k = 0; k < 3; ++k)
            if (t2[std::size_t(k)] != a && t2[std::size_t(k)] != b)
                d = t2[std::size_t(k)];
        if (c == d || trianglesOf.count(key(c, d)))
            continue;
        const auto& p = m.points;
        const double opposite = angleAt(p[std::size_t(c)], p[std::size_t(a)], p[std::size_t(b)]) +
                                angleAt(p[std::size_t(d)], p[std::size_t(a)], p[std::size_t(b)]);
        if (opposite <= M_PI + 1e-9)
            continue;
        const Eigen::Vector3d n1 = normalOf(m, t1).normalized(), n2 = normalOf(m, t2).normalized();
        if (n1.dot(n2) < coplanar)
            continue;
        const std::array<int, 3> u{a, d, c}, v{d, b, c};
        const Eigen::Vector3d nu = normalOf(m, u), nv = normalOf(m, v), average = n1 + n2;
        if (nu.dot(average) <= 0.0 || nv.dot(average) <= 0.0)
            continue; // the quad is not convex in its plane
        t1 = u;
        t2 = v;
        changed[std::size_t(owners[0])] = changed[std::size_t(owners[1])] = 1;
        ++flips;
    }
    return flips;
}

/// Collapses edges shorter than 4/5 of the sizing into their midpoint where that keeps the surface a manifold (the
/// two ends share exactly the two opposite corners), flips no triangle and makes no edge longer than 4/3 of it;
/// each vertex moves at most once per pass. Unused vertices are dropped. Returns the number of collapses.
std::size_t collapseShortEdges(TriangleMesh& m, const EdgeSizing& sizing)
{
    std::vector<std::vector<int>> around(m.points.size()); // triangles of each vertex
    for (std::size_t i = 0; i < m.triangles.size(); ++i)
        for (int v : m.triangles[i])
            around[std::size_t(v)].push_back(int(i));
    std::vector<char> touched(m.points.size(), 0), dead(m.triangles.size(), 0);
    std::vector<int> target(m.points.size());
    for (std::size_t v = 0; v < target.size(); ++v)
        target[v] = int(v);
    std::size_t collapses = 0;
    auto neighbours = [&](int v) {
        std::vector<int> out;
        for (int t : around[std::size_t(v)])
            if (!dead[std::size_t(t)])
                for (int w : m.triangles[std::size_t(t)])
                    if (w != v)
                        out.push_back(w);
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
        return out;
    };
    for (std::size_t i = 0; i < m.triangles.size(); ++i)
        for (int k = 0; k < 3 && !dead[i]; ++k)
        {
            const int a = m.triangles[i][std::size_t(k)], b = m.triangles[i][std::size_t((k + 1) % 3)];
            if (touched[std::size_t(a)] || touched[std::size_t(b)])
                continue;
            const double size = sizing(0.5 * (m.points[std::size_t(a)] + m.points[std::size_t(b)]));
            const double longest = 4.0 / 3.0 * size;
            if ((m.points[std::size_t(a)] - m.points[std::size_t(b)]).norm() >= 0.8 * size)
                continue;
            const std::vector<int> na = neighbours(a), nb = neighbours(b);
            std::vector<int> common;
            std::set_intersection(na.begin(), na.end(), nb.begin(), nb.end(), std::back_inserter(common));
            if (common.size() != 2)
                continue; // the link condition: collapsing would pinch the surface
            const Eigen::Vector3d middle = 0.5 * (m.points[std::size_t(a)] + m.points[std::size_t(b)]);
            bool ok = true;
            for (int w : na)
                ok = ok && (w == b || (m.points[std::size_t(w)] - middle).norm() <= longest);
            for (int w : nb)
                ok = ok && (w == a || (m.points[std::size_t(w)] - middle).norm() <= longest);
            // No surviving triangle may turn over.
            for (int v : {a, b})
                for (int t : around[std::size_t(v)])
                {
                    if (dead[std::size_t(t)] || !ok)
                        continue;
                    std::array<int, 3> tri = m.triangles[std::size_t(t)];
                    if (std::count(tri.begin(), tri.end(), a) + std::count(tri.begin(), tri.end(), b) == 2)
                        continue; // removed by the collapse
                    const Eigen::Vector3d before = normalOf(m, tri);
                    std::array<Eigen::Vector3d, 3> q;
                    for (int j = 0; j < 3; ++j)
                        q[std::size_t(j)] = tri[std::size_t(j)] == v ? middle : m.points[std::size_t(tri[std::size_t(j)])];
                    const Eigen::Vector3d after = (q[1] - q[0]).cross(q[2] - q[0]);
                    ok = ok && after.dot(before) > 0.2 * before.norm() * after.norm();
                }
            if (!ok)
                continue;
            m.points[std::size_t(a)] = middle;
            for (int t : around[std::size_t(b)])
            {
                if (dead[std::size_t(t)])
                    continue;
                auto& tri = m.triangles[std::size_t(t)];
                if (std::count(tri.begin(), tri.end(), a))
                    dead[std::size_t(t)] = 1;
                else
                {
                    std::replace(tri.begin(), tri.end(), b, a);
                    around[std::size_t(a)].push_back(t);
                }
            }
            target[std::size_t(b)] = a;
            touched[std::size_t(a)] = touched[std::size_t(b)] = 1;
            for (int w : na)
                touched[std::size_t(w)] = 1;
            for (int w : nb)
                touched[std::size_t(w)] = 1;
            ++collapses;
        }
    // Compact.
    std::vector<std::array<int, 3>> kept;
    for (std::size_t i = 0; i < m.triangles.size(); ++i)
        if (!dead[i])
            kept.push_back(m.triangles[i]);
    std::vector<int> index(m.points.size(), -1);
    std::vector<Eigen::Vector3d> points;
    for (auto& tri : kept)
        for (int& v : tri)
        {
            if (index[std::size_t(v)] < 0)
            {
                index[std::size_t(v)] = int(points.size());
                points.push_back(m.points[std::size_t(v)]);
            }
            v = index[std::size_t(v)];
        }
    m.points = std::move(points);
    m.triangles = std::move(kept);
    return collapses;
}

/// Moves every vertex half-way to the centroid of its neighbours within its tangent plane.
void relaxTangentially(TriangleMesh& m)
{
    std::vector<Eigen::Vector3d> normal(m.points.size(), Eigen::Vector3d::Zero()), sum(m.points.size(), Eigen::Vector3d::Zero());
    std::vector<int> count(m.points.size(), 0);
    for (const auto& t : m.triangles)
    {
        const Eigen::Vector3d n = normalOf(m, t);
        for (int k = 0; k < 3; ++k)
        {
            normal[std::size_t(t[std::size_t(k)])] += n;
            sum[std::size_t(t[std::size_t(k)])] += m.points[std::size_t(t[std::size_t((k + 1) % 3)])];
            ++count[std::size_t(t[std::size_t(k)])];
        }
    }
    std::vector<Eigen::Vector3d> moved = m.points;
    for (std::size_t v = 0; v < m.points.size(); ++v)
    {
        if (count[v] == 0 || normal[v].norm() == 0.0)
            continue;
        const Eigen::Vector3d n = normal[v].normalized();
        Eigen::Vector3d step = 0.5 * (sum[v] / count[v] - m.points[v]);
        step -= step.dot(n) * n;
        moved[v] += step;
    }
    m.points = std::move(moved);
}

} // namespace

double edgeForVertexBudget(double areaMm2, double vertices)
{
    if (!(areaMm2 > 0.0) || !(vertices > 0.0))
        throw Error("a vertex budget needs a positive area and vertex count");
    return std::sqrt(2.0 * areaMm2 / (std::sqrt(3.0) * vertices));
}

double minTriangleAngle(const TriangleMesh& surface)
{
    double smallest = 180.0;
    for (const auto& t : surface.triangles)
        for (int k = 0; k < 3; ++k)
            smallest = std::min(smallest, angleAt(surface.points[std::size_t(t[std::size_t(k)])],
                                                  surface.points[std::size_t(t[std::size_t((k + 1) % 3)])],
                                                  surface.points[std::size_t(t[std::size_t((k + 2) % 3)])]) *
                                              180.0 / M_PI);
    return smallest;
}

EdgeSizing vesselSizing(const SkeletonGraph& centerlines, double fraction, double largestMm)
{
    std::vector<std::pair<Eigen::Vector3d, double>> samples;
    for (const auto& edge : centerlines.edges)
        for (std::size_t i = 0; i < edge.points.size(); ++i)
            samples.push_back({edge.points[i], edge.radii[i]});
    if (samples.empty())
        throw Error("vessel sizing needs centerlines with points");
    return [samples = std::move(samples), fraction, largestMm](const Eigen::Vector3d& p) {
        double nearest = 1e300, radius = 0.0;
        for (const auto& [point, r] : samples)
            if (const double d = (point - p).squaredNorm(); d < nearest)
                nearest = d, radius = r;
        return std::min(largestMm, fraction * radius);
    };
}

TriangleMesh remeshIsotropic(const TriangleMesh& surface, const EdgeSizing& sizing, int rounds)
{
    if (surface.triangles.empty())
        throw Error("the surface to remesh is empty");
    const EdgeSizing clamped = [&](const Eigen::Vector3d& p) { return std::clamp(sizing(p), 0.1, 50.0); };
    TriangleMesh m;
    m.points = surface.points;
    m.triangles = surface.triangles;
    for (int round = 0; round < rounds; ++round)
    {
        for (int pass = 0; pass < 20 && splitLongEdges(m, clamped); ++pass)
            flipEdges(m);
        for (int pass = 0; pass < 10 && collapseShortEdges(m, clamped) > 0; ++pass)
        {
        }
        for (int pass = 0; pass < 10 && flipEdges(m) > 0; ++pass)
        {
        }
        relaxTangentially(m);
    }
    for (int pass = 0; pass < 10 && flipEdges(m) > 0; ++pass)
    {
    }
    return m;
}

} // namespace vsim::mesh
