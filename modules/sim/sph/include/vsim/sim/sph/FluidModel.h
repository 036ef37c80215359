#pragma once

// The weakly compressible fluid of the SPH solver (issue 18; thesis ch. 5.3): Tait's equation of state
// p = B ((rho / rho0)^gamma - 1), B = c0^2 rho0 / gamma, gamma = 7, with a numerical sound speed c0 chosen so
// that the density varies by about 1 % (c0 >= 10 times the largest flow speed: Monaghan 1994); Newtonian
// viscosity; gravity. Two-phase flow as the thesis models it (ch. 5.3, Table 5.1): mixture particles that carry
// a void fraction s, with the mixture's rest density rho0(s) = rho_p (1 - s) + rho_g s and viscosity
// mu(s) = mu_p (1 - s) + mu_g s (blood plasma and air), each particle's equation of state about its own rho0(s).
// SI throughout.

#include <Eigen/Core>

#include <algorithm>
#include <cmath>

namespace vsim::sim::sph {

struct FluidModel
{
    double restDensity = 1060.0; ///< rho0 of the liquid (s = 0), kg/m^3 (blood)
    double viscosity = 3.5e-3;   ///< mu of the liquid, Pa s (blood at high shear)
    double gasDensity = 1.205;   ///< rho_g, kg/m^3 (air; thesis Table 5.1)
    double gasViscosity = 1.86e-5; ///< mu_g, Pa s (air; thesis Table 5.1)
    double soundSpeed = 10.0;    ///< c0, m/s (numerical)
    double gamma = 7.0;
    double densityDiffusion = 0.1; ///< delta of the delta-SPH term (Antuono et al. 2010's form, SphRates.h; 0: off)
    /// Particle shifting (SphRates.h): A of the shift's diffusion coefficient A h |v_i| (Skillen et al. 2013; 0: off),
    /// and 1 / W(spacing), the anti-clumping term's reference (Lind et al. 2012), m^3.
    double particleShifting = 0.0;
    double shiftingReciprocalWeight = 0.0;
    /// The shift's speed floor (m/s; 0: none): the coefficient is A h max(|v_i|, this), so that a slow zone (a
    /// stenosis's separation zone, at a tenth of the jet's speed) is shifted too; there, with |v_i| alone, the
    /// particles clumped and left voids. With the flow's largest speed it is the delta+-SPH shift's form (Sun et
    /// al. 2017: CFL Ma (2h)^2 = 4 h U_max dt).
    double shiftingSpeedMS = 0.0;
    /// The shift's convective correction (SphRates.h): the velocity follows the particle to where the shift moves
    /// it, a_i += (s_i . grad) v_i (Lind et al. 2012's Taylor correction, in the rate form).
    bool shiftCorrection = false;
    /// The Finite Particle Method's first-order correction (thesis ch. 5.2, eq. 5.17 "with f = v"; SphRates.h):
    /// the continuity equation's velocity divergence and the delta-SPH term's density gradient from FPM systems
    /// instead of the SPH sums.
    bool finiteParticleMethod = false;
    /// Density by summation instead of the continuity equation (SphRates.h, summationDensity): a fluid particle's
    /// density is m_i sum_j W_ij over every neighbour (itself, fluid, walls, buffers) times summationScale, 1 /
    /// (V0 sum over the seeding lattice), so that the lattice the particles start on reads exactly their rest
    /// density. For a fluid that fills its vessel (SphSolver refuses a free surface or a liquid without tension).
    bool densitySummation = false;
    double summationScale = 1.0;
    /// With the continuity density: the time (s) over which it relaxes towards the summation density, a rate
    /// (rho_sum,i - rho_i) / tau added to drho_i/dt (SphRates.h); 0: off.
    double densityRelaxationS = 0.0;
    /// R of the shift's anti-clumping term R (W_ij / W(spacing))^4 (Lind et al. 2012; Monaghan 2000).
    static constexpr double kAntiClumping = 0.2;
    Eigen::Vector3d gravity = Eigen::Vector3d::Zero(); ///< m/s^2
    /// A driving body force per unit mass (m/s^2: a pressure gradient / rho in a periodic pipe), oscillating as
    /// cos(2 pi f t) when bodyForceFrequency > 0 (Hz).
    Eigen::Vector3d bodyForce = Eigen::Vector3d::Zero();
    double bodyForceFrequency = 0.0;
    /// The pressure the rest density stands for (Pa, gauge: the outlets' level). A uniform pressure does not move an
    /// incompressible flow, and in the equation of state it would compress the fluid (by 21 % at 50 mmHg with c0 =
    /// 4 m/s): pressure() and densityAt() work on the pressure above it, the dynamics with them, and what a run
    /// reports is reportedPressure().
    double referencePressurePa = 0.0;
    /// The walls' backstop (thesis ch. 5.4: ghost particles with a Lennard-Jones-type repulsion; Monaghan
    /// 1994): a wall particle j closer than r0 to a fluid particle i pushes it away with a_i = D ((r0 /
    /// r')^12 - (r0 / r')^4) / r' along x_ij / r, r' = max(r, 0.8 r0). D, m^2/s^2 (0: off); r0, m
    /// (SphSolver.h: 0.9 spacings, short of the lattice's distances, where the fluid starts). The plateau
    /// below 0.8 r0 (15 D / r0) bounds it, so that no particle, however it came near a wall particle, is shot
    /// off (with the unbounded law a particle an open end's buffer had handed over 0.23 spacings from a wall
    /// particle left at 5.7e6 m/s). Only wall particles with `backstop` push (ParticleState.h).
    double wallRepulsion = 0.0;
    double wallRepulsionRange = 0.0;
    /// Whether the fluid holds tension: Tait's pressure below the rest density pulls it together (vessels, tanks;
    /// the default). Without it (SphSolver's fluid_tension 0) a liquid that breaks up separates instead of
    /// stretching: a particle's density is held at or above its rest density (densityFloor(): the continuity
    /// equation of a stretching stream had driven particles at a needle's mouth to 1 % of it and below 0, and one
    /// off at 19 m/s), pressure() is at least 0 and the density guard reads compression only. Under tension the
    /// stream falling from a needle stretched 3 % below the rest density within 9 ms (2026-11-28).
    bool tension = true;
    /// The least density a fluid particle of void fraction s keeps (kg/m^3): 0 under tension, rho0(s) without.
    double densityFloor(double voidFraction) const { return tension ? 0.0 : mixtureDensity(voidFraction); }
    /// The density's signed departure from the rest density, rho / rho0(s) - 1 (> 0 compressed, < 0 stretched).
    double densityDeparture(double density, double voidFraction) const
    {
        return density / mixtureDensity(voidFraction) - 1.0;
    }
    /// The departure the guard reads: |rho / rho0(s) - 1|, or its compression only without tension.
    double densityVariation(double density, double voidFraction) const
    {
        const double change = densityDeparture(density, voidFraction);
        return tension ? std::abs(change) : std::max(change, 0.0);
    }

