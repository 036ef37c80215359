#pragma once

// The lumen surface of a vessel label: iso-surface, windowed-sinc smoothing and the thesis's "compression"
// (decimation to a vertex budget, ch. 4.1) with the shape error it costs. VTK stays in the .cpp.

#include "vsim/core/ImageVolume.h"
#include "vsim/core/Parameters.h"
#include "vsim/core/Progress.h"
#include "vsim/core/TriangleMesh.h"

#include <filesystem>

namespace vsim::mesh {

/// smoothing_iterations, smoothing_passband, target_vertices (0: keep every vertex).
std::vector<ParameterSpec> surfaceParameters();

struct VesselSurface
{
    TriangleMesh surface;           ///< mm, LPS, outward (positive signed volume)
    std::size_t fullVertices = 0;   ///< before decimation
    double meanErrorMm = 0.0;       ///< mean distance between the decimated and the undecimated surface, both ways
    double hausdorffMm = 0.0;       ///< symmetric Hausdorff distance between them
};

/// Iso-surface at 0.5 of the voxels equal to `value` (flying edges, computed in voxel coordinates and mapped to
/// the patient frame through the label's geometry), smoothed with a windowed-sinc filter, decimated (quadric
/// error, volume preserving) when target_vertices asks for fewer vertices. Throws vsim::Error for an empty label.
VesselSurface extractVesselSurface(const LabelVolume& label, std::uint8_t value, const ParameterSet& parameters,
                                   const Progress& progress = {});

/// Writes a binary STL file (mm); throws vsim::Error on failure.
void writeStl(const TriangleMesh& surface, const std::filesystem::path& file);

} // namespace vsim::mesh
