#pragma once

// The body forces of the smoke step (thesis eqs. 7.3 - 7.4, 7.7 - 7.9), as accelerations (m/s^2) on the faces:
// Boussinesq buoyancy of hot, smoke-laden air, and vorticity confinement (Fedkiw, Stam & Jensen 2001), which puts
// back the small swirls the coarse grid's interpolation smooths away.

#include "vsim/sim/smoke/SmokeGrid.h"

#include <Eigen/Core>

#include <vector>

namespace vsim::sim::smoke {

/// Standard gravity (m/s^2) and the ambient air of an operating room (20 degC): the default buoyancy coefficients
/// follow from them (Boussinesq: beta = g / T_ambient, alpha = g / rho_air).
inline constexpr double kGravity = 9.81;
inline constexpr double kAmbientK = 293.15;
inline constexpr double kAirDensity = 1.204; // kg/m^3 at 20 degC, 1 atm

/// u += dt (beta T - alpha rho_smoke) up on the faces between cells that are not solid (T and rho averaged to the
/// face); `up` is the unit vector against gravity in the grid's axes (a supine patient's anterior). alpha in
/// m/s^2 per kg/m^3, beta in m/s^2 per K.
void addBuoyancy(SmokeGrid& grid, double dt, double alpha, double beta,
                 const Eigen::Vector3d& up = Eigen::Vector3d::UnitZ());

/// The vorticity w = curl u at the cell centres (1/s), central differences of the cell velocities (one-sided at
/// the domain's edge); 0 in solid cells.
std::vector<Eigen::Vector3f> cellVorticity(const SmokeGrid& grid);

/// Vorticity confinement: f = epsilon h (N x w) with N = grad|w| / |grad|w|| (eqs. 7.8 - 7.9) at the fluid cells,
/// added to `force` (m/s^2 at the cell centres). epsilon is the dimensionless strength of Fedkiw et al.
void accumulateVorticityConfinement(const SmokeGrid& grid, double epsilon, std::vector<Eigen::Vector3f>& force);

/// u += dt f on the faces from accelerations f (m/s^2) at the cell centres (a face takes the mean of its two cells;
/// faces next to solids or on walls are left to the boundary conditions).
void addCellForces(SmokeGrid& grid, const std::vector<Eigen::Vector3f>& force, double dt);

} // namespace vsim::sim::smoke
