#pragma once

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <cstdint>

namespace vsim {

/// Where a voxel grid sits in the DICOM patient frame (LPS: +x left, +y posterior, +z superior).
/// patient = origin + direction * diag(spacing) * index, all in millimetres; the columns of `direction`
/// are the patient-frame unit vectors of the i, j and k axes (as ITK's direction matrix).
struct VolumeGeometry
{
    std::array<int, 3> dims{0, 0, 0};
    Eigen::Vector3d spacing{1.0, 1.0, 1.0};          ///< mm
    Eigen::Vector3d origin{0.0, 0.0, 0.0};           ///< mm, centre of voxel (0,0,0)
    Eigen::Matrix3d direction = Eigen::Matrix3d::Identity();

    std::size_t voxelCount() const
    {
        return static_cast<std::size_t>(dims[0]) * static_cast<std::size_t>(dims[1]) * static_cast<std::size_t>(dims[2]);
    }
    /// Linear index of voxel (i, j, k), i fastest.
    std::size_t linearIndex(int i, int j, int k) const
    {
        return static_cast<std::size_t>(i) +
               static_cast<std::size_t>(dims[0]) * (static_cast<std::size_t>(j) + static_cast<std::size_t>(dims[1]) * k);
    }
    bool contains(int i, int j, int k) const
    {
        return i >= 0 && j >= 0 && k >= 0 && i < dims[0] && j < dims[1] && k < dims[2];
    }
    /// Continuous index -> patient position (mm).
    Eigen::Vector3d indexToPatient(const Eigen::Vector3d& index) const
    {
        return origin + direction * spacing.cwiseProduct(index);
    }
    /// Patient position (mm) -> continuous index.
    Eigen::Vector3d patientToIndex(const Eigen::Vector3d& patient) const
    {
        return (direction.transpose() * (patient - origin)).cwiseQuotient(spacing); // direction is orthonormal
    }
    /// Throws vsim::Error when dims are not positive, spacing is not positive and finite, or the direction
    /// matrix is not orthonormal (within 1e-6).
    void validate() const;
    /// Geometry equality within a tolerance (mm for origin/spacing, absolute for direction).
    bool isClose(const VolumeGeometry& other, double tolerance = 1e-9) const;
};

} // namespace vsim
