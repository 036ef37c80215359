#pragma once

// Edge adapter between the solvers' frame data (vsim/core/SimulationData.h) and VTK datasets, for the Run
// artifact's frames that ParaView reads. Include it only from .cpp files. A tet mesh is VtkMesh.h's.
//
// A vessel network is a vtkPolyData: its nodes first (point array node_index), the interior points of each
// segment's display path after them, one polyline per segment from its `from` node to its `to` node, the segment's
// radii, length and resistance as cell arrays (segment_start_radius_mm, segment_end_radius_mm, segment_length_mm,
// segment_resistance_pa_s_m3) beside its result fields, and the root and outlet conditions as field data. Node names
// are not kept. A voxel grid is a vtkImageData with its geometry (direction included) and one float point array per
// field. A particle set is a vtkPolyData of one vertex cell per particle with its fields as double point arrays (and
// no lines: that is how a run's reader tells it from a network).

#include "vsim/core/SimulationData.h"

#include <vtkSmartPointer.h>

class vtkImageData;
class vtkPolyData;

namespace vsim::interop {

vtkSmartPointer<vtkPolyData> toVtk(const VesselNetwork& network);
/// Throws vsim::Error when the dataset is not a network written by toVtk (no node_index, a line's ends not nodes).
VesselNetwork networkFromVtk(vtkPolyData* polyData);

vtkSmartPointer<vtkImageData> toVtk(const GridFields& grid);
/// Throws vsim::Error for a dataset without point arrays or with a multi-component one.
GridFields gridFieldsFromVtk(vtkImageData* image);

vtkSmartPointer<vtkPolyData> toVtk(const ParticleSet& particles);
/// Throws vsim::Error for a dataset with lines or polygons, or a point array of more than one component.
ParticleSet particlesFromVtk(vtkPolyData* polyData);

} // namespace vsim::interop
