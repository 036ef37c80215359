#pragma once

// The weakly compressible fluid of the SPH solver (issue 18; thesis ch. 5.3): Tait's equation of state
// p = B ((rho / rho0)^gamma - 1), B = c0^2 rho0 / gamma, gamma = 7, with a numerical sound speed c0 chosen so
// that the density varies by about 1 % (c0 >= 10 times the largest flow speed: Monaghan 1994); Newtonian
// viscosity; gravity. SI throughout.

#include <Eigen/Core>

namespace vsim::sim::sph {

struct FluidModel
{
    double restDensity = 1060.0; ///< rho0, kg/m^3 (blood)
    double viscosity = 3.5e-3;   ///< mu, Pa s (blood at high shear)
    double soundSpeed = 10.0;    ///< c0, m/s (numerical)
    double gamma = 7.0;
    double densityDiffusion = 0.1; ///< delta of the delta-SPH term (Molteni & Colagrossi 2009; 0: off)
    Eigen::Vector3d gravity = Eigen::Vector3d::Zero(); ///< m/s^2
    /// A driving body force per unit mass (m/s^2: a pressure gradient / rho in a periodic pipe), oscillating as
    /// cos(2 pi f t) when bodyForceFrequency > 0 (Hz).
    Eigen::Vector3d bodyForce = Eigen::Vector3d::Zero();
    double bodyForceFrequency = 0.0;

    /// Gravity and the body force at time t (s), m/s^2.
    Eigen::Vector3d externalAcceleration(double timeS) const;
    double stiffness() const { return soundSpeed * soundSpeed * restDensity / gamma; }
    double pressure(double density) const;
    /// The density whose pressure is `pressurePa` (the inverse of pressure()).
    double densityAt(double pressurePa) const;
};

} // namespace vsim::sim::sph
