#pragma once

// The blood's load on the vessel wall from the particles (issue 18): at points on the wall's surface (the lumen
// surface's vertices, or a validation case's analytic wall) with their unit normals into the lumen:
//   wall shear stress  the friction the walls give the fluid: the tangential part of sum_i m_i a_i^wall over the fluid
//                      particles in a column on the point (a kernel support deep along the normal, 1.5 lattice
//                      spacings across), a_i^wall the viscous acceleration from the wall particles alone with their
//                      no-slip velocity (SphRates.h: wallFrictionAcceleration), over the column's cross-section
//                      sum_i V_i / depth (the same particles' volume: the lattice columns the disk happens to hold
//                      cancel). It is the momentum the walls take out of the flow, so a boundary layer the particles
//                      resolve coarsely still gives the friction the flow felt. It replaced (2026-12-01) a
//                      least-squares parabola u_t = u0 + a y + b y^2 through the particles' velocities 3 spacings
//                      deep (tau_w = mu a), which read a stenosis throat's boundary layer of about a spacing 47 % low
//                      (Re 97, 0.05 mm: 15.1 against OpenFOAM's 28.5 Pa, the friction 22.0) and 60 % low at Re 200
//                      (27.9 against 70.5, the friction 53.0), and hundreds of Pa where the walls' backstop held the
//                      fluid off a diverging wall (RESULTS.md, 2026-12-01).
//   wall pressure      the least-squares line p = p0 + c y through the fluid particles in a cylinder 3 spacings deep
//                      and 1.5 across, its value at the wall p0.
// WallLoadSeries averages them over time from a given time on: the time-averaged WSS (TAWSS, the mean of |tau_w|),
// the oscillatory shear index OSI = (1 - |mean tau_w| / mean |tau_w|) / 2 (Ku et al. 1985; 0 for a steady flow) and
// the mean wall pressure. SI: m, Pa.

#include "vsim/sim/sph/FluidModel.h"
#include "vsim/sim/sph/NeighbourGrid.h"
#include "vsim/sim/sph/ParticleState.h"
#include "vsim/sim/sph/QuarticKernel.h"
#include "vsim/sim/sph/SampleSchedule.h"

#include <Eigen/Core>

#include <vector>

namespace vsim::sim::sph {

struct WallPoint
{
    Eigen::Vector3d positionM = Eigen::Vector3d::Zero();
    Eigen::Vector3d normal = Eigen::Vector3d::UnitX(); ///< unit, into the lumen
};

struct WallLoad
{
    Eigen::Vector3d shearPa = Eigen::Vector3d::Zero(); ///< tau_w, tangential (on the wall, in the flow's direction)
    double pressurePa = 0.0;
    bool valid = false; ///< false where the cylinder holds fluid particles at fewer than two depths (past an open end)
};

/// The load at `point` from the fluid particles of `particles` (the grid built on their positions with the kernel's
/// support as its reach), the blood's viscosity from `fluid`, the lattice spacing `spacingM`.
WallLoad wallLoad(const ParticleState& particles, const NeighbourGrid& grid, const QuarticKernel& kernel,
                  const FluidModel& fluid, double spacingM, const WallPoint& point);

struct WallLoadAverage
{
    double tawssPa = 0.0;       ///< mean |tau_w|
    Eigen::Vector3d meanShearPa = Eigen::Vector3d::Zero();
    double osi = 0.0;           ///< (1 - |mean tau_w| / mean |tau_w|) / 2
    double meanPressurePa = 0.0;
    double largestShearPa = 0.0; ///< the largest |tau_w| sampled
    double sampledTimeS = 0.0;   ///< the time its valid samples cover
};

class WallLoadSeries
{
public:
    WallLoadSeries() = default;
    /// Samples every `everySteps`-th call from `fromTimeS` on, each weighted by the time since the last one taken.
    WallLoadSeries(std::vector<WallPoint> points, double fromTimeS, int everySteps = 1)
        : m_points(std::move(points)), m_schedule(fromTimeS, everySteps)
    {
    }
    bool empty() const { return m_points.empty(); }
    const std::vector<WallPoint>& points() const { return m_points; }
    void sample(const ParticleState& particles, const NeighbourGrid& grid, const QuarticKernel& kernel,
                const FluidModel& fluid, double spacingM, double timeS, double weightS);
    /// The time averages per point (zeros before any sample).
    std::vector<WallLoadAverage> averages() const;
    void reset() { m_schedule.reset(), m_sums.clear(); }
    void sampleEveryCall() { m_schedule.everyCall(); } ///< the caller keeps the cadence (SampleSchedule.h)
    /// The weighted sums so far, one per point or none, and where the schedule stands (SphCheckpoint.h); restore()
    /// goes on from them. Throws vsim::Error for sums of another number of points.
    struct Sums
    {
        std::vector<WallLoadAverage> points;
        SampleSchedule::State schedule;
    };
    Sums sums() const { return {m_sums, m_schedule.state()}; }
    void restore(Sums sums);

private:
    std::vector<WallPoint> m_points;
    SampleSchedule m_schedule;
    std::vector<WallLoadAverage> m_sums; ///< weighted sums (tawss, mean shear, pressure), the largest, the weight
};

} // namespace vsim::sim::sph
