#include "vsim/core/PrincipalAxis.h"

#include "vsim/core/Error.h"

#include <Eigen/Eigenvalues>

#include <algorithm>

namespace vsim {

PrincipalAxis principalAxis(const std::vector<Eigen::Vector3d>& points)
{
    if (points.empty())
        throw Error("the principal axis of no points");
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const auto& p : points)
        mean += p / double(points.size());
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for (const auto& p : points)
        covariance += (p - mean) * (p - mean).transpose();
    PrincipalAxis axis;
    axis.direction = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(covariance).eigenvectors().col(2);
    double low = 0.0, high = 0.0;
    for (const auto& p : points)
        low = std::min(low, (p - mean).dot(axis.direction)), high = std::max(high, (p - mean).dot(axis.direction));
    axis.centre = mean + 0.5 * (low + high) * axis.direction;
    axis.halfLength = 0.5 * (high - low);
    return axis;
}

} // namespace vsim
