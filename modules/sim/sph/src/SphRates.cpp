#include "vsim/sim/sph/SphRates.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>

namespace vsim::sim::sph
{

std::vector<double> pressures(const ParticleState& particles, const FluidModel& fluid)
{
    std::vector<double> p(particles.size());
    for (std::size_t i = 0; i < p.size(); ++i)
        p[i] = fluid.pressure(particles.density[i]);
    return p;
}

namespace
{

/// G_i of every fluid particle (the delta-SPH term's correction; see SphRates.h).
void renormalisedDensityGradients(const ParticleState& particles, const NeighbourGrid& grid,
                                  const QuarticKernel& kernel, std::vector<Eigen::Vector3d>& gradients)
{
    const int n = int(particles.size());
    gradients.assign(std::size_t(n), Eigen::Vector3d::Zero());
#pragma omp parallel for schedule(dynamic, 256)
    for (int i = 0; i < n; ++i)
    {
        const std::size_t si = std::size_t(i);
        if (particles.wall[si])
            continue;
        Eigen::Matrix3d moment = Eigen::Matrix3d::Zero();
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        grid.forEachNeighbour(particles.position, i,
                              [&](int j, const Eigen::Vector3d& rij, double)
                              {
                                  const std::size_t sj = std::size_t(j);
                                  if (particles.wall[sj])
                                      return;
                                  const Eigen::Vector3d gradW = kernel.gradient(rij);
                                  const double volume = particles.mass[sj] / particles.density[sj];
                                  moment.noalias() -=
                                      volume * rij * gradW.transpose(); // (x_j - x_i) (x) grad_i W_ij
                                  sum += volume * (particles.density[sj] - particles.density[si]) * gradW;
                              });
        const Eigen::Matrix3d transposed = moment.transpose();
        // A particle with too few fluid neighbours around it (a droplet, a jet's tip) keeps G = 0: plain
        // Molteni.
        if (std::abs(transposed.determinant()) > 1e-3)
            gradients[si] = transposed.inverse() * sum;
    }
}

} // namespace

void computeRates(const ParticleState& particles, const std::vector<double>& pressure,
                  const NeighbourGrid& grid, const QuarticKernel& kernel, const FluidModel& fluid,
                  SphRates& rates)
{
    const int n = int(particles.size());
    if (fluid.densityDiffusion > 0.0)
        renormalisedDensityGradients(particles, grid, kernel, rates.densityGradient);
    else
        rates.densityGradient.assign(std::size_t(n), Eigen::Vector3d::Zero());
    rates.acceleration.assign(std::size_t(n), Eigen::Vector3d::Zero());
    rates.densityRate.assign(std::size_t(n), 0.0);
    const double h = kernel.smoothingLength(), eta2 = 0.01 * h * h;
    const double diffusion = fluid.densityDiffusion * h * fluid.soundSpeed;
    const double mu = fluid.viscosity;
    double largestAcceleration = 0.0, largestViscousRate = 0.0;
#pragma omp parallel for schedule(dynamic, 256) reduction(max : largestAcceleration, largestViscousRate)
    for (int i = 0; i < n; ++i)
    {
        const std::size_t si = std::size_t(i);
        const bool wallI = particles.wall[si] != 0;
        const Eigen::Vector3d& vi = particles.velocity[si];
        const double rhoI = particles.density[si], pI = pressure[si];
        double densityRate = 0.0;
        Eigen::Vector3d force = Eigen::Vector3d::Zero();
        grid.forEachNeighbour(
            particles.position, i,
            [&](int j, const Eigen::Vector3d& rij, double r)
            {
                const std::size_t sj = std::size_t(j);
                const bool wallJ = particles.wall[sj] != 0;
                if (wallI && wallJ)
                    return; // frozen walls do not act on each other
                const Eigen::Vector3d gradW = kernel.gradient(rij);
                const Eigen::Vector3d vij = vi - particles.velocity[sj];
                const double mJ = particles.mass[sj], rhoJ = particles.density[sj];
                densityRate += mJ * vij.dot(gradW);
                if (!wallI && !wallJ && diffusion > 0.0)
                {
                    const Eigen::Vector3d psi = 2.0 * (rhoJ - rhoI) / (r * r) * (-rij) -
                                                (rates.densityGradient[si] + rates.densityGradient[sj]);
                    densityRate += diffusion * (mJ / rhoJ) * psi.dot(gradW);
                }
                const double rDotGrad = rij.dot(gradW);
                if (!wallI)
                {
                    force -= mJ * (pI / (rhoI * rhoI) + pressure[sj] / (rhoJ * rhoJ)) * gradW;
                    force += mJ * 2.0 * mu * rDotGrad / (rhoI * rhoJ * (r * r + eta2)) * vij;
                }
                largestViscousRate =
                    std::max(largestViscousRate, std::abs(h * vij.dot(rij) / (r * r + eta2)));
            });
        rates.densityRate[si] = densityRate;
        if (!wallI)
        {
            rates.acceleration[si] = force + fluid.gravity;
            largestAcceleration = std::max(largestAcceleration, rates.acceleration[si].norm());
        }
    }
    rates.largestAcceleration = largestAcceleration;
    rates.largestViscousRate = largestViscousRate;
}

double stableTimeStep(const SphRates& rates, const QuarticKernel& kernel, const FluidModel& fluid, double cfl)
{
    const double h = kernel.smoothingLength();
    double step = h / (fluid.soundSpeed + rates.largestViscousRate);
    if (rates.largestAcceleration > 0.0)
        step = std::min(step, std::sqrt(h / rates.largestAcceleration));
    step *= cfl;
    if (fluid.viscosity > 0.0)
        step = std::min(step, 0.125 * h * h * fluid.restDensity / fluid.viscosity);
    return step;
}

} // namespace vsim::sim::sph
