#pragma once

// Edge adapter between the core mesh types and VTK datasets. Include it only from .cpp files.
// Meshes are copied (they are small next to images); named fields become double point/cell arrays.

#include "vsim/core/TetMesh.h"
#include "vsim/core/TriangleMesh.h"

#include <vtkSmartPointer.h>

class vtkPolyData;
class vtkUnstructuredGrid;

namespace vsim::interop {

/// Returns a vtkPolyData with the mesh's points (mm), triangles and point fields.
vtkSmartPointer<vtkPolyData> toVtk(const TriangleMesh& mesh);
/// Returns the triangles of `polyData`; throws vsim::Error when a polygon is not a triangle.
TriangleMesh triangleMeshFromVtk(vtkPolyData* polyData);
/// Returns a vtkUnstructuredGrid of VTK_TETRA cells with the mesh's point and cell fields.
vtkSmartPointer<vtkUnstructuredGrid> toVtk(const TetMesh& mesh);
/// Returns the tetrahedra of `grid`; throws vsim::Error when a cell is not a linear tetrahedron.
TetMesh tetMeshFromVtk(vtkUnstructuredGrid* grid);

} // namespace vsim::interop
