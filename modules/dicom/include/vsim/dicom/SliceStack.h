#pragma once

#include "vsim/core/VolumeGeometry.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

namespace vsim::dicom {

/// The planes of an acquisition as DICOM describes them: parallel image planes that share an orientation
/// (Image Orientation Patient) and pixel spacing, each with its own position (Image Position Patient). Unlike a
/// VolumeGeometry it can describe gantry-tilted and unevenly spaced series. All in mm, LPS.
struct SliceStack
{
    int columns = 0;
    int rows = 0;
    double columnSpacing = 1.0;                        ///< mm between neighbouring columns (along xDirection)
    double rowSpacing = 1.0;                           ///< mm between neighbouring rows (along yDirection)
    Eigen::Vector3d xDirection = Eigen::Vector3d::UnitX(); ///< IOP first triplet: along a row, column index up
    Eigen::Vector3d yDirection = Eigen::Vector3d::UnitY(); ///< IOP second triplet: down a column
    std::vector<Eigen::Vector3d> positions;            ///< IPP (centre of the first pixel) of each slice

    Eigen::Vector3d normal() const { return xDirection.cross(yDirection).normalized(); }
    /// Patient position (mm) of pixel (column i, row j) of slice `slice`.
    Eigen::Vector3d pixelPosition(std::size_t slice, double i, double j) const
    {
        return positions[slice] + i * columnSpacing * xDirection + j * rowSpacing * yDirection;
    }
    /// The volume grid with this stack's in-plane axes whose slice axis is the normal, spaced by the distance
    /// between the first two planes: exact for an untilted, evenly spaced stack.
    VolumeGeometry nominalGeometry() const;
};

/// The stack of a volume grid: one plane per k.
SliceStack stackOf(const VolumeGeometry& geometry);

/// A gantry-tilted acquisition of the same region as `geometry`: the image planes are turned by `tiltDegrees`
/// about the x axis (IOP column vector (0, cos, sin)) while the table moves along patient z by the slice spacing,
/// as CT scanners write tilted series. The centre slice coincides with the centre of `geometry`.
SliceStack tiltedStack(const VolumeGeometry& geometry, double tiltDegrees);

} // namespace vsim::dicom
