#pragma once

// Points and named scalar fields between the core types and VTK, shared by the mesh, network and grid adapters.

#include <Eigen/Core>
#include <vtkSmartPointer.h>

#include <map>
#include <string>
#include <vector>

class vtkFieldData;
class vtkPoints;

namespace vsim::interop {

/// Double-precision VTK points (mm).
vtkSmartPointer<vtkPoints> pointsToVtk(const std::vector<Eigen::Vector3d>& points);
std::vector<Eigen::Vector3d> pointsFromVtk(vtkPoints* points);
/// Each field as a named double array of one component.
void fieldsToVtk(const std::map<std::string, std::vector<double>>& fields, vtkFieldData* target);
/// Every named one-component array (multi-component ones, normals or vectors, are not scalar fields); `skip` names
/// arrays an adapter reads itself.
std::map<std::string, std::vector<double>> fieldsFromVtk(vtkFieldData* source, const std::vector<std::string>& skip = {});

} // namespace vsim::interop
