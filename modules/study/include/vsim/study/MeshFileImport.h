#pragma once

// Tetrahedral meshes from outside (ParaView, gmsh via meshio, other planning tools) as VTK XML unstructured grids.

#include "vsim/core/TetMesh.h"

#include <filesystem>

namespace vsim::study {

/// Reads a .vtu file's tetrahedra (mm, patient frame) with its point and cell fields. Throws vsim::Error for a
/// missing or unreadable file, one without tetrahedra, or inverted / degenerate elements (naming the first).
TetMesh readTetMeshFile(const std::filesystem::path& file);

} // namespace vsim::study
