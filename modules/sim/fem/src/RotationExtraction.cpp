#include "vsim/sim/fem/RotationExtraction.h"

#include <cmath>

namespace vsim::sim::fem {

void extractRotation(const Eigen::Matrix3d& a, Eigen::Quaterniond& q, int maxIterations, double tolerance)
{
    for (int iteration = 0; iteration < maxIterations; ++iteration)
    {
        const Eigen::Matrix3d r = q.toRotationMatrix();
        // Mueller et al. 2016 eq. 5: omega = sum_i r_i x a_i / (|sum_i r_i . a_i| + eps)
        const Eigen::Vector3d torque = r.col(0).cross(a.col(0)) + r.col(1).cross(a.col(1)) + r.col(2).cross(a.col(2));
        const double alignment = std::abs(r.col(0).dot(a.col(0)) + r.col(1).dot(a.col(1)) + r.col(2).dot(a.col(2)));
        const Eigen::Vector3d omega = torque / (alignment + 1e-12);
        const double angle = omega.norm();
        if (angle < tolerance)
            break;
        q = Eigen::Quaterniond(Eigen::AngleAxisd(angle, omega / angle)) * q;
        q.normalize();
    }
}

} // namespace vsim::sim::fem
