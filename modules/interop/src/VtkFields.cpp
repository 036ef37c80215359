#include "VtkFields.h"

#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkPoints.h>

#include <algorithm>

namespace vsim::interop {

vtkSmartPointer<vtkPoints> pointsToVtk(const std::vector<Eigen::Vector3d>& points)
{
    auto vtkPointsOut = vtkSmartPointer<vtkPoints>::New();
    vtkPointsOut->SetDataTypeToDouble();
    vtkPointsOut->SetNumberOfPoints(static_cast<vtkIdType>(points.size()));
    for (std::size_t p = 0; p < points.size(); ++p)
        vtkPointsOut->SetPoint(static_cast<vtkIdType>(p), points[p].data());
    return vtkPointsOut;
}

std::vector<Eigen::Vector3d> pointsFromVtk(vtkPoints* points)
{
    std::vector<Eigen::Vector3d> result(points ? points->GetNumberOfPoints() : 0);
    for (vtkIdType p = 0; p < static_cast<vtkIdType>(result.size()); ++p)
        points->GetPoint(p, result[p].data());
    return result;
}

void fieldsToVtk(const std::map<std::string, std::vector<double>>& fields, vtkFieldData* target)
{
    for (const auto& [name, values] : fields)
    {
        auto array = vtkSmartPointer<vtkDoubleArray>::New();
        array->SetName(name.c_str());
        array->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
        for (std::size_t i = 0; i < values.size(); ++i)
            array->SetValue(static_cast<vtkIdType>(i), values[i]);
        target->AddArray(array);
    }
}

std::map<std::string, std::vector<double>> fieldsFromVtk(vtkFieldData* source, const std::vector<std::string>& skip)
{
    std::map<std::string, std::vector<double>> fields;
    for (int a = 0; a < source->GetNumberOfArrays(); ++a)
    {
        vtkDataArray* array = source->GetArray(a);
        if (!array || !array->GetName() || array->GetNumberOfComponents() != 1 ||
            std::find(skip.begin(), skip.end(), array->GetName()) != skip.end())
            continue; // multi-component arrays (normals, vectors) are not scalar fields
        std::vector<double>& values = fields[array->GetName()];
        values.resize(array->GetNumberOfTuples());
        for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
            values[i] = array->GetComponent(i, 0);
    }
    return fields;
}

} // namespace vsim::interop
