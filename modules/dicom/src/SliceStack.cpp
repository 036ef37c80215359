#include "vsim/dicom/SliceStack.h"

#include <cmath>
#include <numbers>

namespace vsim::dicom {

VolumeGeometry SliceStack::nominalGeometry() const
{
    VolumeGeometry geometry;
    geometry.dims = {columns, rows, static_cast<int>(positions.size())};
    const Eigen::Vector3d n = normal();
    const double sliceSpacing = positions.size() > 1 ? std::abs((positions[1] - positions[0]).dot(n)) : 1.0;
    geometry.spacing = {columnSpacing, rowSpacing, sliceSpacing > 1e-6 ? sliceSpacing : 1.0};
    geometry.origin = positions.empty() ? Eigen::Vector3d::Zero() : positions.front();
    geometry.direction.col(0) = xDirection.normalized();
    geometry.direction.col(1) = yDirection.normalized();
    geometry.direction.col(2) = n;
    return geometry;
}

SliceStack stackOf(const VolumeGeometry& geometry)
{
    SliceStack stack;
    stack.columns = geometry.dims[0];
    stack.rows = geometry.dims[1];
    stack.columnSpacing = geometry.spacing.x();
    stack.rowSpacing = geometry.spacing.y();
    stack.xDirection = geometry.direction.col(0);
    stack.yDirection = geometry.direction.col(1);
    for (int k = 0; k < geometry.dims[2]; ++k)
        stack.positions.push_back(geometry.indexToPatient(Eigen::Vector3d(0, 0, k)));
    return stack;
}

SliceStack tiltedStack(const VolumeGeometry& geometry, double tiltDegrees)
{
    const double angle = tiltDegrees * std::numbers::pi / 180.0;
    SliceStack stack;
    stack.columns = geometry.dims[0];
    stack.rows = geometry.dims[1];
    stack.columnSpacing = geometry.spacing.x();
    stack.rowSpacing = geometry.spacing.y();
    stack.xDirection = Eigen::Vector3d::UnitX();
    stack.yDirection = Eigen::Vector3d(0.0, std::cos(angle), std::sin(angle));
    const Eigen::Vector3d centre =
        geometry.indexToPatient(0.5 * Eigen::Vector3d(geometry.dims[0] - 1, geometry.dims[1] - 1, geometry.dims[2] - 1));
    const Eigen::Vector3d firstPixelOffset = -0.5 * (stack.columns - 1) * stack.columnSpacing * stack.xDirection -
                                             0.5 * (stack.rows - 1) * stack.rowSpacing * stack.yDirection;
    for (int k = 0; k < geometry.dims[2]; ++k)
        stack.positions.push_back(centre + firstPixelOffset +
                                  (k - 0.5 * (geometry.dims[2] - 1)) * geometry.spacing.z() * Eigen::Vector3d::UnitZ());
    return stack;
}

} // namespace vsim::dicom