    /// The backstop's acceleration factor at distance r (m) from a wall particle: a_i = factor x_ij (1/s^2).
    double wallRepulsionFactor(double r) const
    {
        if (!(r < wallRepulsionRange) || !(r > 0.0) || wallRepulsion <= 0.0)
            return 0.0;
        const double plateau = std::max(r, kWallRepulsionPlateau * wallRepulsionRange);
        const double q2 = wallRepulsionRange * wallRepulsionRange / (plateau * plateau), q4 = q2 * q2;
        return wallRepulsion * (q4 * q4 * q4 - q4) / (plateau * r);
    }
    static constexpr double kWallRepulsionPlateau = 0.8; ///< r' / r0 below which the backstop stays constant

    /// Gravity and the body force at time t (s), m/s^2.
    Eigen::Vector3d externalAcceleration(double timeS) const;
    /// The mixture's rest density and viscosity at void fraction s (0 <= s <= 1).
    double mixtureDensity(double voidFraction) const { return restDensity * (1.0 - voidFraction) + gasDensity * voidFraction; }
    double mixtureViscosity(double voidFraction) const { return viscosity * (1.0 - voidFraction) + gasViscosity * voidFraction; }
    /// B = c0^2 rho0(s) / gamma.
    double stiffness(double voidFraction = 0.0) const { return soundSpeed * soundSpeed * mixtureDensity(voidFraction) / gamma; }
    double pressure(double density, double voidFraction = 0.0) const;
    /// The density whose pressure is `pressurePa` (the inverse of pressure()).
    double densityAt(double pressurePa, double voidFraction = 0.0) const;
    /// The gauge pressure a run reports (frames, sections, wall loads, boundaries): the reference plus pressure().
    double reportedPressure(double density, double voidFraction = 0.0) const
    {
        return referencePressurePa + pressure(density, voidFraction);
    }
};

} // namespace vsim::sim::sph
