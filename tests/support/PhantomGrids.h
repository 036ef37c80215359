#pragma once

// Grids for rendering a phantom's truth labels finely around its vessels only (no body, no air): the fixtures of the
// skeleton, centerline and measurement tests; and the truth segment a measured one stands for.

#include "vsim/core/VolumeGeometry.h"
#include "vsim/dicom/PhantomModel.h"

#include <algorithm>
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

/// The truth segment whose end nodes are nearest to a measured segment's ends `a` and `b` (mm), either way round.
inline const dicom::VesselSegment& nearestTruthSegment(const dicom::PhantomModel& model, const Eigen::Vector3d& a,
                                                       const Eigen::Vector3d& b)
{
    const dicom::VesselSegment* best = &model.segments.front();
    double bestDistance = 1e300;
    for (const dicom::VesselSegment& truth : model.segments)
    {
        const Eigen::Vector3d ta = model.nodes[std::size_t(truth.from)].position;
        const Eigen::Vector3d tb = model.nodes[std::size_t(truth.to)].position;
        const double d = std::min((a - ta).norm() + (b - tb).norm(), (a - tb).norm() + (b - ta).norm());
        if (d < bestDistance)
            bestDistance = d, best = &truth;
    }
    return *best;
}

} // namespace vsim::test
