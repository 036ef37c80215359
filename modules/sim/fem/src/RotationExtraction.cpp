#include "vsim/sim/fem/RotationExtraction.h"

#include <algorithm>
#include <cmath>

namespace vsim::sim::fem {

void extractRotation(const Eigen::Matrix3d& a, Eigen::Quaterniond& q, int maxIterations, double tolerance)
{
    for (int iteration = 0; iteration < maxIterations; ++iteration)
    {
        const Eigen::Matrix3d r = q.toRotationMatrix();
        // Mueller et al. 2016 eq. 5: omega = sum_i r_i x a_i / (|sum_i r_i . a_i| + eps)
        const Eigen::Vector3d torque = r.col(0).cross(a.col(0)) + r.col(1).cross(a.col(1)) + r.col(2).cross(a.col(2));
        // Newton step on tr(R^T A): the Hessian in omega is tr(M) I - sym(M) with M = A R^T (about 2 I near the
        // solution, where Mueller et al.'s |sum r_i . a_i| ~ 3 gives the linear rate 1/3); when it is not
        // positive definite (far from the solution) take their step.
        const Eigen::Matrix3d m = a * r.transpose();
        const Eigen::Matrix3d hessian = m.trace() * Eigen::Matrix3d::Identity() - 0.5 * (m + m.transpose());
        // Symmetric 3x3 solve by the adjugate: positive definite when every leading minor is positive.
        const double h00 = hessian(0, 0), h01 = hessian(0, 1), h02 = hessian(0, 2), h11 = hessian(1, 1),
                     h12 = hessian(1, 2), h22 = hessian(2, 2);
        const double c00 = h11 * h22 - h12 * h12, c01 = h02 * h12 - h01 * h22, c02 = h01 * h12 - h02 * h11;
        const double determinant = h00 * c00 + h01 * c01 + h02 * c02;
        Eigen::Vector3d omega;
        const double floor = 0.1 * std::abs(m.trace());
        if (m.trace() > 0.0 && std::min({h00, h11, h22}) > floor && h00 * h11 - h01 * h01 > 0.0 && determinant > 0.0)
        {
            Eigen::Matrix3d adjugate;
            adjugate << c00, c01, c02, c01, h00 * h22 - h02 * h02, h01 * h02 - h00 * h12, c02, h01 * h02 - h00 * h12,
                h00 * h11 - h01 * h01;
            omega = adjugate * torque / determinant;
        }
        else
            omega = torque / (std::abs(m.trace()) + 1e-12);
        const double angle = omega.norm();
        if (angle < tolerance)
            break;
        // Small corrections (every warm-started step) skip the trigonometry: exp(omega / 2) to third order.
        const Eigen::Quaterniond turn = angle < 1e-3 ? Eigen::Quaterniond(1.0, 0.5 * omega.x(), 0.5 * omega.y(), 0.5 * omega.z())
                                                     : Eigen::Quaterniond(Eigen::AngleAxisd(angle, omega / angle));
        q = turn * q;
        q.normalize();
    }
}

} // namespace vsim::sim::fem
