#include "vsim/sim/fem/ConjugateGradient.h"

#include "vsim/core/Error.h"

#include <Eigen/LU>

#include <cmath>

namespace vsim::sim::fem {

ConjugateGradientResult solveConjugateGradient(const BlockSparseMatrix& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                                               const std::vector<std::uint8_t>& constrained, double tolerance,
                                               int maxIterations, const AggregationMultigrid* multigrid)
{
    const std::size_t nodes = a.nodeCount();
    const Eigen::Index n = Eigen::Index(3 * nodes);
    if (b.size() != n || x.size() != n || (!constrained.empty() && constrained.size() != std::size_t(n)))
        throw Error("conjugate gradients: the matrix, right-hand side, guess and constraints differ in size");
    // The filter as a 0/1 mask per component, folded into the preconditioner and the mat-vec.
    Eigen::VectorXd free = Eigen::VectorXd::Ones(n);
    for (std::size_t i = 0; i < constrained.size(); ++i)
        if (constrained[i])
            free[Eigen::Index(i)] = 0.0;
    std::vector<Eigen::Matrix3d> inverseDiagonal(nodes);
    for (std::size_t node = 0; node < nodes; ++node)
    {
        const Eigen::Matrix3d& d = a.diagonal(node);
        const Eigen::Matrix3d inverse = std::abs(d.determinant()) > 0.0 ? Eigen::Matrix3d(d.inverse()) : Eigen::Matrix3d::Identity();
        const Eigen::Vector3d mask = free.segment<3>(Eigen::Index(3 * node));
        inverseDiagonal[node] = mask.asDiagonal() * inverse * mask.asDiagonal();
    }
    const std::uint32_t* rowStart = a.rowStart().data();
    const std::uint32_t* columns = a.columns().data();
    const Eigen::Matrix3d* blocks = a.blocks().data();
    auto row = [&](const Eigen::VectorXd& v, std::ptrdiff_t node) {
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        for (std::uint32_t s = rowStart[node]; s < rowStart[node + 1]; ++s)
            sum.noalias() += blocks[s] * v.segment<3>(Eigen::Index(3 * columns[s]));
        return Eigen::Vector3d(free.segment<3>(3 * node).cwiseProduct(sum));
    };

    ConjugateGradientResult result;
    Eigen::VectorXd r(n), z(n), p = Eigen::VectorXd::Zero(n), q = Eigen::VectorXd::Zero(n);
    double bb = 0.0, rr = 0.0, rz = 0.0;
#pragma omp parallel for reduction(+ : bb, rr, rz) schedule(static)
    for (std::ptrdiff_t node = 0; node < std::ptrdiff_t(nodes); ++node)
    {
        const Eigen::Vector3d bFree = free.segment<3>(3 * node).cwiseProduct(b.segment<3>(3 * node));
        const Eigen::Vector3d residual = bFree - row(x, node);
        const Eigen::Vector3d preconditioned = inverseDiagonal[std::size_t(node)] * residual;
        r.segment<3>(3 * node) = residual;
        z.segment<3>(3 * node) = preconditioned;
        bb += bFree.squaredNorm();
        rr += residual.squaredNorm();
        rz += residual.dot(preconditioned);
    }
    if (multigrid)
    {
        multigrid->apply(a, r, z);
        rz = r.dot(z);
    }
    // Relative to |S b|; when only prescribed values drive the free ones (b = 0 there), to the first residual.
    const double reference = bb > 0.0 ? std::sqrt(bb) : std::sqrt(rr);
    if (reference == 0.0)
    {
        result.converged = true;
        return result;
    }
    double residual = std::sqrt(rr) / reference, beta = 0.0;
    // Two fused sweeps per iteration. The new direction p = z + beta p is formed inside the mat-vec sweep, with
    // q = S A p = S A z + beta q (no separate pass over p, and one barrier less); then x, r and z with r.z, r.r.
    // The CUDA backend runs the same two sweeps.
    while (residual > tolerance && result.iterations < maxIterations)
    {
        double pq = 0.0;
#pragma omp parallel for reduction(+ : pq) schedule(static)
        for (std::ptrdiff_t node = 0; node < std::ptrdiff_t(nodes); ++node)
        {
            const Eigen::Vector3d pNode = z.segment<3>(3 * node) + beta * p.segment<3>(3 * node);
            const Eigen::Vector3d qNode = row(z, node) + beta * q.segment<3>(3 * node);
            p.segment<3>(3 * node) = pNode;
            q.segment<3>(3 * node) = qNode;
            pq += pNode.dot(qNode);
        }
        if (!(pq > 0.0))
            break; // not positive definite along p (or NaN): the caller's guard reports it
        const double alpha = rz / pq;
        double rzNext = 0.0;
        rr = 0.0;
#pragma omp parallel for reduction(+ : rzNext, rr) schedule(static)
        for (std::ptrdiff_t node = 0; node < std::ptrdiff_t(nodes); ++node)
        {
            x.segment<3>(3 * node) += alpha * p.segment<3>(3 * node);
            const Eigen::Vector3d rNode = r.segment<3>(3 * node) - alpha * q.segment<3>(3 * node);
            const Eigen::Vector3d zNode = inverseDiagonal[std::size_t(node)] * rNode;
            r.segment<3>(3 * node) = rNode;
            z.segment<3>(3 * node) = zNode;
            rzNext += rNode.dot(zNode);
            rr += rNode.squaredNorm();
        }
        // The V-cycle only where another iteration follows (the CUDA backend's guard skips it the same way).
        if (multigrid && std::sqrt(rr) / reference > tolerance && result.iterations + 1 < maxIterations)
        {
            multigrid->apply(a, r, z);
            rzNext = r.dot(z);
        }
        beta = rzNext / rz;
        rz = rzNext;
        residual = std::sqrt(rr) / reference;
        ++result.iterations;
    }
    result.relativeResidual = residual;
    result.converged = residual <= tolerance;
    return result;
}

} // namespace vsim::sim::fem
