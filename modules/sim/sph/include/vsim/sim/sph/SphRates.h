#pragma once

// The rates of the weakly compressible SPH equations (issue 18; thesis ch. 5.3) at every particle, each
// summed over its own neighbours (a gather: every particle writes only its own sums, the layout the GPU
// backend shares):
//  continuity (thesis 5.26, in the volume form that mixes particles of other rest densities consistently):
//      drho_i/dt = rho_i sum_j V_j (v_i - v_j) . grad_i W_ij + D_i, with the delta-SPH density diffusion
//      D_i = delta h c0 sum_j V_j psi_ij . grad_i W_ij over fluid neighbours j,
//      psi_ij = 2 (rho_j - rho_i) (x_j - x_i) / |x_ij|^2 - (G_i + G_j) (Antuono et al. 2010; mixture particles
//      diffuse rho / rho0(s) instead, times rho0(s_i): void fractions at one pressure exchange nothing), G the
//      renormalised density gradient G_i = (M_i^T)^-1 sum_j V_j (rho_j - rho_i) grad_i W_ij, M_i = sum_j V_j
//      (x_j - x_i) (x) grad_i W_ij over the fluid: psi vanishes for a linear density (a fluid at rest under
//      gravity is not diffused, also at its free surface, where Molteni & Colagrossi's 2009 term without G
//      makes the pressure drift);
//  momentum:  a_i = -sum_j m_j (p_i / rho_i^2 + p_j / rho_j^2) grad_i W_ij
//                   + sum_j m_j (mu_i + mu_j) (x_ij . grad_i W_ij) / (rho_i rho_j (|x_ij|^2 + 0.001 h^2)) v_ij
//                   + g + f(t) + the walls' backstop from the wall particles with `backstop` (FluidModel.h),
//      the viscous term of Morris et al. 1997 in the form of Lo & Shao 2002. No slip: a wall particle j of
//      known depth d_j below the wall's surface takes the velocity -(d_j / d_i) v_i in i's viscous term, so
//      that v_ij = beta v_i, beta = min(10, 1 + d_j / d_i), d_i i's distance to the surface (Morris et al.
//      1997; d_i = min over wall neighbours of |x_ij| - d_j); without depths the wall particles stand still
//      (the plain dynamic boundary, whose no-slip plane lies about 0.75 spacings too deep: sph-poiseuille's
//      peak 15 % high). Wall particles stand still and get no rates: their pressure is the fluid's around them,
//      extrapolated (extrapolateWallPressure, below). Buffer particles of the open boundaries (OpenBoundary.h) act on the
//      fluid as fluid does, but outside the density diffusion, and get no rates: their values are imposed.
//  particle shifting (an option, FluidModel::particleShifting A > 0): the drift moves a fluid particle by
//      dt (v_i + s_i), s_i = -A h |v_i| grad C_i, grad C_i = sum_j V_j (1 + 0.2 (W_ij / W(spacing))^4) grad_i W_ij
//      over every neighbour (fluid, walls, buffers): Fick's diffusion of the particles' concentration (Lind et al.
//      2012, J Comput Phys 231:1499; the coefficient A h |v_i| dt of Skillen et al. 2013, Comput Methods Appl Mech
//      Eng 265:163), with Monaghan's 2000 anti-clumping term. It keeps a jet's shear layer from ordering particles
//      into streaks and voids (the tensile instability), which had stopped stenotic jets by the density guard.
//      Without the correction (FluidModel::shiftCorrection) the fields are not corrected for the shift: a shifted
//      particle takes its velocity across a shear layer (first order in the shift, A |v| dt ~ A Ma CFL h a step,
//      but it adds up over the steps a particle spends in the layer). With it, the velocity follows the particle to
//      where the shift moves it: a_i += (s_i . grad) v_i, grad v_i = sum_j V_j (v_j - v_i) (x) grad_i W_ij over
//      every neighbour (Lind et al. 2012's Taylor correction v + dr . grad v, as a rate: the shift dr = dt s_i is
//      taken with the velocity over the same step; the arbitrary Lagrangian-Eulerian form of Sun et al. 2017's
//      delta+-SPH). Not at a free surface, whose truncated support would push particles out (SphSolver refuses the
//      two together).
//  the Finite Particle Method (an option, FluidModel::finiteParticleMethod; thesis ch. 5.2: "the change of fluid
//      density can be derived by computing the first-order derivative of velocity using the FPM described in
//      Equation (5.17)"): drho_i/dt = -rho_i tr(grad v_i) + D_i, grad v_i from the FPM system (FiniteParticleMethod.h)
//      over i itself and every neighbour (the walls at rest: v = 0; a buffer particle with its imposed velocity),
//      and G_i the FPM gradient of rho / rho0 over i and its neighbours that are not walls (the sum's set). Both
//      are exact for linear fields whatever the particles' arrangement, also where a free surface or a wall cuts
//      the support, where the SPH sums are not (tst_sph_fpm_rates). Where a system is singular (a particle with too
//      few neighbours), that particle keeps the SPH sum. Not momentum-conserving in the continuity equation (the
//      SPH sum's pairwise antisymmetry is given up), as in the thesis. The CUDA backend's launchFpm runs the same.
//  density by summation (an option, FluidModel::densitySummation): rho_i = m_i sum_j W_ij (Hu & Adams 2006's number
//      density, times the lattice's scale) from the positions alone, and no continuity rate. The continuity density
//      is a particle's own record and drifts from what its neighbours' spacing says wherever the discrete divergence
//      misses how they move apart (a stenotic jet's shear layer, particles shifted, fluid handed over by an open
//      end): the pulsatile stenosis at throat Re 200 read rho0 by continuity where the wake's particles stood at
//      0.5-0.7 of the lattice's number density, no pressure held them, and the pipe lost 30 % of its fluid
//      through the outlet (RESULTS.md, 2026-12-04). Summation cannot drift: fluid that thins out is at a lower
//      pressure and is drawn back. It needs the support filled (walls a support deep, no free surface). Summation
//      reads every particle's disorder at once, though: at the pulsatile stenosis's inlet (Womersley 9 against the
//      buffer's parabola) it swung to 5 % where the continuity density stayed within 2.2 % (RESULTS.md, 2026-12-04).
//  the continuity density relaxed towards summation (an option, FluidModel::densityRelaxationS tau > 0): drho_i/dt
//      gains (rho_sum,i - rho_i) / tau. Over times short against tau the continuity density's smoothness stands (and
//      its delta-SPH term); over longer ones a particle's density follows its neighbours' spacing, so the slow drift
//      above cannot build up: a drift at rate r leaves the two apart by about r tau.

