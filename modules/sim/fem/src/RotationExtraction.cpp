#include "vsim/sim/fem/RotationExtraction.h"

#include <Eigen/Cholesky>

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
        Eigen::Vector3d omega;
        const Eigen::LLT<Eigen::Matrix3d> newton(hessian);
        if (newton.info() == Eigen::Success && hessian.diagonal().minCoeff() > 0.1 * m.trace())
            omega = newton.solve(torque);
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
