#include "BlurredTubeFit.h"
#include "BlurredDisc.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vsim::imaging::detail {
namespace {

/// Least squares by Levenberg-Marquardt with forward-difference Jacobians (`steps`: the difference per parameter).
/// `residuals(x, out)` fills the residual vector; `valid(x)` rejects a step out of the model's domain. Returns the
/// final cost (sum of squares).
template <class Residuals, class Valid>
double levenbergMarquardt(Eigen::VectorXd& x, const Eigen::VectorXd& steps, Residuals residuals, Valid valid)
{
    const Eigen::Index n = x.size();
    Eigen::VectorXd r, trial;
    residuals(x, r);
    double cost = r.squaredNorm(), lambda = 1e-3;
    for (int iteration = 0; iteration < 40; ++iteration)
    {
        Eigen::MatrixXd jacobian(r.size(), n);
        for (Eigen::Index j = 0; j < n; ++j)
        {
            Eigen::VectorXd shifted = x;
            shifted[j] += steps[j];
            residuals(shifted, trial);
            jacobian.col(j) = (trial - r) / steps[j];
        }
        const Eigen::MatrixXd normal = jacobian.transpose() * jacobian;
        const Eigen::VectorXd gradient = jacobian.transpose() * r;
        bool improved = false, converged = false;
        for (int attempt = 0; attempt < 8 && !improved; ++attempt)
        {
            Eigen::MatrixXd damped = normal;
            damped.diagonal() *= 1.0 + lambda;
            const Eigen::VectorXd candidate = x + damped.ldlt().solve(-gradient);
            if (!valid(candidate))
            {
                lambda *= 10.0;
                continue;
            }
            residuals(candidate, trial);
            const double candidateCost = trial.squaredNorm();
            if (candidateCost < cost)
            {
                improved = true;
                converged = cost - candidateCost < 1e-10 * cost;
                x = candidate, r = trial, cost = candidateCost, lambda = std::max(1e-7, lambda / 10.0);
            }
            else
                lambda *= 10.0;
        }
        if (!improved || converged)
            break;
    }
    return cost;
}

/// The model's occupancy at sample k given the tube's own occupancy there.
double withNeighbours(const TubeSamples& samples, std::size_t k, double own)
{
    return samples.floor.empty() ? own : std::max(own, samples.floor[k]);
}

} // namespace

std::pair<double, double> toPolyline(const std::vector<Eigen::Vector3d>& path, const std::vector<double>& arc,
                                     const Eigen::Vector3d& p)
{
    double best = 1e300, at = 0.0;
    for (std::size_t i = 1; i < path.size(); ++i)
    {
        const Eigen::Vector3d d = path[i] - path[i - 1];
        const double length2 = d.squaredNorm();
        const double t = length2 > 0.0 ? std::clamp((p - path[i - 1]).dot(d) / length2, 0.0, 1.0) : 0.0;
        const double distance = (path[i - 1] + t * d - p).squaredNorm();
        if (distance < best)
            best = distance, at = arc[i - 1] + t * (arc[i] - arc[i - 1]);
    }
    return {std::sqrt(best), at};
}

double blurredOccupancy(double radius, double distance, double sigma)
{
    return blurredDiscOccupancy(distance, std::max(radius, 0.0), sigma);
}

double TubeModel::occupancy(const Eigen::Vector3d& p, double sigma) const
{
    if (axis.size() < 2 || !(arc.back() > 0.0))
        return 0.0;
    const auto [distance, at] = toPolyline(axis, arc, p);
    const double radius = startRadiusMm + (endRadiusMm - startRadiusMm) * at / arc.back();
    return blurredOccupancy(radius, distance, sigma);
}

