#pragma once

// A structured tube wall ready for the wall solver (the GPU parity and GUI frame-rate cases).

#include "vsim/core/TetMesh.h"
#include "vsim/sim/fem/StructuredMeshes.h"

#include <array>

namespace vsim::test {

/// A closed tube wall (inner radius 10 mm, 1.5 mm thick, 100 mm long, z from 0) of sim::fem::tubeWallTetMesh's
/// cells (layers, around, along) as a wall mesh in mm: wall_layer 0 on the lumen side, both ends fixed (end sets
/// 1 and 2).
inline TetMesh tubeWall(const std::array<int, 3>& cells)
{
    const sim::fem::StructuredTetMesh tube = sim::fem::tubeWallTetMesh(0.01, 0.0115, 0.1, cells);
    TetMesh wall;
    wall.tets = tube.tets;
    std::vector<double> layer, ends;
    for (const Eigen::Vector3d& p : tube.points)
    {
        wall.points.push_back(1e3 * p);
        layer.push_back(p.head<2>().norm() > 0.0105 ? 1.0 : 0.0);
        ends.push_back(p.z() < 1e-9 ? 1.0 : p.z() > 0.1 - 1e-9 ? 2.0 : 0.0);
    }
    wall.pointFields["wall_layer"] = layer;
    wall.pointFields["end_set"] = ends;
    return wall;
}

} // namespace vsim::test
