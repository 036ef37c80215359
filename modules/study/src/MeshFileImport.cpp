#include "vsim/study/MeshFileImport.h"

#include "vsim/core/Error.h"
#include "vsim/interop/VtkMesh.h"

#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

namespace vsim::study {

TetMesh readTetMeshFile(const std::filesystem::path& file)
{
    if (!std::filesystem::exists(file))
        throw Error("the mesh file does not exist", {{"file", file.string()}});
    auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
    if (!reader->CanReadFile(file.string().c_str()))
        throw Error("not a VTK XML unstructured grid (.vtu)", {{"file", file.string()}});
    reader->SetFileName(file.string().c_str());
    reader->Update();
    TetMesh mesh = interop::tetMeshFromVtk(reader->GetOutput());
    if (mesh.tets.empty())
        throw Error("the mesh has no tetrahedra", {{"file", file.string()}});
    mesh.validate();
    return mesh;
}

} // namespace vsim::study
