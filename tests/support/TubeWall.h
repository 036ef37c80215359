#pragma once

// A structured tube wall ready for the wall solver (the GPU parity and GUI frame-rate cases), and the same tube with
// a local thinning (the quasi-static tearing cases: one element is the most stressed).

#include "vsim/core/TetMesh.h"
#include "vsim/sim/fem/QuasiStaticTearing.h"
#include "vsim/sim/fem/StructuredMeshes.h"

#include <array>
#include <cmath>

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

/// The tube of tubeWall(cells) with its wall thinned by up to 40 % around angle `angle` (rad) and height `z` (mm),
/// the lumen kept: a smooth dent (cos^2 over +-25 degrees and +-10 mm).
inline TetMesh thinnedTube(double angle, double z, const std::array<int, 3>& cells = {1, 36, 30})
{
    constexpr double pi = 3.14159265358979323846;
    TetMesh wall = tubeWall(cells);
    for (std::size_t n = 0; n < wall.points.size(); ++n)
    {
        if (wall.pointFields.at("wall_layer")[n] < 0.5)
            continue;
        Eigen::Vector3d& p = wall.points[n];
        const double turn = std::remainder(std::atan2(p.y(), p.x()) - angle, 2.0 * pi);
        const double u = turn / (25.0 * pi / 180.0), v = (p.z() - z) / 10.0;
        if (std::abs(u) >= 1.0 || std::abs(v) >= 1.0)
            continue;
        const double dent = 0.4 * std::pow(std::cos(0.5 * pi * u), 2) * std::pow(std::cos(0.5 * pi * v), 2);
        const double radius = p.head<2>().norm(), thickness = radius - 10.0;
        p.head<2>() *= (10.0 + thickness * (1.0 - dent)) / radius;
    }
    return wall;
}

/// The quasi-static tearing of a thinnedTube wall in ramp increments of `incrementPa`: the thesis's linear material
/// (E 4.23 MPa, nu 0.23), 0 to 120 kPa, tearing at 0.5 MPa, the onset and the first releases (4 tears: further ones
/// bring the torn wall near a mechanism).
inline sim::fem::QuasiStaticTearingSetup thinnedTubeTearing(const TetMesh& wall, double incrementPa)
{
    sim::fem::QuasiStaticTearingSetup setup;
    setup.wall = wall;
    setup.material.youngModulusPa = 4.23e6;
    setup.material.poissonRatio = 0.23;
    setup.startPa = 0.0;
    setup.endPa = 120e3;
    setup.incrementPa = incrementPa;
    setup.tearStressPa = 0.5e6;
    setup.maxTears = 4;
    return setup;
}

} // namespace vsim::test
