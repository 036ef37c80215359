#include "vsim/sim/sph/FiniteParticleMethod.h"

namespace vsim::sim::sph {

void FpmSystem::add(const Eigen::Vector3d& rij, double volumeM3, double value)
{
    const double r = rij.norm();
    m_fields.add(rij, m_kernel.value(r), m_kernel.gradient(rij, r), volumeM3, FpmFields<1>::Values(value));
}

std::optional<CorrectedField> FpmSystem::solve() const
{
    const auto solution = m_fields.solve();
    if (!solution)
        return std::nullopt;
    return CorrectedField{(*solution)(0, 0), solution->col(0).tail<3>()};
}

} // namespace vsim::sim::sph
