#include "vsim/mesh/WallMesh.h"

#include "WallFlips.h"
#include "WallSmoothing.h"

#include "vsim/core/Error.h"
#include "vsim/core/StoredText.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <set>

namespace vsim::mesh {
namespace {

/// Elements whose smallest dihedral angle is under this get their free nodes moved (WallSmoothing.h).
constexpr double kSmoothingTargetDeg = 12.0; // 2 degrees above the floor: the worst element's ring is raised too
constexpr double kFloorDeg = 10.0;           // the smallest dihedral angle the clinical analysis asks (issue 16)
constexpr double kFloorMarginDeg = 1.0;      // the lumen nodes slide for elements under the floor plus this
/// A lumen node slides along the surface by at most this fraction of its mean edge: off the surface by under
/// (0.1 a)^2 / (2 R), 0.005 mm for 3.7 mm edges on a 14 mm radius.
constexpr double kLumenSlideFraction = 0.1;
// The tallest the inner (thrombus) prisms may stand against their shortest lumen edge before the layer is split into
// sub-layers: an ideal prism split into three tets keeps its smallest dihedral angle over 11 degrees from 0.4 to
// 4.6 times as tall as wide, and falls to 8.1 at 7 and 4.1 at 14 (the thrombus test cylinder, RESULTS.md
// 2026-11-30): 5 stays on the good side of the 10 degrees the clinical analysis asks.
constexpr double kMaxInnerPrismAspect = 5.0;
constexpr int kMaxThrombusSubLayers = 8;

/// Removes the triangles of each end's cap (a vertex beyond the cut plane, one radius inside the end, within three
/// radii or four mean edges of it). Returns the surface and, per vertex, the end whose new boundary it lies on (-1: none).
std::pair<TriangleMesh, std::vector<int>> openEnds(const TriangleMesh& lumen, const std::vector<VesselEnd>& ends,
                                                   std::vector<std::string>& warnings)
{
    // The cut sphere: three radii, and at least four mean edge lengths (a thin vessel's tip radius is small).
    double edgeSum = 0.0;
    for (const auto& t : lumen.triangles)
        edgeSum += (lumen.points[std::size_t(t[1])] - lumen.points[std::size_t(t[0])]).norm();
    const double meanEdge = edgeSum / double(lumen.triangles.size());
    std::vector<Eigen::Vector3d> planePoint(ends.size());
    std::vector<double> reach(ends.size());
    for (std::size_t e = 0; e < ends.size(); ++e)
    {
        planePoint[e] = ends[e].point - ends[e].radiusMm * ends[e].outward;
        reach[e] = std::max(3.0 * ends[e].radiusMm, 4.0 * meanEdge);
    }
    auto beyond = [&](const Eigen::Vector3d& v, std::size_t e) {
        return (v - planePoint[e]).dot(ends[e].outward) > 0.0 && (v - planePoint[e]).norm() < reach[e];
    };
    std::vector<std::array<int, 3>> kept;
    std::vector<std::size_t> cutPerEnd(ends.size(), 0);
    for (const auto& triangle : lumen.triangles)
    {
        bool drop = false;
        for (std::size_t e = 0; e < ends.size() && !drop; ++e)
            for (int v : triangle)
                if (beyond(lumen.points[std::size_t(v)], e))
                {
                    drop = true;
                    ++cutPerEnd[e];
                    break;
                }
        if (!drop)
            kept.push_back(triangle);
    }
    for (std::size_t e = 0; e < ends.size(); ++e)
        if (cutPerEnd[e] == 0)
            throw Error(Pattern{"the vessel end %1 cuts no triangle of the lumen surface: is the surface from the "
                                "same label as the centerlines?",
                                {std::to_string(e + 1)}});
    // Keep the largest connected piece: a cut can leave a loose ring of a vessel's cap, which nothing would hold.
    {
        std::vector<int> parent(lumen.points.size());
        for (std::size_t v = 0; v < parent.size(); ++v)
            parent[v] = int(v);
        std::function<int(int)> root = [&](int v) { return parent[std::size_t(v)] == v ? v : parent[std::size_t(v)] = root(parent[std::size_t(v)]); };
        for (const auto& t : kept)
            for (int k = 1; k < 3; ++k)
                parent[std::size_t(root(t[std::size_t(k)]))] = root(t[0]);
        std::map<int, std::size_t> size;
        for (const auto& t : kept)
            ++size[root(t[0])];
        const int largest = std::max_element(size.begin(), size.end(), [](const auto& a, const auto& b) {
                                return a.second < b.second;
                            })->first;
        const std::size_t before = kept.size();
        kept.erase(std::remove_if(kept.begin(), kept.end(), [&](const auto& t) { return root(t[0]) != largest; }),
                   kept.end());
        if (kept.size() < before)
            warnings.push_back(storedText(Pattern{
                "%1 triangles in loose pieces left by the end cuts (or apart from the vessel tree) were dropped",
                {std::to_string(before - kept.size())}}));
    }
    // Compact the vertices.
    std::vector<int> newIndex(lumen.points.size(), -1);
    TriangleMesh open;
    for (auto& triangle : kept)
        for (int& v : triangle)
        {
            if (newIndex[std::size_t(v)] < 0)
            {
                newIndex[std::size_t(v)] = int(open.points.size());
                open.points.push_back(lumen.points[std::size_t(v)]);
            }
            v = newIndex[std::size_t(v)];
        }
    open.triangles = kept;
    // Boundary edges (in one triangle only) belong to the nearest end's cut when they lie in its cut sphere; any
    // other boundary was open before (a lumen cut by the image border) and stays free.
    std::map<std::pair<int, int>, int> edgeCount;
    for (const auto& t : open.triangles)
        for (int k = 0; k < 3; ++k)
            ++edgeCount[std::minmax(t[std::size_t(k)], t[std::size_t((k + 1) % 3)])];
    std::vector<int> endOf(open.points.size(), -1);
    std::size_t stray = 0;
    for (const auto& [edge, count] : edgeCount)
        if (count == 1)
            for (int v : {edge.first, edge.second})
            {
                std::size_t nearest = 0;
                for (std::size_t e = 1; e < ends.size(); ++e)
                    if ((open.points[std::size_t(v)] - planePoint[e]).norm() <
                        (open.points[std::size_t(v)] - planePoint[nearest]).norm())
                        nearest = e;
                if ((open.points[std::size_t(v)] - planePoint[nearest]).norm() < reach[nearest])
                    endOf[std::size_t(v)] = int(nearest);
                else
                    ++stray;
            }
    if (stray > 0)
        warnings.push_back(storedText(Pattern{"the lumen surface is open away from the vessel ends (%1 boundary edges; "
                                              "is the segmentation cut by the image border?): those nodes stay free",
                                              {std::to_string(stray / 2)}}));
    // (Flattening the loop onto the plane was tried: it turns the triangles next to the cut into slivers.)
    return {open, endOf};
}

double signedVolume(const std::vector<Eigen::Vector3d>& p, const std::array<int, 4>& t)
{
    return (p[std::size_t(t[1])] - p[std::size_t(t[0])])
               .cross(p[std::size_t(t[2])] - p[std::size_t(t[0])])
               .dot(p[std::size_t(t[3])] - p[std::size_t(t[0])]) /
           6.0;
}

} // namespace

std::vector<VesselEnd> vesselEnds(const SkeletonGraph& centerlines)
{
    std::vector<VesselEnd> ends;
    for (int node : centerlines.endpoints())
        for (const SkeletonGraph::Edge& edge : centerlines.edges)
        {
            if (edge.from != node && edge.to != node)
                continue;
            // Walk inward from the end about 3 mm (or the whole edge) to get a stable direction.
            std::vector<Eigen::Vector3d> points = edge.points;
            std::vector<double> radii = edge.radii;
            if (edge.to == node)
            {
                std::reverse(points.begin(), points.end());
                std::reverse(radii.begin(), radii.end());
            }
            std::size_t inner = 1;
            while (inner + 1 < points.size() && (points[inner] - points.front()).norm() < 3.0)
                ++inner;
            VesselEnd end;
            end.point = points.front();
            end.outward = (points.front() - points[inner]).normalized();
            end.radiusMm = *std::max_element(radii.begin(), radii.begin() + long(inner + 1));
            ends.push_back(end);
            break;
        }
    return ends;
}

double minDihedralAngle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                        const Eigen::Vector3d& d)
{
    const std::array<Eigen::Vector3d, 4> p{a, b, c, d};
    // Face normals (outward for a positive tet): face k is opposite corner k.
    std::array<Eigen::Vector3d, 4> normal;
    for (int k = 0; k < 4; ++k)
        normal[std::size_t(k)] = (p[std::size_t(kTetFaces[k][1])] - p[std::size_t(kTetFaces[k][0])])
                                     .cross(p[std::size_t(kTetFaces[k][2])] - p[std::size_t(kTetFaces[k][0])])
                                     .normalized();
    double smallest = 180.0;
    for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j)
        {
            // The dihedral angle at the edge shared by faces i and j is pi minus the angle between their normals.
            const double cosine = std::clamp(-normal[std::size_t(i)].dot(normal[std::size_t(j)]), -1.0, 1.0);
            smallest = std::min(smallest, std::acos(cosine) * 180.0 / M_PI);
        }
    return smallest;
}

