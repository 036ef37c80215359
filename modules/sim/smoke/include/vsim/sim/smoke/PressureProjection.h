#pragma once

// The pressure projection of the stable-fluids step (Stam 1999; thesis eqs. 7.5 - 7.6, where the printed 7.5 means
// the divergence of u'): the faces of solids and of wall boundaries take the solid's normal velocity, then
// lap psi = div u' with psi = dt p / rho is solved by multigrid-preconditioned conjugate gradients
// (PoissonMultigrid.h) to a relative residual, warm-started from the last two projections' psi extrapolated in time
// (PressureWarmStart.h), and u = u' - grad psi.
// Every projection reports its iterations, its residual and the largest divergence left.

#include "vsim/sim/smoke/PoissonMultigrid.h"
#include "vsim/sim/smoke/PressureWarmStart.h"
#include "vsim/sim/smoke/SmokeGrid.h"

#include <vector>

namespace vsim::sim::smoke {

struct ProjectionReport
{
    int iterations = 0;
    double relativeResidual = 0.0;   ///< ||b - A psi|| / ||b|| at the end (0 when b = 0)
    bool converged = false;          ///< relativeResidual <= the tolerance asked for
    double maxDivergence = 0.0;      ///< largest |div u - the source's| over the fluid cells afterwards (1/s)
    double divergenceRatio = 0.0;    ///< maxDivergence h / max |u| (dimensionless; 0 at rest)
};

/// Sets every face next to a solid cell, and every face on a wall of the domain, to the normal velocity of the
/// solid (0 on the domain's walls).
void applySolidBoundaries(SmokeGrid& grid);

/// The divergence of the face velocities at each fluid cell (1/s; solid cells 0).
std::vector<float> divergence(const SmokeGrid& grid);

class PressureProjection
{
public:
    /// Builds the operator for the grid's solids and boundaries; call again after they change (psi and its history
    /// are kept while the grid's size is).
    void prepare(const SmokeGrid& grid);
    /// Projects the grid's velocity: the solid faces first, then the solve to `tolerance` (relative residual) in
    /// at most `maxIterations` conjugate-gradient iterations. `sourceDivergence` (1/s per cell, optional) is the
    /// divergence the flow keeps: a suction's sink (negative) takes that much volume out of its cells. `stepS`: the
    /// length of the step this projection ends (s), for the warm start; 0 for a projection outside a step.
    ProjectionReport project(SmokeGrid& grid, double tolerance, int maxIterations,
                             const std::vector<float>* sourceDivergence = nullptr, double stepS = 0.0);
    /// psi of the last projection (m^2/s; the pressure is rho psi / dt).
    const std::vector<float>& potential() const { return m_psi; }
    const PoissonMultigrid& multigrid() const { return m_multigrid; }

private:
    PoissonMultigrid m_multigrid;
    std::vector<std::uint8_t> m_sides; ///< per cell: 1 fluid, 2 a vent (ambient), 0 solid
    std::vector<float> m_psi, m_b, m_r, m_z, m_p, m_q;
    std::vector<float> m_previousPsi; ///< psi of the projection before the last
    PressureWarmStart m_warmStart;
};

} // namespace vsim::sim::smoke
