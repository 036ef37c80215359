#include "vsim/sim/sph/FiniteParticleMethod.h"

#include <cmath>

namespace vsim::sim::sph {

void FpmSystem::add(const Eigen::Vector3d& rij, double volumeM3, double value)
{
    // Test functions: W_ij and the three components of grad_i W_ij; unknowns (f_i, grad f_i); the offset x_j
    // - x_i.
    Eigen::Vector4d test;
    test << m_kernel.value(rij.norm()), m_kernel.gradient(rij);
    Eigen::Vector4d taylor;
    taylor << 1.0, -rij;
    m_moments.noalias() += volumeM3 * test * taylor.transpose();
    m_sums += volumeM3 * value * test;
}

std::optional<CorrectedField> FpmSystem::solve() const
{
    const Eigen::FullPivLU<Eigen::Matrix4d> lu(m_moments);
    // Scale-free singularity test: the smallest pivot against the largest.
    const Eigen::Matrix4d& u = lu.matrixLU();
    double largest = 0.0, smallest = INFINITY;
    for (int k = 0; k < 4; ++k)
        largest = std::max(largest, std::abs(u(k, k))), smallest = std::min(smallest, std::abs(u(k, k)));
    if (!(largest > 0.0) || smallest < 1e-10 * largest)
        return std::nullopt;
    const Eigen::Vector4d x = lu.solve(m_sums);
    return CorrectedField{x[0], x.tail<3>()};
}

} // namespace vsim::sim::sph
