#pragma once

// A run frame's field on a SliceView (issue 17: every view follows the played frame). The frame (a tet mesh,
// a vessel tree as tubes of its radii, a voxel grid) is cut by the view's plane, or its particles within the
// slice's thickness are picked out (a particle set), and drawn in the view's slice coordinates (x along the
// view's right, y along its up, mm from the cursor), in front of the CT and the label overlay and behind the
// markers, coloured blue (low) to red (high) like the 3D view's legend.

#include "vsim/core/SimulationData.h"
#include "vsim/viz/SliceOrientation.h"

#include <vtkSmartPointer.h>

#include <optional>
#include <string>

class vtkActor;
class vtkCutter;
class vtkDataSetMapper;
class vtkPlane;
class vtkPolyData;
class vtkRenderer;
class vtkTransform;
class vtkTransformFilter;

namespace vsim::viz {

class SliceFieldLayer
{
public:
    explicit SliceFieldLayer(vtkRenderer* renderer);
    ~SliceFieldLayer();

    /// Shows `field` of `frame` over [low, high]; throws vsim::Error when the frame has no such field.
    void setField(const SimulationData& frame, const std::string& field, double low, double high);
    void clear();
    bool isEmpty() const;
    /// Cuts the frame by the plane through `cursorMm` with the view's axes; particles within half
    /// `thicknessMm` of it.
    void update(const Eigen::Vector3d& cursorMm, const ScreenAxes& axes, double thicknessMm);
    /// Cells of the cut drawn in the current slice (polygons of a mesh or a grid, ring segments of a tree,
    /// particles).
    long long cellsShown() const;

private:
    void pickParticles(const Eigen::Vector3d& cursorMm, const Eigen::Vector3d& normal, double thicknessMm);

    vtkRenderer* m_renderer;
    std::optional<ParticleSet> m_particles; ///< the shown frame when it is particles (picked, not cut)
    std::string m_field;
    vtkSmartPointer<vtkPolyData> m_pickedParticles;
    vtkSmartPointer<vtkPlane> m_plane;
    vtkSmartPointer<vtkCutter> m_cutter;
    vtkSmartPointer<vtkTransform> m_toSlice;
    vtkSmartPointer<vtkTransformFilter> m_toSliceFilter;
    vtkSmartPointer<vtkDataSetMapper> m_mapper;
    vtkSmartPointer<vtkActor> m_actor;
};

} // namespace vsim::viz