#include "vsim/sim/sph/FluidModel.h"
#include "vsim/sim/sph/NeighbourGrid.h"
#include "vsim/sim/sph/ParticleState.h"
#include "vsim/sim/sph/QuarticKernel.h"

#include <vector>

namespace vsim::sim::sph {

struct SphRates
{
    std::vector<Eigen::Vector3d> acceleration; ///< m/s^2 (zero at wall and buffer particles)
    std::vector<double> densityRate;           ///< kg/(m^3 s) (zero at fluid particles with density by summation)
    /// s_i, m/s (fluid particles with particle shifting on; empty when it is off)
    std::vector<Eigen::Vector3d> shiftVelocity;
    /// G_i, kg/m^4 (fluid particles; zero where M_i is singular).
    std::vector<Eigen::Vector3d> densityGradient;
    /// d_i, m (fluid particles; infinite without a wall neighbour of known depth).
    std::vector<double> wallDistance;
    /// With the Finite Particle Method: tr(grad v_i) by FPM, 1/s (fluid particles; NaN where the system is singular
    /// and the SPH sum stands); empty without it.
    std::vector<double> velocityDivergence;
    /// The same over the wall particles with the backstop (ParticleState::backstop) and against their guard
    /// depths (ParticleState::guardDepth), m: what the through-the-wall guard reads (an open end's buffer hands
    /// fluid over arbitrarily close to the walls around it).
    std::vector<double> guardedWallDistance;
    double largestAcceleration = 0.0; ///< m/s^2, over the fluid
    /// max_ij |h v_ij . x_ij / (r^2 + 0.001 h^2)| over a fluid particle i's neighbours j, m/s (Monaghan's CFL; as
    /// on the GPU: a wall-buffer pair is not a fluid's)
    double largestViscousRate = 0.0;
    double largestKinematicViscosity = 0.0; ///< max over the fluid of mu(s) / rho0(s), m^2/s
};

/// The pressure of every particle from its density (Tait).
std::vector<double> pressures(const ParticleState& particles, const FluidModel& fluid);

/// Density by summation (FluidModel::densitySummation): each fluid particle's density (not the walls', whose
/// density is their extrapolated pressure's, nor the buffers', whose values the open boundaries impose), `grid` built
/// on the particles' positions.
void summationDensity(ParticleState& particles, const NeighbourGrid& grid, const QuarticKernel& kernel,
                      const FluidModel& fluid);

/// Fills `rates` for the particles (`grid` built on their positions) at time `timeS` (s: the body force's phase).
void computeRates(const ParticleState& particles, const std::vector<double>& pressure, const NeighbourGrid& grid,
                  const QuarticKernel& kernel, const FluidModel& fluid, double timeS, SphRates& rates);

/// The viscous acceleration the wall particles alone give fluid particle i (m/s^2): computeRates's viscous term over
/// i's wall neighbours, with the no-slip wall velocity (the backstop left out): the walls' friction on it. `grid`
/// built on the particles' positions (WallShear.h sums it into the wall shear stress).
Eigen::Vector3d wallFrictionAcceleration(const ParticleState& particles, const NeighbourGrid& grid,
                                         const QuarticKernel& kernel, const FluidModel& fluid, std::size_t i);

/// The wall particles' pressure from the fluid around them (Adami, Hu & Adams 2012, J Comput Phys 231:7057, for walls at
/// rest): p_w = sum_f W+_wf (p_f + rho_f g . (x_w - x_f)) / sum_f W+_wf, W+ = max(W, 0) (the quartic kernel's negative
/// lobe near 2h let a deep wall particle's sum of weights vanish: sph-mass blew up), over the fluid and buffer particles f
/// within the support, set as the wall particle's density through the equation of state; a wall particle without
/// fluid around it keeps its density. The dynamic boundary's own continuity (Crespo et al. 2007), which it replaces,
/// lags the fluid's pressure wherever the fluid is compressed as a whole (an inflow's rise): the fluid next to the
/// wall then saw a lower pressure in the wall and was pushed into it. With a free surface (a tank, a dam break) the
/// extrapolation is floored at 0 Pa: walls above the surface would otherwise extrapolate the fluid's hydrostatics
/// into the air as suction (sph-hydrostatic read 2.2 % high with it, 1.7 % without); vessels keep negative gauge
/// pressures (a throat's Bernoulli drop below the outlet's pressure). Gravity only, not the driving body force: that
/// force (the validation channels' stand-in for a pressure gradient) is balanced by the viscosity, not by a pressure
/// gradient, and a wall pressure swinging along the axis with it made the Womersley pipe at alpha 8 blow up.
void extrapolateWallPressure(ParticleState& particles, const NeighbourGrid& grid, const QuarticKernel& kernel,
                             const FluidModel& fluid, bool freeSurface);

/// The explicit step's limit: CFL x min(min_i sqrt(h / |a_i|), h / (c0 + largestViscousRate)), and the
/// viscous limit 0.125 h^2 / nu at the fluid's largest kinematic viscosity (Morris et al. 1997); s.
double stableTimeStep(const SphRates& rates, const QuarticKernel& kernel, const FluidModel& fluid,
                      double cfl);

} // namespace vsim::sim::sph
