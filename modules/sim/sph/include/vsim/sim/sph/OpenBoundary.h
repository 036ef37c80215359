#pragma once

// Open boundaries of the SPH solver (issue 18): inlets and outlets at vessel ends. Each is a disk (centre, unit normal
// into the domain, radius) with a buffer of particles behind it, as deep as the kernel's support, so that the fluid
// next to the plane keeps a full neighbourhood. Buffer particles are not integrated: every step they take prescribed
// values and values extrapolated from the fluid at their mirror point across the plane (x - 2 s n for a buffer
// particle s = (x - c) . n < 0 behind it; a zeroth-order Shepard interpolation over the fluid there), in the manner
// of Tafuni et al. 2018 (CMAME 342:604) and Federico et al. 2012:
//  velocity prescribed (an inlet's flow rate, or a needle's): v = Q(t) / C shape(r) n, shape 1 - r^2 / R^2
//      (parabolic) or 1 (plug), R the equivalent radius of the buffer's cross-section, C = sum_buffer shape V / depth
//      (so that the particles' flux is Q), Q(t) = Q ramp(t) waveform(t); the density extrapolated (rho / rho0(s));
//  pressure prescribed (an outlet, or an inlet at a given pressure): p = p0 waveform(t) + R_out Q_out (a resistance
//      outlet; Q_out the buffer's outflow, m^3/s, from the particles' normal velocities); the velocity extrapolated.
// After each drift the particles are exchanged (OpenBoundaries::exchange): a buffer particle that crossed into the
// domain becomes fluid, and a copy of it enters the buffer a depth behind (the buffer stays full); a fluid particle
// that crossed out through the disk joins a pressure buffer (or an outflowing velocity buffer) and leaves an
// inflowing velocity buffer at once (joining it would overfill it: the copies refill it already); a buffer particle
// deeper than the buffer leaves. A ledger counts the mass that entered and left through each boundary, so that
// inflow - outflow - absorbed = the fluid's mass change (sph-mass).

#include "vsim/sim/sph/FluidModel.h"
#include "vsim/sim/sph/NeighbourGrid.h"
#include "vsim/sim/sph/ParticleState.h"
#include "vsim/sim/sph/QuarticKernel.h"

#include <Eigen/Core>

#include <string>
#include <utility>
#include <vector>

namespace vsim::sim::sph {

/// A periodic factor over time: (time s, factor) points, linear between them, repeating after the last time (a
/// cardiac cycle). Empty: 1.
struct Waveform
{
    std::vector<std::pair<double, double>> points;
    double factorAt(double timeS) const;
    double period() const { return points.empty() ? 0.0 : points.back().first; }
};

/// The inflow's rise from rest over `rampS` (s): (1 - cos(pi t / ramp)) / 2, then 1 (no ramp: 1).
double rampFactor(double timeS, double rampS);

struct OpenBoundary
{
    enum class Prescribed { Velocity, Pressure };
    Eigen::Vector3d centreM = Eigen::Vector3d::Zero();
    Eigen::Vector3d normal = Eigen::Vector3d::UnitX(); ///< unit, into the domain
    double radiusM = 0.0;                              ///< particles farther from the axis are not the boundary's
    Prescribed prescribed = Prescribed::Pressure;
    double flowRateM3S = 0.0;    ///< velocity prescribed: into the domain (> 0) or out of it (< 0)
    bool parabolic = true;       ///< velocity prescribed: parabolic or plug profile
    double pressurePa = 0.0;     ///< pressure prescribed (gauge: on the scale FluidModel::reportedPressure gives)
    double resistancePaSM3 = 0.0; ///< pressure prescribed: p = pressurePa + resistance x outflow (Pa s/m^3)
    Waveform waveform;           ///< multiplies the flow rate or the pressure
    double rampS = 0.0;          ///< the flow rate rises as (1 - cos(pi t / ramp)) / 2 over this time (from rest)
    bool tracer = false;         ///< the particles it lets in carry the tracer (an injected drug: absorbable)
    std::string name;            ///< "inlet", "outlet 2", ... for messages and metrics
};

/// Mass through the open boundaries (per boundary) and into the walls since the start (kg).
struct MassLedger
{
    std::vector<long double> inflowKg, outflowKg;
    long double absorbedKg = 0.0;
    long double totalInflow() const;
    long double totalOutflow() const;
};

class OpenBoundaries
{
public:
    OpenBoundaries() = default;
    explicit OpenBoundaries(std::vector<OpenBoundary> boundaries) : m_boundaries(std::move(boundaries)) {}

