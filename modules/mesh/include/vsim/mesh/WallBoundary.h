#pragma once

// Which faces of a tetrahedral wall from elsewhere carry the blood pressure, and which nodes are held: never
// guessed. The pressure faces come from a point-data array (nonzero on the lumen surface's nodes) or from a point
// inside the lumen (the smooth boundary patch facing it: boundary faces joined across edges whose dihedral angle is
// below a feature angle, as the inner surface of a cut vessel is parted from its end cuts by ~90 degree edges); the
// fixed nodes from a point-data array or from the pressure surface's open boundary loops (the end cuts touching
// them). The result carries the wall fields WallSimulation reads (wall_layer 0 on the lumen surface, end_set).

#include "vsim/core/TetMesh.h"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace vsim::mesh {

struct WallBoundarySelection
{
    std::string pressureArray;                  ///< point data, nonzero on the lumen surface's nodes
    std::optional<Eigen::Vector3d> lumenPointMm; ///< a point inside the lumen (patient frame, mm)
    std::string fixedArray;                     ///< point data, nonzero on the held nodes
    bool fixOpenEnds = false;                   ///< hold the end cuts at the pressure surface's open loops
    double featureAngleDeg = 60.0;              ///< dihedral angle that parts smooth patches
};

struct MarkedWall
{
    TetMesh wall;                 ///< with wall_layer (0 on pressure-face nodes, 1 elsewhere) and end_set (1: held)
    std::size_t pressureFaces = 0;
    std::size_t boundaryFaces = 0;
    std::size_t fixedNodes = 0;
    std::size_t openLoops = 0;    ///< boundary loops of the pressure surface (2 for a tube cut at both ends)
    std::vector<std::string> warnings;
};

/// Marks the pressure faces and the held nodes of `mesh` (mm) as `selection` says. Throws vsim::Error naming the
/// options when the selection does not say where the pressure acts (pressureArray or lumenPointMm) or what is held
/// (fixedArray or fixOpenEnds), for an array that is missing, and when no face or no node results.
MarkedWall markWallBoundary(TetMesh mesh, const WallBoundarySelection& selection);

} // namespace vsim::mesh
