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

/// The cone with a catheter of radius `catheterRadius` lying concentric along it: eq. 6.4 with the annulus's
/// Hagen-Poiseuille conductance in place of R^4, pi / (8 mu) (R^4 - a^4 - (R^2 - a^2)^2 / ln(R / a)) (Lamb 1932,
/// art. 331; White, Viscous Fluid Flow, eq. 3-49), integrated as integratedResistance does. Concentric is the
/// most resistive position: a catheter lying against the wall lets up to 2.5 times more through (Piercy et al.
/// 1933). Equals conicalResistance when the catheter radius is 0; infinite when the catheter fills the lumen
/// anywhere along the cone (a wedged catheter: no flow passes it).
double annularResistance(double startRadius, double endRadius, double catheterRadius, double length, double viscosity,
                         int panels = 64);

/// Volume (m^3) of the first `x` metres of the cone (from the start radius's end).
double conicalVolume(double startRadius, double endRadius, double length, double x);

/// The distance x (m) from the start at which conicalVolume(x) = `volume` (clamped to [0, length]): where a front
/// that has filled `volume` stands (Newton on the cubic, monotonic since the cross-section is positive).
double filledLength(double startRadius, double endRadius, double length, double volume);

} // namespace vsim::sim::network