namespace {

/// buildWallMesh with `subLayers` (>= 1) prism layers through the inner layer (with the outer wall).
WallMesh buildLayeredWall(const TriangleMesh& lumen, const std::vector<VesselEnd>& ends, double thicknessMm,
                          const OuterWallDistance& outerWall, int subLayers)
{
    if (lumen.triangles.empty())
        throw Error("the lumen surface is empty: extract the surface first");
    if (!(thicknessMm >= 0.1 && thicknessMm <= 10.0))
        throw Error(Pattern{"the wall thickness must lie in 0.1..10 mm (%1 given)", {std::to_string(thicknessMm)}});
    WallMesh wall;
    const auto [surface, endOf] = openEnds(lumen, ends, wall.warnings);
    const int n = int(surface.points.size());
    // Area-weighted vertex normals (triangles are counter-clockwise seen from outside the lumen), then smoothed
    // (three 1-ring averages): on a noisy segmented surface neighbouring normals scatter, which twists the prisms
    // and leaves a flat tet among their three.
    std::vector<Eigen::Vector3d> normal = surface.vertexNormals();
    for (int pass = 0; pass < 3; ++pass)
    {
        std::vector<Eigen::Vector3d> averaged = normal;
        for (const auto& t : surface.triangles)
            for (int k = 0; k < 3; ++k)
                averaged[std::size_t(t[std::size_t(k)])] += normal[std::size_t(t[std::size_t((k + 1) % 3)])] +
                                                             normal[std::size_t(t[std::size_t((k + 2) % 3)])];
        for (std::size_t v = 0; v < normal.size(); ++v)
            if (averaged[v].norm() > 0.0)
                normal[v] = averaged[v].normalized();
    }
    // Each lumen vertex's mean and shortest edge (mm).
    std::vector<double> edgeSum(std::size_t(n), 0.0), edgeCount(std::size_t(n), 0.0), shortestEdge(std::size_t(n), INFINITY);
    for (const auto& t : surface.triangles)
        for (int k = 0; k < 3; ++k)
        {
            const double length = (surface.points[std::size_t(t[std::size_t(k)])] - surface.points[std::size_t(t[std::size_t((k + 1) % 3)])]).norm();
            for (int end : {t[std::size_t(k)], t[std::size_t((k + 1) % 3)]})
            {
                edgeSum[std::size_t(end)] += length, edgeCount[std::size_t(end)] += 1.0;
                shortestEdge[std::size_t(end)] = std::min(shortestEdge[std::size_t(end)], length);
            }
        }
    // The layers' offsets along the normals: one layer of the wall thickness, or with the sac's outer wall the
    // thrombus-wall interface and the outer surface (the outer distances smoothed over two 1-rings: the label's
    // voxel steps would otherwise ripple the outer surface).
    std::vector<std::array<double, 2>> offset(surface.points.size(), {thicknessMm, thicknessMm});
    std::vector<double> thrombus(surface.points.size(), 0.0);
    if (outerWall)
    {
        std::vector<double> outer(surface.points.size());
        for (int v = 0; v < n; ++v)
            outer[std::size_t(v)] = std::max(thicknessMm, outerWall(surface.points[std::size_t(v)], normal[std::size_t(v)]));
        for (int pass = 0; pass < 2; ++pass)
        {
            std::vector<double> sum(outer.size(), 0.0);
            std::vector<int> count(outer.size(), 0);
            for (const auto& t : surface.triangles)
                for (int k = 0; k < 3; ++k)
                    for (int other = 0; other < 3; ++other)
                        sum[std::size_t(t[std::size_t(k)])] += outer[std::size_t(t[std::size_t(other)])], ++count[std::size_t(t[std::size_t(k)])];
            for (std::size_t v = 0; v < outer.size(); ++v)
                if (count[v] > 0)
                    outer[v] = sum[v] / count[v];
        }
        double tallest = 0.0; // the inner prisms' largest height over their shortest lumen edge
        for (std::size_t v = 0; v < outer.size(); ++v)
        {
            thrombus[v] = outer[v] - thicknessMm;
            offset[v] = {std::max(thrombus[v], 0.5 * thicknessMm), outer[v]};
            wall.maxThrombusMm = std::max(wall.maxThrombusMm, thrombus[v]);
            if (shortestEdge[v] > 0.0 && std::isfinite(shortestEdge[v]))
                tallest = std::max(tallest, offset[v][0] / shortestEdge[v]);
        }
        // A thick thrombus over fine lumen edges asks for the inner layer in equal sub-layers (the same number
        // everywhere, so that the columns conform; buildWallMesh tries them).
        wall.innerSubLayersByAspect = std::clamp(int(std::ceil(tallest / kMaxInnerPrismAspect)), 1, kMaxThrombusSubLayers);
        wall.innerSubLayers = subLayers;
    }
    // The layers: the inner one's sub-layers, then the wall (with the sac's outer wall), or the single wall layer.
    const int inner = outerWall ? wall.innerSubLayers : 0;
    const int layers = inner + 1;
    wall.mesh.points = surface.points;
    wall.mesh.points.resize(std::size_t(layers + 1) * surface.points.size());
    for (int v = 0; v < n; ++v)
    {
        const Eigen::Vector3d direction = normal[std::size_t(v)];
        if (direction.norm() == 0.0)
            throw Error("a lumen vertex has no normal (degenerate surface)");
        const auto& o = offset[std::size_t(v)];
        for (int l = 1; l <= layers; ++l)
            wall.mesh.points[std::size_t(l * n + v)] =
                surface.points[std::size_t(v)] + (l == layers ? o[1] : o[0] * l / inner) * direction.normalized();
    }
    // Prisms (a, b, c) -> (a', b', c') into three tets; rotate so that the smallest index comes first (Dompierre
    // et al. 1999): with inner indices below outer ones, the quad diagonals follow the smaller inner index.
    std::vector<double> material;
    for (int l = 0; l < layers; ++l)
        for (const auto& triangle : surface.triangles)
        {
            std::array<int, 3> t = triangle;
            std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
            const int v0 = t[0] + l * n, v1 = t[1] + l * n, v2 = t[2] + l * n, v3 = v0 + n, v4 = v1 + n, v5 = v2 + n;
            const std::array<std::array<int, 4>, 3> tets =
                v1 < v2 ? std::array<std::array<int, 4>, 3>{{{v0, v1, v2, v5}, {v0, v1, v5, v4}, {v0, v4, v5, v3}}}
                        : std::array<std::array<int, 4>, 3>{{{v0, v1, v2, v4}, {v0, v4, v2, v5}, {v0, v4, v5, v3}}};
            // The inner layer is thrombus where the prism's lumen corners have 1.5 wall thicknesses to the outer
            // wall on average (half a wall thickness of thrombus at least).
            const double meanThrombus = (thrombus[std::size_t(t[0])] + thrombus[std::size_t(t[1])] + thrombus[std::size_t(t[2])]) / 3.0;
            const bool isThrombus = l < inner && meanThrombus >= 0.5 * thicknessMm;
            for (std::array<int, 4> tet : tets)
            {
                if (signedVolume(wall.mesh.points, tet) < 0.0)
                    std::swap(tet[1], tet[2]);
                if (signedVolume(wall.mesh.points, tet) <= 0.0)
                    ++wall.inverted;
                wall.mesh.tets.push_back(tet);
                material.push_back(isThrombus ? 1.0 : 0.0);
                wall.thrombusElements += isThrombus;
            }
        }
    if (outerWall)
        wall.mesh.cellFields["material"] = material;
    std::vector<double> layer(wall.mesh.points.size(), 0.0), endSet(wall.mesh.points.size(), 0.0);
    wall.endNodes.assign(ends.size(), {});
    for (int v = 0; v < n; ++v)
    {
        for (int l = 1; l <= layers; ++l)
            layer[std::size_t(l * n + v)] = double(l) / layers;
        if (endOf[std::size_t(v)] >= 0)
        {
            const int end = endOf[std::size_t(v)];
            for (int l = 0; l <= layers; ++l)
            {
                endSet[std::size_t(l * n + v)] = double(end + 1);
                wall.endNodes[std::size_t(end)].push_back(l * n + v);
            }
        }
    }
    wall.mesh.pointFields["wall_layer"] = layer;
    wall.mesh.pointFields["end_set"] = endSet;
    // Smoothing (the nodes off the lumen across their offset direction), 4-4 edge flips where a prism's diagonal
    // choice left a poor element, and smoothing again around what is still under the floor, the lumen nodes now
    // sliding along the surface too.
    std::vector<Eigen::Vector3d> across(wall.mesh.points.size(), Eigen::Vector3d::Zero());
    std::vector<double> maxMove(wall.mesh.points.size(), 0.5 * thicknessMm);
    for (std::size_t v = 0; v < across.size(); ++v)
        if (endSet[v] == 0.0)
        {
            across[v] = normal[v % std::size_t(n)].normalized();
            if (v < std::size_t(n))
                maxMove[v] = edgeCount[v] > 0.0 ? kLumenSlideFraction * edgeSum[v] / edgeCount[v] : 0.0;
        }
    // The lumen nodes move only for what stays under the floor after the rest: elsewhere the lumen is the surface.
    const std::vector<Eigen::Vector3d> built = wall.mesh.points;
    std::vector<Eigen::Vector3d> offLumen = across;
    std::fill(offLumen.begin(), offLumen.begin() + n, Eigen::Vector3d::Zero());
    wall.minDihedralUnsmoothedDeg = detail::raiseDihedralAngles(wall.mesh, offLumen, kSmoothingTargetDeg, maxMove);
    wall.edgeFlips = detail::flipEdgesOfFour(wall.mesh, material, kSmoothingTargetDeg);
    detail::raiseDihedralAngles(wall.mesh, across, kFloorDeg + kFloorMarginDeg, maxMove, built);
    for (std::size_t v = 0; v < built.size(); ++v)
        if (wall.mesh.points[v] != built[v])
        {
            ++wall.nodesSmoothed;
            wall.largestSmoothingMoveMm = std::max(wall.largestSmoothingMoveMm, (wall.mesh.points[v] - built[v]).norm());
        }
    double smallest = 180.0, sum = 0.0;
    for (const auto& tet : wall.mesh.tets)
    {
        const double angle = minDihedralAngle(wall.mesh.points[std::size_t(tet[0])], wall.mesh.points[std::size_t(tet[1])],
                                              wall.mesh.points[std::size_t(tet[2])], wall.mesh.points[std::size_t(tet[3])]);
        if (angle < smallest)
        {
            smallest = angle;
            wall.worstElementMm = 0.25 * (wall.mesh.points[std::size_t(tet[0])] + wall.mesh.points[std::size_t(tet[1])] +
                                          wall.mesh.points[std::size_t(tet[2])] + wall.mesh.points[std::size_t(tet[3])]);
        }
        sum += angle;
        wall.slivers += angle < 5.0;
    }
    wall.minDihedralDeg = smallest;
    wall.meanMinDihedralDeg = sum / double(wall.mesh.tets.size());
    if (wall.inverted > 0)
        wall.warnings.push_back(storedText(Pattern{"%1 elements are inverted where the offset folds (wall thicker than "
                                                   "the local radius of curvature): use a thinner wall or a smoother "
                                                   "surface",
                                                   {std::to_string(wall.inverted)}}));
    for (std::size_t e = 0; e < ends.size(); ++e)
        if (wall.endNodes[e].empty())
            wall.warnings.push_back(storedText(Pattern{"end %1 has no open boundary", {std::to_string(e + 1)}}));
    return wall;
}

} // namespace

