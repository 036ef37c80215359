#pragma once

// A vessel segment as a conical pipe with a linearly varying radius (thesis ch. 6.2). SI units: radii and lengths
// in m, viscosity in Pa s, resistance in Pa s / m^3 (pressure drop per volume flow).

namespace vsim::sim::network {

/// Conical Hagen-Poiseuille (eq. 6.6 with mdot / rho_h = Q): dP / Q = 8 mu L / pi * (1/3) (1 / (R1 R2^3) +
/// 1 / (R1^2 R2^2) + 1 / (R1^3 R2)), the exact integral of eq. 6.4 over the cone; 8 mu L / (pi R^4) when R1 = R2.
double conicalResistance(double startRadius, double endRadius, double length, double viscosity);

/// Eq. 6.4 integrated numerically (composite Gauss-Legendre, `panels` panels of 8 points): the check of the
/// closed form.
double integratedResistance(double startRadius, double endRadius, double length, double viscosity, int panels);

/// Volume (m^3) of the first `x` metres of the cone (from the start radius's end).
double conicalVolume(double startRadius, double endRadius, double length, double x);

/// The distance x (m) from the start at which conicalVolume(x) = `volume` (clamped to [0, length]): where a front
/// that has filled `volume` stands (Newton on the cubic, monotonic since the cross-section is positive).
double filledLength(double startRadius, double endRadius, double length, double volume);

} // namespace vsim::sim::network
