#include "vsim/sim/sph/SphRates.h"

#include "vsim/sim/sph/FiniteParticleMethod.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>

namespace vsim::sim::sph {

std::vector<double> pressures(const ParticleState& particles, const FluidModel& fluid)
{
    std::vector<double> p(particles.size());
    for (std::size_t i = 0; i < p.size(); ++i)
        p[i] = fluid.pressure(particles.density[i], particles.voidFraction[i]);
    return p;
}

namespace {

// The cap on the no-slip extrapolation's beta. Morris et al. 1997 capped it at 1.5 with h about one spacing; with
// h = 2 spacings the wall's four layers lie up to 3.5 spacings deep, and a cap of 1.5 left the no-slip plane
// 0.3 spacings too deep (sph-poiseuille's peak 6 % high): 10 lets every layer take its part.
constexpr double kMorrisBetaMax = 10.0;

/// rho / rho0(s): what the delta-SPH term diffuses, so that neighbours of different void fractions at the same
/// pressure exchange nothing (for pure blood, rho / rho0).
double relativeDensity(const ParticleState& particles, const FluidModel& fluid, std::size_t i)
{
    return particles.density[i] / fluid.mixtureDensity(particles.voidFraction[i]);
}
// eta^2 / h^2 in the viscous term's 1 / (r^2 + eta^2): it only keeps r -> 0 finite. The usual 0.01 lowers the
// Laplacian's normalisation on a lattice at h = 2 spacings to 0.9917 (the viscosity 0.8 % low); 0.001 gives 1.0002.
constexpr double kEtaSquared = 0.001;

/// The velocity difference the viscous term takes between i and neighbour j: at a wall particle of known depth the
/// no-slip one, j moving opposite to i scaled by how much deeper it lies than i stands off the surface (Morris et al.
/// 1997), v_ij = beta v_i; else v_i - v_j.
Eigen::Vector3d viscousVelocityDifference(const ParticleState& particles, std::size_t i, std::size_t j,
                                          double wallDistance, double h)
{
    const double depth = particles.wall[j] ? particles.wallDepth[j] : -1.0;
    if (depth >= 0.0)
        return std::min(kMorrisBetaMax, 1.0 + depth / std::max(wallDistance, 1e-3 * h)) * particles.velocity[i];
    return particles.velocity[i] - particles.velocity[j];
}

/// Morris et al. 1997's viscous acceleration of i by j (Lo & Shao 2002 form), rDotGrad = x_ij . grad_i W_ij.
Eigen::Vector3d viscousAcceleration(const ParticleState& particles, const FluidModel& fluid, std::size_t i,
                                    std::size_t j, double rDotGrad, double r, double eta2, const Eigen::Vector3d& vij)
{
    const double muI = fluid.mixtureViscosity(particles.voidFraction[i]);
    const double muJ = fluid.mixtureViscosity(particles.voidFraction[j]);
    return particles.mass[j] * (muI + muJ) * rDotGrad /
           (particles.density[i] * particles.density[j] * (r * r + eta2)) * vij;
}

/// What the main pass needs from a fluid particle's neighbourhood first: G_i (the delta-SPH term's correction,
/// when it is on), the distance to the nearest wall surface, min over wall neighbours of |x_ij| - depth_j
/// (infinite when none has a known depth), and with the Finite Particle Method tr(grad v_i). See SphRates.h.
void fluidNeighbourhood(const ParticleState& particles, const NeighbourGrid& grid, const QuarticKernel& kernel,
                        const FluidModel& fluid, bool densityGradients, SphRates& rates)
{
    const int n = int(particles.size());
    const bool fpm = fluid.finiteParticleMethod;
    rates.densityGradient.assign(std::size_t(n), Eigen::Vector3d::Zero());
    rates.wallDistance.assign(std::size_t(n), INFINITY);
    rates.guardedWallDistance.assign(std::size_t(n), INFINITY);
    rates.velocityDivergence.assign(fpm ? std::size_t(n) : 0u, NAN);
#pragma omp parallel for schedule(dynamic, 256)
    for (int i = 0; i < n; ++i)
    {
        const std::size_t si = std::size_t(i);
        if (!particles.isFluid(si))
            continue;
        Eigen::Matrix3d moment = Eigen::Matrix3d::Zero();
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        double wallDistance = INFINITY, guardedWallDistance = INFINITY;
        const double relativeI = relativeDensity(particles, fluid, si);
        // With FPM: i itself first (rij = 0), then each neighbour.
        FpmFields<3> velocity;
        FpmFields<1> density;
        if (fpm)
        {
            const double volumeI = particles.mass[si] / particles.density[si], w0 = kernel.value(0.0);
            velocity.add(Eigen::Vector3d::Zero(), w0, Eigen::Vector3d::Zero(), volumeI, particles.velocity[si]);
            density.add(Eigen::Vector3d::Zero(), w0, Eigen::Vector3d::Zero(), volumeI,
                        FpmFields<1>::Values(relativeI));
        }
        grid.forEachNeighbour(particles.position, i, [&](int j, const Eigen::Vector3d& rij, double r) {
            const std::size_t sj = std::size_t(j);
            if (fpm) // the velocity over every neighbour (a wall particle stands still), rho / rho0 over the others
            {
                const double volume = particles.mass[sj] / particles.density[sj], w = kernel.value(r);
                const Eigen::Vector3d gradW = kernel.gradient(rij, r);
                velocity.add(rij, w, gradW, volume, particles.velocity[sj]);
                if (!particles.wall[sj] && densityGradients)
                    density.add(rij, w, gradW, volume, FpmFields<1>::Values(relativeDensity(particles, fluid, sj)));
            }
            if (particles.wall[sj])
            {
                if (particles.wallDepth[sj] >= 0.0)
                {
                    wallDistance = std::min(wallDistance, r - particles.wallDepth[sj]);
                    if (particles.backstop[sj])
                        guardedWallDistance = std::min(guardedWallDistance, r - particles.guardDepth[sj]);
                }
                return;
            }
            if (!densityGradients || fpm)
                return;
            const Eigen::Vector3d gradW = kernel.gradient(rij, r);
            const double volume = particles.mass[sj] / particles.density[sj];
            moment.noalias() -= volume * rij * gradW.transpose(); // (x_j - x_i) (x) grad_i W_ij
            sum += volume * (relativeDensity(particles, fluid, sj) - relativeI) * gradW;
        });
        rates.wallDistance[si] = wallDistance;
        rates.guardedWallDistance[si] = guardedWallDistance;
        if (fpm)
        {
            if (const auto solved = velocity.solve())
                rates.velocityDivergence[si] = (*solved)(1, 0) + (*solved)(2, 1) + (*solved)(3, 2);
            if (const auto solved = density.solve(); solved && densityGradients)
                rates.densityGradient[si] = solved->col(0).tail<3>();
            continue;
        }
        const Eigen::Matrix3d transposed = moment.transpose();
        // A particle with too few fluid neighbours around it (a droplet, a jet's tip) keeps G = 0: plain Molteni.
        if (densityGradients && std::abs(transposed.determinant()) > 1e-3)
            rates.densityGradient[si] = transposed.inverse() * sum;
    }
}

} // namespace

void summationDensity(ParticleState& particles, const NeighbourGrid& grid, const QuarticKernel& kernel,
                      const FluidModel& fluid)
{
    const int n = int(particles.size());
    const double self = kernel.value(0.0);
#pragma omp parallel for schedule(dynamic, 256)
    for (int i = 0; i < n; ++i)
    {
        const std::size_t si = std::size_t(i);
        if (!particles.isFluid(si))
            continue;
        double sum = self;
        grid.forEachNeighbour(particles.position, i,
                              [&](int, const Eigen::Vector3d&, double r) { sum += kernel.value(r); });
        particles.density[si] = fluid.summationScale * particles.mass[si] * sum;
    }
}

void computeRates(const ParticleState& particles, const std::vector<double>& pressure, const NeighbourGrid& grid,
                  const QuarticKernel& kernel, const FluidModel& fluid, double timeS, SphRates& rates)
{
    const int n = int(particles.size());
    const bool wallDepths = std::any_of(particles.wallDepth.begin(), particles.wallDepth.end(), [](double d) { return d >= 0.0; });
    if (fluid.densityDiffusion > 0.0 || wallDepths || fluid.finiteParticleMethod)
        fluidNeighbourhood(particles, grid, kernel, fluid, fluid.densityDiffusion > 0.0, rates);
    else
    {
        rates.densityGradient.assign(std::size_t(n), Eigen::Vector3d::Zero());
        rates.wallDistance.assign(std::size_t(n), INFINITY);
        rates.guardedWallDistance.assign(std::size_t(n), INFINITY);
        rates.velocityDivergence.clear();
    }
    rates.acceleration.assign(std::size_t(n), Eigen::Vector3d::Zero());
    rates.densityRate.assign(std::size_t(n), 0.0);
    const bool shifting = fluid.particleShifting > 0.0;
    const bool relaxing = fluid.densityRelaxationS > 0.0 && !fluid.densitySummation;
    rates.shiftVelocity.assign(shifting ? std::size_t(n) : 0u, Eigen::Vector3d::Zero());
    const double h = kernel.smoothingLength(), eta2 = kEtaSquared * h * h;
    const double diffusion = fluid.densityDiffusion * h * fluid.soundSpeed;
    double largestAcceleration = 0.0, largestViscousRate = 0.0, largestKinematicViscosity = 0.0;
    const Eigen::Vector3d external = fluid.externalAcceleration(timeS);
#pragma omp parallel for schedule(dynamic, 256) reduction(max : largestAcceleration, largestViscousRate, largestKinematicViscosity)
    for (int i = 0; i < n; ++i)
    {
        const std::size_t si = std::size_t(i);
        if (particles.boundary[si] || particles.wall[si])
            continue; // a buffer particle's values are imposed (OpenBoundary.h); walls get no rates (their pressure:
                      // extrapolateWallPressure), and a wall-fluid pair's viscous rate is the fluid one's (as on the GPU)
        const Eigen::Vector3d& vi = particles.velocity[si];
        const double rhoI = particles.density[si], pI = pressure[si];
        const double restI = fluid.mixtureDensity(particles.voidFraction[si]), relativeI = rhoI / restI;
        const double muI = fluid.mixtureViscosity(particles.voidFraction[si]);
        auto relativeJ = [&](std::size_t sj) { return relativeDensity(particles, fluid, sj); };
        double continuity = 0.0, diffusionRate = 0.0;
        double weights = kernel.value(0.0); // sum_j W_ij, i included (the relaxation towards summation)
        Eigen::Vector3d force = Eigen::Vector3d::Zero(), crowding = Eigen::Vector3d::Zero();
        Eigen::Matrix3d velocityGradient = Eigen::Matrix3d::Zero(); // d v_k / d x_l (the shift's correction)
        grid.forEachNeighbour(
            particles.position, i,
            [&](int j, const Eigen::Vector3d& rij, double r)
            {
                const std::size_t sj = std::size_t(j);
                const Eigen::Vector3d gradW = kernel.gradient(rij, r);
                const Eigen::Vector3d vij = vi - particles.velocity[sj];
                const double mJ = particles.mass[sj], rhoJ = particles.density[sj];
                continuity += rhoI * (mJ / rhoJ) * vij.dot(gradW); // volume form: mixtures of other rest densities
                if (particles.isFluid(sj) && diffusion > 0.0)
                {
                    const Eigen::Vector3d psi = 2.0 * (relativeJ(sj) - relativeI) / (r * r) * (-rij) -
                                                (rates.densityGradient[si] + rates.densityGradient[sj]);
                    diffusionRate += diffusion * restI * (mJ / rhoJ) * psi.dot(gradW);
                }
                const double rDotGrad = rij.dot(gradW);
                if (relaxing)
                    weights += kernel.value(r);
                force -= mJ * (pI / (rhoI * rhoI) + pressure[sj] / (rhoJ * rhoJ)) * gradW;
                force += viscousAcceleration(particles, fluid, si, sj, rDotGrad, r, eta2,
                                             viscousVelocityDifference(particles, si, sj, rates.wallDistance[si], h));
                if (particles.backstop[sj])
                    force += fluid.wallRepulsionFactor(r) * rij;
                if (shifting) // grad C_i with the anti-clumping term (SphRates.h)
                {
                    const double ratio = kernel.value(r) * fluid.shiftingReciprocalWeight;
                    const double ratio2 = ratio * ratio;
                    crowding += (mJ / rhoJ) * (1.0 + FluidModel::kAntiClumping * ratio2 * ratio2) * gradW;
                    if (fluid.shiftCorrection)
                        velocityGradient -= (mJ / rhoJ) * vij * gradW.transpose();
                }
                largestViscousRate =
                    std::max(largestViscousRate, std::abs(h * vij.dot(rij) / (r * r + eta2)));
            });
        // With FPM the continuity equation's divergence is the FPM one where its system was regular (SphRates.h).
        const bool fpmDivergence = !rates.velocityDivergence.empty() && std::isfinite(rates.velocityDivergence[si]);
        if (!fluid.densitySummation)
            rates.densityRate[si] =
                (fpmDivergence ? -rhoI * rates.velocityDivergence[si] : continuity) + diffusionRate;
        if (relaxing)
            rates.densityRate[si] +=
                (fluid.summationScale * particles.mass[si] * weights - rhoI) / fluid.densityRelaxationS;
        rates.acceleration[si] = force + external;
        if (shifting)
        {
            rates.shiftVelocity[si] =
                -fluid.particleShifting * h * std::max(vi.norm(), fluid.shiftingSpeedMS) * crowding;
            if (fluid.shiftCorrection)
                rates.acceleration[si] += velocityGradient * rates.shiftVelocity[si];
        }
        largestKinematicViscosity = std::max(largestKinematicViscosity, muI / restI);
        largestAcceleration = std::max(largestAcceleration, rates.acceleration[si].norm());
    }
    rates.largestAcceleration = largestAcceleration;
    rates.largestViscousRate = largestViscousRate;
    rates.largestKinematicViscosity = largestKinematicViscosity;
}

void extrapolateWallPressure(ParticleState& particles, const NeighbourGrid& grid, const QuarticKernel& kernel,
                             const FluidModel& fluid, bool freeSurface)
{
    const double floorPa = freeSurface ? 0.0 : -INFINITY;
    const int n = int(particles.size());
    // Gravity only: a driving body force (the validation channels' stand-in for a pressure gradient) is balanced by
    // the fluid's viscosity, not by a pressure gradient, so the walls must not extrapolate one from it (with it the
    // Womersley pipe at alpha 8 blew up: the walls' pressure swung along the axis with the force).
    const Eigen::Vector3d& external = fluid.gravity;
#pragma omp parallel for schedule(dynamic, 256)
    for (int i = 0; i < n; ++i)
    {
        const std::size_t si = std::size_t(i);
        if (!particles.wall[si])
            continue;
        double weight = 0.0, pressure = 0.0;
        grid.forEachNeighbour(particles.position, i,
                              [&](int j, const Eigen::Vector3d& rij, double r)
                              {
                                  const std::size_t sj = std::size_t(j);
                                  if (particles.wall[sj])
                                      return;
                                  const double w = kernel.interpolationWeight(r);
                                  weight += w;
                                  pressure += w * (fluid.pressure(particles.density[sj], particles.voidFraction[sj]) +
                                                   particles.density[sj] * external.dot(rij));
                              });
        if (weight > 0.0) // a wall particle beyond the fluid's reach keeps its density
            particles.density[si] = fluid.densityAt(std::max(floorPa, pressure / weight), particles.voidFraction[si]);
    }
}

double stableTimeStep(const SphRates& rates, const QuarticKernel& kernel, const FluidModel& fluid, double cfl)
{
    const double h = kernel.smoothingLength();
    double step = h / (fluid.soundSpeed + rates.largestViscousRate);
    if (rates.largestAcceleration > 0.0)
        step = std::min(step, std::sqrt(h / rates.largestAcceleration));
    step *= cfl;
    if (rates.largestKinematicViscosity > 0.0) // the viscous limit at the particles' largest mu(s) / rho0(s)
        step = std::min(step, 0.125 * h * h / rates.largestKinematicViscosity);
    return step;
}

Eigen::Vector3d wallFrictionAcceleration(const ParticleState& particles, const NeighbourGrid& grid,
                                         const QuarticKernel& kernel, const FluidModel& fluid, std::size_t i)
{
    const double h = kernel.smoothingLength(), eta2 = kEtaSquared * h * h;
    double wallDistance = INFINITY; // as fluidNeighbourhood: min over wall neighbours of |x_ij| - depth_j
    grid.forEachNeighbour(particles.position, int(i), [&](int j, const Eigen::Vector3d&, double r) {
        if (particles.wall[std::size_t(j)] && particles.wallDepth[std::size_t(j)] >= 0.0)
            wallDistance = std::min(wallDistance, r - particles.wallDepth[std::size_t(j)]);
    });
    Eigen::Vector3d friction = Eigen::Vector3d::Zero();
    grid.forEachNeighbour(particles.position, int(i), [&](int j, const Eigen::Vector3d& rij, double r) {
        const std::size_t sj = std::size_t(j);
        if (!particles.wall[sj])
            return;
        friction += viscousAcceleration(particles, fluid, i, sj, rij.dot(kernel.gradient(rij, r)), r, eta2,
                                        viscousVelocityDifference(particles, i, sj, wallDistance, h));
    });
    return friction;
}

} // namespace vsim::sim::sph
