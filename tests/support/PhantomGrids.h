#pragma once

// Grids for rendering a phantom's truth labels finely around its vessels only (no body, no air): the fixtures of the
// skeleton, centerline and measurement tests.

#include "vsim/core/VolumeGeometry.h"
#include "vsim/dicom/PhantomModel.h"

#include <cmath>

namespace vsim::test {

/// An axial grid over the model's vessel nodes +- `margin` mm, with isotropic `spacing` mm.
inline VolumeGeometry gridAroundVessels(const dicom::PhantomModel& model, double spacing, double margin)
{
    Eigen::Vector3d low = Eigen::Vector3d::Constant(1e9), high = Eigen::Vector3d::Constant(-1e9);
    for (const dicom::VesselNode& node : model.nodes)
        low = low.cwiseMin(node.position), high = high.cwiseMax(node.position);
    VolumeGeometry geometry;
    geometry.origin = low - Eigen::Vector3d::Constant(margin);
    geometry.spacing = Eigen::Vector3d::Constant(spacing);
    for (int a = 0; a < 3; ++a)
        geometry.dims[a] = int(std::ceil((high[a] - low[a] + 2 * margin) / spacing)) + 1;
    return geometry;
}

} // namespace vsim::test
