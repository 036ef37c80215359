#include "vsim/sim/fem/Gmres.h"

#include "vsim/core/Error.h"

#include <Eigen/Dense>

#include <cmath>

namespace vsim::sim::fem {

GmresResult solveGmres(const BlockSparseMatrix& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                       const std::vector<std::uint8_t>& constrained, const Preconditioner& preconditioner,
                       double tolerance, int maxIterations, int restart)
{
    const Eigen::Index n = Eigen::Index(3 * a.nodeCount());
    if (b.size() != n || (!constrained.empty() && constrained.size() != std::size_t(n)) || restart < 1)
        throw Error("GMRES: the matrix, right-hand side and constraints differ in size");
    Eigen::VectorXd free = Eigen::VectorXd::Ones(n);
    for (std::size_t i = 0; i < constrained.size(); ++i)
        if (constrained[i])
            free[Eigen::Index(i)] = 0.0;
    const auto product = [&](const Eigen::VectorXd& v, Eigen::VectorXd& out) {
        a.multiply(v, out);
        out.array() *= free.array();
    };
    GmresResult result;
    x = Eigen::VectorXd::Zero(n);
    const Eigen::VectorXd rhs = b.cwiseProduct(free);
    const double reference = rhs.norm();
    if (reference == 0.0)
    {
        result.converged = true;
        return result;
    }
    Eigen::VectorXd residual = rhs, w;
    // The Krylov basis V and its preconditioned vectors Z = M^-1 V (kept: x += Z y then needs no further
    // application of M^-1, which is a sparse triangular solve pair here).
    std::vector<Eigen::VectorXd> basis(std::size_t(restart) + 1);
    std::vector<Eigen::VectorXd> preconditioned(static_cast<std::size_t>(restart));
    Eigen::MatrixXd h = Eigen::MatrixXd::Zero(restart + 1, restart);
    Eigen::VectorXd cs(restart), sn(restart), g(restart + 1);
    double beta = reference;
    while (beta > tolerance * reference && result.iterations < maxIterations)
    {
        basis[0] = residual / beta;
        g.setZero();
        g[0] = beta;
        int k = 0;
        for (; k < restart && result.iterations < maxIterations; ++k)
        {
            Eigen::VectorXd& z = preconditioned[std::size_t(k)];
            preconditioner(basis[std::size_t(k)], z);
            z.array() *= free.array();
            product(z, w);
            ++result.iterations;
            // Modified Gram-Schmidt, then Givens rotations keep the Hessenberg matrix triangular.
            for (int j = 0; j <= k; ++j)
            {
                h(j, k) = w.dot(basis[std::size_t(j)]);
                w -= h(j, k) * basis[std::size_t(j)];
            }
            h(k + 1, k) = w.norm();
            if (h(k + 1, k) > 0.0)
                basis[std::size_t(k) + 1] = w / h(k + 1, k);
            for (int j = 0; j < k; ++j)
            {
                const double upper = cs[j] * h(j, k) + sn[j] * h(j + 1, k);
                h(j + 1, k) = -sn[j] * h(j, k) + cs[j] * h(j + 1, k);
                h(j, k) = upper;
            }
            const double radius = std::hypot(h(k, k), h(k + 1, k));
            cs[k] = h(k, k) / radius;
            sn[k] = h(k + 1, k) / radius;
            h(k, k) = radius;
            h(k + 1, k) = 0.0;
            g[k + 1] = -sn[k] * g[k];
            g[k] = cs[k] * g[k];
            if (std::abs(g[k + 1]) <= tolerance * reference || !(radius > 0.0))
            {
                ++k;
                break;
            }
        }
        // x += Z y with H y = g (upper triangular).
        const Eigen::VectorXd y = h.topLeftCorner(k, k).triangularView<Eigen::Upper>().solve(g.head(k));
        for (int j = 0; j < k; ++j)
            x += y[j] * preconditioned[std::size_t(j)];
        product(x, w);
        residual = rhs - w;
        const double next = residual.norm();
        if (!(next < beta) && !(next <= tolerance * reference))
        {
            beta = next;
            break; // no progress in a whole cycle (or NaN): stop with what we have
        }
        beta = next;
    }
    result.relativeResidual = beta / reference;
    result.converged = result.relativeResidual <= tolerance;
    return result;
}

} // namespace vsim::sim::fem
