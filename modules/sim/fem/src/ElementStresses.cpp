#include "vsim/sim/fem/ElementStresses.h"

#include <Eigen/Eigenvalues>

#include <cmath>

namespace vsim::sim::fem {

double vonMisesOf(const Eigen::Matrix3d& s)
{
    return std::sqrt(0.5 * ((s(0, 0) - s(1, 1)) * (s(0, 0) - s(1, 1)) + (s(1, 1) - s(2, 2)) * (s(1, 1) - s(2, 2)) +
                            (s(2, 2) - s(0, 0)) * (s(2, 2) - s(0, 0))) +
                     3.0 * (s(0, 1) * s(0, 1) + s(1, 2) * s(1, 2) + s(2, 0) * s(2, 0)));
}

ElementStresses elementStressesFrom(std::vector<Eigen::Matrix3d> tensors)
{
    ElementStresses out;
    out.vonMises.resize(tensors.size());
    out.maxPrincipal.resize(tensors.size());
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t t = 0; t < std::ptrdiff_t(tensors.size()); ++t)
    {
        const std::size_t e = std::size_t(t);
        out.vonMises[e] = vonMisesOf(tensors[e]);
        out.maxPrincipal[e] =
            Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(tensors[e], Eigen::EigenvaluesOnly).eigenvalues()[2];
    }
    out.tensors = std::move(tensors);
    return out;
}

} // namespace vsim::sim::fem
