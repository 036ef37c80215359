#pragma once

// The blood's load on the vessel wall from the particles (issue 18): at points on the wall's surface (the lumen
// surface's vertices, or a validation case's analytic wall) with their unit normals into the lumen, from the fluid
// particles in a cylinder on the point (3 lattice spacings deep along the normal, 1.5 across; the first three
// layers of a lattice):
//   wall shear stress  tau_w = mu du_t/dn at the wall, u_t the particles' velocities less their normal part, from
//                      the least-squares parabola u_t = u0 + a y + b y^2 in the depth y: tau_w = mu a. The intercept
//                      is fitted, not set to 0: the particles next to the wall carry a small apparent slip, and with
//                      u0 = 0 sph-poiseuille read 5.9 % high (1.6e-3 with it). Interpolating u_t at probes by the FPM
//                      first read 20 % high: its support, 4 spacings, is wider than the profile's curvature allows.
//   wall pressure      the least-squares line p = p0 + c y, its value at the wall p0.
// WallLoadSeries averages them over time from a given time on: the time-averaged WSS (TAWSS, the mean of |tau_w|),
// the oscillatory shear index OSI = (1 - |mean tau_w| / mean |tau_w|) / 2 (Ku et al. 1985; 0 for a steady flow) and
// the mean wall pressure. SI: m, Pa.

#include "vsim/sim/sph/FluidModel.h"
#include "vsim/sim/sph/NeighbourGrid.h"
#include "vsim/sim/sph/ParticleState.h"
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
    bool valid = false; ///< false where the cylinder holds fluid particles at fewer than three depths (past an open end)
};

/// The load at `point` from the fluid particles of `particles` (the grid built on their positions; its reach at least
/// 2.2 lattice spacings `spacingM`: the cylinder's corners from its centre), the blood's viscosity from `fluid`.
WallLoad wallLoad(const ParticleState& particles, const NeighbourGrid& grid, const FluidModel& fluid, double spacingM,
                  const WallPoint& point);

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
    void sample(const ParticleState& particles, const NeighbourGrid& grid, const FluidModel& fluid, double spacingM,
                double timeS, double weightS);
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
