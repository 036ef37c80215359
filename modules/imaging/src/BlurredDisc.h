#pragma once

// The occupancy of a straight tube's cross-section under a Gaussian blur: the exact convolution of a disc of radius r
// with an isotropic 2D Gaussian of standard deviation sigma, at a point rho from the disc's centre. It is the
// cumulative distribution of the Rice distribution (nu = rho, scale sigma) at r, 1 - Q1(rho / sigma, r / sigma) with
// Marcum's Q function (Rice, Bell Syst. Tech. J. 23, 1944; Marcum, IRE Trans. Inf. Theory 6, 1960). Unlike the edge
// profile Phi((r - rho) / sigma) it keeps the disc's area (its integral over the plane is pi r^2 for any blur) and its
// half level lies about sigma^2 / (2 r) inside the radius: what a scanner does to a thin vessel.

namespace vsim::imaging::detail {

/// Fraction (0..1) of the blurred disc at distance rhoMm (>= 0) from its centre; radiusMm >= 0, sigmaMm > 0. Tabulated
/// in (r / sigma, rho / sigma) up to r = 30 sigma (4e-4 absolute at most between the table's nodes); wider tubes take
/// the plane edge Phi((r - rho) / sigma), whose difference from the disc is then under 1 % of sigma in position.
double blurredDiscOccupancy(double rhoMm, double radiusMm, double sigmaMm);

} // namespace vsim::imaging::detail
