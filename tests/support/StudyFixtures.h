#pragma once

// Small, exactly known data for study tests.

#include "vsim/core/ImageVolume.h"
#include "vsim/core/SkeletonGraph.h"
#include "vsim/core/TetMesh.h"
#include "vsim/core/TriangleMesh.h"

namespace vsim::test {

/// A volume whose voxel v holds (v * multiplier) mod 2000 - 1000 HU, so every save is checkable voxel by voxel.
inline CtVolume patternedVolume(int size, int multiplier)
{
    VolumeGeometry geometry;
    geometry.dims = {size, size + 1, size + 2};
    geometry.spacing = {0.7, 0.7, 1.0};
    geometry.origin = {-120.0, -90.0, 300.0};
    geometry.direction.col(0) = Eigen::Vector3d(-1, 0, 0); // stored right-to-left, as many scanners do
    CtVolume volume(geometry);
    for (std::size_t v = 0; v < volume.size(); ++v)
        volume.data()[v] = static_cast<std::int16_t>((v * static_cast<std::size_t>(multiplier)) % 2000) - 1000;
    return volume;
}

inline bool samePattern(const CtVolume& volume, int multiplier)
{
    for (std::size_t v = 0; v < volume.size(); ++v)
        if (volume.data()[v] != static_cast<std::int16_t>((v * static_cast<std::size_t>(multiplier)) % 2000) - 1000)
            return false;
    return true;
}

inline TetMesh singleTet()
{
    TetMesh mesh;
    mesh.points = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0, 0, 2}};
    mesh.tets = {{0, 1, 2, 3}};
    mesh.cellFields["von_mises_kpa"] = {12.5};
    return mesh;
}

inline SkeletonGraph twoNodeSkeleton()
{
    SkeletonGraph skeleton;
    skeleton.nodes = {{Eigen::Vector3d(0, 0, 0), {0, 0, 0}}, {Eigen::Vector3d(0, 0, 3), {0, 0, 3}}};
    SkeletonGraph::Edge edge;
    edge.from = 0;
    edge.to = 1;
    edge.voxels = {{0, 0, 0}, {0, 0, 1}, {0, 0, 2}, {0, 0, 3}};
    edge.points = {{0, 0, 0}, {0, 0, 1}, {0, 0, 2}, {0, 0, 3}};
    edge.radii = {3.0, 2.9, 2.8, 2.7};
    skeleton.edges = {edge};
    return skeleton;
}

} // namespace vsim::test
