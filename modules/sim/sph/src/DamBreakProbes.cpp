#include "vsim/sim/sph/DamBreakProbes.h"

#include "vsim/core/Error.h"

#include <algorithm>
#include <cmath>

namespace vsim::sim::sph {

double waterHeightM(const ParticleState& particles, const QuarticKernel& kernel, double spacingM, double xM,
                    double yM)
{
    // The particles within the support of the vertical line.
    const double reach = kernel.support();
    std::vector<std::size_t> near;
    double top = 0.0;
    for (std::size_t i = 0; i < particles.size(); ++i)
    {
        const Eigen::Vector3d& p = particles.position[i];
        if (std::hypot(p.x() - xM, p.y() - yM) < reach && !particles.boundary[i])
            near.push_back(i), top = std::max(top, p.z());
    }
    const auto fraction = [&](double z) {
        const Eigen::Vector3d at(xM, yM, z);
        double sum = 0.0;
        for (std::size_t i : near)
            sum += particles.mass[i] / particles.density[i] * kernel.value((at - particles.position[i]).norm());
        return sum;
    };
    const double dz = 0.25 * spacingM;
    double below = fraction(0.0);
    if (below < 0.5)
        return 0.0;
    for (double z = dz; z <= top + reach; z += dz)
    {
        const double here = fraction(z);
        if (here < 0.5)
            return z - dz * (0.5 - here) / (below - here);
        below = here;
    }
    return top + reach;
}

std::array<double, 4> DamBreakExperiment::at(double timeS) const
{
    if (heightsM.empty() || timeS < 0.0 || timeS > lastTimeS() + 1e-12)
        throw Error("the dam break experiment's record does not cover that time");
    const double position = timeS / intervalS;
    const std::size_t k = std::min(std::size_t(position), heightsM.size() - 2);
    const double w = position - double(k);
    std::array<double, 4> h{};
    for (int p = 0; p < 4; ++p)
        h[std::size_t(p)] = (1.0 - w) * heightsM[k][std::size_t(p)] + w * heightsM[k + 1][std::size_t(p)];
    return h;
}

} // namespace vsim::sim::sph
