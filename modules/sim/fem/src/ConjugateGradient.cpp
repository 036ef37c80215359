#include "vsim/sim/fem/ConjugateGradient.h"

#include "vsim/core/Error.h"

#include <Eigen/LU>

#include <cmath>

namespace vsim::sim::fem {
namespace {

void filter(Eigen::VectorXd& v, const std::vector<std::uint8_t>& constrained)
{
    if (constrained.empty())
        return;
    for (Eigen::Index i = 0; i < v.size(); ++i)
        if (constrained[std::size_t(i)])
            v[i] = 0.0;
}

double dot(const Eigen::VectorXd& a, const Eigen::VectorXd& b)
{
    double sum = 0.0;
#pragma omp parallel for reduction(+ : sum) schedule(static)
    for (Eigen::Index i = 0; i < a.size(); ++i)
        sum += a[i] * b[i];
    return sum;
}

} // namespace

ConjugateGradientResult solveConjugateGradient(const BlockSparseMatrix& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                                               const std::vector<std::uint8_t>& constrained, double tolerance,
                                               int maxIterations)
{
    const Eigen::Index n = Eigen::Index(3 * a.nodeCount());
    if (b.size() != n || x.size() != n || (!constrained.empty() && constrained.size() != std::size_t(n)))
        throw Error("conjugate gradients: the matrix, right-hand side, guess and constraints differ in size");
    std::vector<Eigen::Matrix3d> inverseDiagonal(a.nodeCount());
    for (std::size_t node = 0; node < a.nodeCount(); ++node)
    {
        const Eigen::Matrix3d& d = a.diagonal(node);
        inverseDiagonal[node] = std::abs(d.determinant()) > 0.0 ? Eigen::Matrix3d(d.inverse()) : Eigen::Matrix3d::Identity();
    }
    auto precondition = [&](const Eigen::VectorXd& r, Eigen::VectorXd& z) {
        z.resize(n);
#pragma omp parallel for schedule(static)
        for (std::ptrdiff_t node = 0; node < std::ptrdiff_t(a.nodeCount()); ++node)
            z.segment<3>(3 * node) = inverseDiagonal[std::size_t(node)] * r.segment<3>(3 * node);
        filter(z, constrained);
    };

    ConjugateGradientResult result;
    Eigen::VectorXd filteredB = b;
    filter(filteredB, constrained);
    const double bNorm = std::sqrt(dot(filteredB, filteredB));
    Eigen::VectorXd r(n), z(n), p(n), q(n);
    a.multiply(x, q);
    r = b - q;
    filter(r, constrained);
    // Relative to |S b|; when only prescribed values drive the free ones (b = 0 there), to the first residual.
    const double reference = bNorm > 0.0 ? bNorm : std::sqrt(dot(r, r));
    if (reference == 0.0)
    {
        result.converged = true;
        return result;
    }
    precondition(r, z);
    p = z;
    double rz = dot(r, z);
    double residual = std::sqrt(dot(r, r)) / reference;
    while (residual > tolerance && result.iterations < maxIterations)
    {
        a.multiply(p, q);
        filter(q, constrained);
        const double pq = dot(p, q);
        if (!(pq > 0.0))
            break; // not positive definite along p (or NaN): the caller's guard reports it
        const double alpha = rz / pq;
        x += alpha * p;
        r -= alpha * q;
        precondition(r, z);
        const double rzNext = dot(r, z);
        p = z + (rzNext / rz) * p;
        rz = rzNext;
        residual = std::sqrt(dot(r, r)) / reference;
        ++result.iterations;
    }
    result.relativeResidual = residual;
    result.converged = residual <= tolerance;
    return result;
}

} // namespace vsim::sim::fem
