#include "vsim/interop/VtkMesh.h"

#include "vsim/core/Error.h"

#include "VtkFields.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkIdList.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>

#include <map>
#include <string>
#include <vector>

namespace vsim::interop {

vtkSmartPointer<vtkPolyData> toVtk(const TriangleMesh& mesh)
{
    auto polyData = vtkSmartPointer<vtkPolyData>::New();
    polyData->SetPoints(pointsToVtk(mesh.points));
    auto triangles = vtkSmartPointer<vtkCellArray>::New();
    for (const auto& triangle : mesh.triangles)
    {
        const vtkIdType ids[3] = {triangle[0], triangle[1], triangle[2]};
        triangles->InsertNextCell(3, ids);
    }
    polyData->SetPolys(triangles);
    fieldsToVtk(mesh.pointFields, polyData->GetPointData());
    return polyData;
}

TriangleMesh triangleMeshFromVtk(vtkPolyData* polyData)
{
    if (!polyData)
        throw Error("no surface to convert");
    TriangleMesh mesh;
    mesh.points = pointsFromVtk(polyData->GetPoints());
    vtkCellArray* polys = polyData->GetPolys();
    auto ids = vtkSmartPointer<vtkIdList>::New();
    polys->InitTraversal();
    while (polys->GetNextCell(ids))
    {
        if (ids->GetNumberOfIds() != 3)
            throw Error("surface polygon is not a triangle", {{"points", std::to_string(ids->GetNumberOfIds())}});
        mesh.triangles.push_back({static_cast<int>(ids->GetId(0)), static_cast<int>(ids->GetId(1)),
                                  static_cast<int>(ids->GetId(2))});
    }
    mesh.pointFields = fieldsFromVtk(polyData->GetPointData());
    return mesh;
}

vtkSmartPointer<vtkUnstructuredGrid> toVtk(const TetMesh& mesh)
{
    auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
    grid->SetPoints(pointsToVtk(mesh.points));
    grid->Allocate(static_cast<vtkIdType>(mesh.tets.size()));
    for (const auto& tet : mesh.tets)
    {
        const vtkIdType ids[4] = {tet[0], tet[1], tet[2], tet[3]};
        grid->InsertNextCell(VTK_TETRA, 4, ids);
    }
    fieldsToVtk(mesh.pointFields, grid->GetPointData());
    fieldsToVtk(mesh.cellFields, grid->GetCellData());
    return grid;
}

TetMesh tetMeshFromVtk(vtkUnstructuredGrid* grid)
{
    if (!grid)
        throw Error("no tetrahedral mesh to convert");
    TetMesh mesh;
    mesh.points = pointsFromVtk(grid->GetPoints());
    auto ids = vtkSmartPointer<vtkIdList>::New();
    for (vtkIdType cell = 0; cell < grid->GetNumberOfCells(); ++cell)
    {
        if (grid->GetCellType(cell) != VTK_TETRA)
            throw Error("mesh cell is not a linear tetrahedron",
                        {{"cell", std::to_string(cell)}, {"vtk cell type", std::to_string(grid->GetCellType(cell))}});
        grid->GetCellPoints(cell, ids);
        mesh.tets.push_back({static_cast<int>(ids->GetId(0)), static_cast<int>(ids->GetId(1)),
                             static_cast<int>(ids->GetId(2)), static_cast<int>(ids->GetId(3))});
    }
    mesh.pointFields = fieldsFromVtk(grid->GetPointData());
    mesh.cellFields = fieldsFromVtk(grid->GetCellData());
    return mesh;
}

} // namespace vsim::interop