    bool empty() const { return m_boundaries.empty(); }
    const std::vector<OpenBoundary>& boundaries() const { return m_boundaries; }
    /// Checks the boundaries and calibrates the velocity profiles from the buffer particles (ParticleState::boundary
    /// = k + 1 for boundary k) of `depthM` (the support); throws vsim::Error for a boundary without buffer
    /// particles, a normal that is not a unit vector or a buffer index beyond the boundaries.
    void initialize(const ParticleState& particles, double depthM, double spacingM);
    /// Throws vsim::Error for a boundary whose deepest buffer particle lies beyond `depthM` or more than `spacingM`
    /// short of it: seeded for another smoothing ratio, its imposed inflow would be scaled by the depths' ratio
    /// (SphSolver::initialize checks a lattice's buffers before initialize()).
    void checkBufferDepths(const ParticleState& particles, double depthM, double spacingM) const;
    /// The fluid's reference pressure (FluidModel::referencePressurePa, Pa): the prescribed pressures are gauge, and
    /// prescribedPressure() and pressure() give them above it.
    void setReferencePressure(double pressurePa) { m_referencePa = pressurePa; }
    /// The exchange after a drift (see above); `nextId` numbers the particles it creates, `ledger` (sized by
    /// initialize's caller to the boundaries) counts. The caller rebuilds its grid.
    void exchange(ParticleState& particles, int& nextId, MassLedger& ledger) const;
    /// The buffer particles' velocity and density at time t, the grid built on the current positions.
    void impose(ParticleState& particles, const NeighbourGrid& grid, const QuarticKernel& kernel, const FluidModel& fluid,
                double timeS);
    /// The last imposed flow rate of boundary k into the domain (m^3/s; < 0 out of it), from its buffer particles.
    double flowRate(std::size_t k) const { return m_flowRate.at(k); }
    /// The last imposed pressure of boundary k (Pa above the reference; velocity prescribed: the mean of its buffer
    /// particles').
    double pressure(std::size_t k) const { return m_pressure.at(k); }
    /// Puts back the last flow rates and pressures of a saved run (SphCheckpoint.h: a resistance outlet's pressure
    /// follows its last outflow), after initialize(); throws vsim::Error for another number of boundaries.
    void restoreLast(std::vector<double> flowRatesM3S, std::vector<double> pressuresPa);
    /// Where x (m) lies against boundary k: s = (x - c) . n (m; < 0 behind it) and whether it is within the disk.
    double signedDistance(std::size_t k, const Eigen::Vector3d& x) const { return (x - m_boundaries[k].centreM).dot(m_boundaries[k].normal); }
    bool withinDisk(std::size_t k, const Eigen::Vector3d& x) const;
    /// What another stepper (the GPU's) needs to impose the same values, after initialize(): the buffers' depth
    /// (m), boundary k's profile calibration C_k (m^2) and equivalent radius R_k (m), its flow rate Q(t) (m^3/s;
    /// velocity prescribed) and pressure p0 waveform(t) + R_out Q_out - the reference for the last outflow `flowRate`
    /// (Pa).
    double depth() const { return m_depthM; }
    double calibration(std::size_t k) const { return m_calibration.at(k); }
    double equivalentRadius(std::size_t k) const { return m_equivalentRadius.at(k); }
    double prescribedFlowRate(std::size_t k, double timeS) const;
    double prescribedPressure(std::size_t k, double timeS, double flowRate) const;

private:
    double shape(std::size_t k, const Eigen::Vector3d& x) const;

    std::vector<OpenBoundary> m_boundaries;
    std::vector<double> m_calibration;      ///< C_k = sum shape V / depth, m^2
    std::vector<double> m_equivalentRadius; ///< R_k, m
    std::vector<double> m_flowRate, m_pressure;
    double m_depthM = 0.0;
    double m_referencePa = 0.0; ///< setReferencePressure()
};

} // namespace vsim::sim::sph
