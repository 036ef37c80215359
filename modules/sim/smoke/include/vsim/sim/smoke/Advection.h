#pragma once

// Advection on the MAC grid. The velocity: semi-Lagrangian (Stam 1999), each face value traced back through the
// velocity as it was at the start of the step (second-order Runge-Kutta) and sampled there trilinearly; MacCormack
// (Selle et al. 2008) adds the error estimate of a forward trace for second order, with their limiter (where the
// corrected value leaves the range of the eight values it was sampled from, the semi-Lagrangian value stays).
// The smoke and the heat: either the same semi-Lagrangian schemes (which do not conserve mass: a puff rising in a
// closed box loses about a fifth of its smoke in 500 steps) or, by default, a conservative finite-volume transport
// swept axis by axis: the flux through each face is the face velocity times the upwind cell value with a
// minmod-limited slope (MUSCL, van Leer 1979), in sub-steps of at most half a cell; each sweep adds back the
// step's start value times its own divergence, which sums to zero over the three sweeps in a divergence-free flow
// (Easter 1993's correction in its simplest form), so that the smoke mass changes only through open boundaries,
// the sources and the projection's residual, and a uniform field stays uniform. Sweeping axis by axis costs a
// third of the unsplit scheme's sub-steps.

#include "vsim/sim/smoke/SmokeGrid.h"

namespace vsim::sim::smoke {

enum class AdvectionScheme
{
    SemiLagrangian,
    MacCormack,  ///< with the limiter
    Conservative ///< finite volume, limited (the smoke and the heat only; the velocity then moves by MacCormack)
};

/// The conservative transport's sub-steps along an axis whose fastest face moves at `fastest` (m/s) over dt (s)
/// on cells of h (m): each at most half a cell. A Courant number within 1e-3 above a whole number of half cells
/// counts as that number: the stable step puts the fastest flow at exactly a whole number of cells, where the
/// rounding of the velocity would otherwise decide between two counts (and two backends part by a sub-step).
int transportSubsteps(double fastest, double dt, double h);

/// Advects the velocity by `velocityScheme` and the smoke density and the temperature by `scalarScheme`, over
/// dt (s). Solid cells keep no smoke. The conservative transport sweeps the axes x, y, z, or z, y, x when
/// `reverseSweeps` (alternate it from step to step).
void advect(SmokeGrid& grid, double dt, AdvectionScheme velocityScheme, AdvectionScheme scalarScheme,
            bool reverseSweeps = false);

} // namespace vsim::sim::smoke
