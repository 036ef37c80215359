#pragma once

#include <Eigen/Core>

#include <vector>

namespace vsim {

/// The axis of largest spread of a point set: its direction (unit), the middle of the points' extent along it and
/// the half-length of that extent (the points' units).
struct PrincipalAxis
{
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();
    double halfLength = 0.0;
};

/// The principal axis of `points` (largest eigenvector of their covariance). Throws vsim::Error for no points.
PrincipalAxis principalAxis(const std::vector<Eigen::Vector3d>& points);

} // namespace vsim