TubeFit fitReferenceTube(const TubeSamples& samples, const std::vector<Eigen::Vector3d>& path,
                         const std::vector<double>& arc, double lower, double upper, double blood, double radius0,
                         double tissue0, double sigma0)
{
    TubeFit fit;
    if (samples.points.size() < 30 || path.size() < 2 || !(upper > lower))
        return fit;
    const Eigen::Vector3d axis = (path.back() - path.front()).normalized();
    const Eigen::Vector3d f1 = axis.unitOrthogonal(), f2 = axis.cross(f1);
    // Parameters: the shift (u, v), r1, r2, sigma, tissue.
    Eigen::VectorXd x(6), steps(6);
    x << 0.0, 0.0, radius0, radius0, sigma0, tissue0;
    steps << 1e-4, 1e-4, 1e-4, 1e-4, 1e-4, 0.5;
    auto residuals = [&](const Eigen::VectorXd& q, Eigen::VectorXd& out) {
        const Eigen::Vector3d shift = q[0] * f1 + q[1] * f2;
        out.resize(Eigen::Index(samples.points.size()));
        for (std::size_t k = 0; k < samples.points.size(); ++k)
        {
            const auto [distance, s] = toPolyline(path, arc, samples.points[k] - shift);
            const double t = std::clamp((s - lower) / (upper - lower), 0.0, 1.0);
            const double own = blurredOccupancy(q[2] + (q[3] - q[2]) * t, distance, q[4]);
            out[Eigen::Index(k)] = samples.values[k] - (q[5] + (blood - q[5]) * withNeighbours(samples, k, own));
        }
    };
    const double cost = levenbergMarquardt(x, steps, residuals, [](const Eigen::VectorXd& q) {
        return q[2] > 0.05 && q[3] > 0.05 && q[4] > 0.05;
    });
    fit.ok = std::isfinite(cost) && x[2] > 0.05 && x[3] > 0.05;
    fit.r1 = x[2], fit.r2 = x[3], fit.sigma = x[4], fit.tissue = x[5];
    return fit;
}

TubeFit fitThinTube(const TubeSamples& samples, const Eigen::Vector3d& start, const Eigen::Vector3d& end, double blood,
                    double radius0, double sigma)
{
    TubeFit fit;
    if (samples.points.size() < 30 || !((end - start).norm() > 0.0))
        return fit;
    const Eigen::Vector3d axis = (end - start).normalized();
    const Eigen::Vector3d f1 = axis.unitOrthogonal(), f2 = axis.cross(f1);
    // Parameters: the start's shift (u, v), r1, r2, the end's shift (u2, v2).
    Eigen::VectorXd x(6), steps = Eigen::VectorXd::Constant(6, 1e-4);
    x << 0.0, 0.0, radius0, radius0, 0.0, 0.0;
    auto line = [&](const Eigen::VectorXd& q) {
        return std::vector<Eigen::Vector3d>{start + q[0] * f1 + q[1] * f2, end + q[4] * f1 + q[5] * f2};
    };
    auto residuals = [&](const Eigen::VectorXd& q, Eigen::VectorXd& out) {
        const std::vector<Eigen::Vector3d> path = line(q);
        const std::vector<double> arc{0.0, (path[1] - path[0]).norm()};
        out.resize(Eigen::Index(samples.points.size()));
        for (std::size_t k = 0; k < samples.points.size(); ++k)
        {
            const auto [distance, s] = toPolyline(path, arc, samples.points[k]);
            const double own = blurredOccupancy(q[2] + (q[3] - q[2]) * s / arc[1], distance, sigma);
            const double tissue = samples.tissue[k];
            out[Eigen::Index(k)] = samples.values[k] - (tissue + (blood - tissue) * withNeighbours(samples, k, own));
        }
    };
    const double cost = levenbergMarquardt(x, steps, residuals, [](const Eigen::VectorXd& q) {
        return q[2] > 0.05 && q[3] > 0.05;
    });
    fit.ok = std::isfinite(cost) && x[2] > 0.05 && x[3] > 0.05;
    fit.r1 = x[2], fit.r2 = x[3], fit.sigma = sigma;
    const std::vector<Eigen::Vector3d> ends = line(x);
    fit.start = ends[0], fit.end = ends[1];
    return fit;
}

std::pair<Eigen::Vector3d, Eigen::Vector3d> lumenLine(const TubeSamples& samples, const Eigen::Vector3d& start,
                                                      const Eigen::Vector3d& end, double blood)
{
    const Eigen::Vector3d direction = (end - start).normalized();
    const double middle = 0.5 * (start + end).dot(direction);
    Eigen::Vector3d centre[2] = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    double weight[2] = {0.0, 0.0};
    for (std::size_t k = 0; k < samples.points.size(); ++k)
    {
        const double w = std::max(0.0, (samples.values[k] - samples.tissue[k]) / (blood - samples.tissue[k]));
        const int half = samples.points[k].dot(direction) >= middle ? 1 : 0;
        centre[half] += w * samples.points[k], weight[half] += w;
    }
    if (!(weight[0] > 0.0 && weight[1] > 0.0))
        return {start, end};
    const Eigen::Vector3d c0 = centre[0] / weight[0], c1 = centre[1] / weight[1];
    if (!((c1 - c0).norm() > 0.25 * (end - start).norm()))
        return {start, end};
    const Eigen::Vector3d d = (c1 - c0).normalized();
    return {c0 + (start - c0).dot(d) * d, c0 + (end - c0).dot(d) * d}; // the same span, on the new line
}

} // namespace vsim::imaging::detail
