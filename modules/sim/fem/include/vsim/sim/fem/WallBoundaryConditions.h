#pragma once

// The boundary conditions of a vessel wall mesh (mesh::buildWallMesh's point fields): its end nodes held
// (end_set > 0) and the lumen faces the blood pressure acts on (boundary faces whose corners all lie on the lumen
// side, wall_layer 0), each kept as (element, the corner opposite it) so that it follows node splits. Shared by
// the time-stepped wall (WallSimulation) and the static hyperelastic analysis (StaticWallRun).

#include "vsim/core/TetMesh.h"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

namespace vsim::sim::fem {

struct WallBoundaryConditions
{
    struct Face
    {
        std::size_t element;
        int opposite; ///< the element's corner not on the face (kTetFaces order)
    };
    std::vector<std::uint8_t> fixed; ///< 3 per node, 1: held
    std::vector<Face> lumenFaces;

    /// The faces' corner nodes (outward order) in `tets`.
    std::vector<std::array<int, 3>> faceNodes(const std::vector<std::array<int, 4>>& tets) const;
};

/// Throws vsim::Error when the wall_layer / end_set point fields are missing (the mesh is not a vessel wall).
void requireWallFields(const TetMesh& wallMm);

/// Throws vsim::Error for a mesh that is not a wall (wall_layer / end_set missing), no held node, or no lumen face
/// under load (`loaded` selects lumen faces by centroid, mm; empty: all).
WallBoundaryConditions wallBoundaryConditions(const TetMesh& wallMm,
                                              const std::function<bool(const Eigen::Vector3d&)>& loaded = {});

} // namespace vsim::sim::fem