WallMesh buildWallMesh(const TriangleMesh& lumen, const std::vector<VesselEnd>& ends, double thicknessMm,
                       const OuterWallDistance& outerWall)
{
    WallMesh single = buildLayeredWall(lumen, ends, thicknessMm, outerWall, 1);
    if (!outerWall || single.innerSubLayersByAspect <= 1)
        return single;
    // Sub-layers that a tall thrombus asks for are flat where the inner layer is thin (half a wall thickness under
    // the lumen's longest edges): kept only where the whole wall's smallest angle gains by them.
    WallMesh split = buildLayeredWall(lumen, ends, thicknessMm, outerWall, single.innerSubLayersByAspect);
    return split.minDihedralDeg > single.minDihedralDeg ? split : single;
}

std::vector<std::array<int, 3>> lumenFaces(const TetMesh& wall)
{
    const auto layer = wall.pointFields.find("wall_layer");
    if (layer == wall.pointFields.end())
        throw Error("the tetrahedral mesh is not a vessel wall (no wall_layer field)");
    std::vector<std::array<int, 3>> inner;
    for (const auto& face : boundaryFaces(wall.tets))
        if (layer->second[std::size_t(face[0])] == 0.0 && layer->second[std::size_t(face[1])] == 0.0 &&
            layer->second[std::size_t(face[2])] == 0.0)
            inner.push_back(face);
    return inner;
}

} // namespace vsim::mesh
