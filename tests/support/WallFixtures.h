#pragma once

// A capped cylinder lumen (the straight-tube analytic case) and its centerline, for wall-mesh and wall-solver
// tests.

#include "vsim/core/SkeletonGraph.h"
#include "vsim/core/TriangleMesh.h"

#include <cmath>

namespace vsim::test {

/// A closed cylinder along z (radius, length in mm, `around` segments, rings every mm), caps as fans; outward
/// triangles.
inline TriangleMesh cappedCylinder(double radius, double length, int around)
{
    TriangleMesh surface;
    const int rings = int(length) + 1;
    for (int k = 0; k < rings; ++k)
        for (int j = 0; j < around; ++j)
        {
            const double phi = 2.0 * M_PI * j / around;
            surface.points.emplace_back(radius * std::cos(phi), radius * std::sin(phi), length * k / (rings - 1));
        }
    for (int k = 0; k + 1 < rings; ++k)
        for (int j = 0; j < around; ++j)
        {
            const int a = k * around + j, b = k * around + (j + 1) % around, c = a + around, d = b + around;
            surface.triangles.push_back({a, b, d});
            surface.triangles.push_back({a, d, c});
        }
    const int bottom = int(surface.points.size()), top = bottom + 1;
    surface.points.emplace_back(0, 0, 0);
    surface.points.emplace_back(0, 0, length);
    for (int j = 0; j < around; ++j)
    {
        surface.triangles.push_back({bottom, (j + 1) % around, j});
        surface.triangles.push_back({top, (rings - 1) * around + j, (rings - 1) * around + (j + 1) % around});
    }
    return surface;
}

/// The cylinder's centerline: one edge along z with constant radius, points 1 mm apart.
inline SkeletonGraph cylinderCenterline(double radius, double length)
{
    SkeletonGraph graph;
    graph.nodes.push_back({Eigen::Vector3d(0, 0, 0), {0, 0, 0}});
    graph.nodes.push_back({Eigen::Vector3d(0, 0, length), {0, 0, int(length)}});
    SkeletonGraph::Edge edge;
    edge.from = 0;
    edge.to = 1;
    for (int k = 0; k <= int(length); ++k)
    {
        edge.points.emplace_back(0, 0, double(k));
        edge.voxels.push_back({0, 0, k});
        edge.radii.push_back(radius);
    }
    graph.edges.push_back(edge);
    return graph;
}

} // namespace vsim::test
