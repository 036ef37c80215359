#pragma once

// The flow through cross-sections of a vessel (issue 18: the stenosis metrics, the mass checks): the fluid particles in
// a slab of the given thickness about a plane, within a disk, stand for the section. With V_i = m_i / rho_i the
// particles' volumes and u_i = v_i . n their speeds along the normal:
//   area A = sum V_i / thickness, flow rate Q = sum V_i u_i / thickness, mean velocity Q / A,
//   peak velocity: the mean of the fastest 5 % of the section's particles' u_i (at least 3): the duplex peak
//   velocity's counterpart, robust to a single particle's noise (about 2 % below the maximum of a parabolic profile
//   sampled by 100 particles), mean pressure sum V_i p_i / sum V_i.
// SectionSeries averages them over time (weighted by the time steps) from a given time on and keeps the largest peak;
// for a pulsatile run it also averages over a phase window of each cycle (the systole: the duplex peak-systolic
// velocities are read there). SI: m, m/s, m^3/s, Pa, s.

#include "vsim/sim/sph/FluidModel.h"
#include "vsim/sim/sph/ParticleState.h"
#include "vsim/sim/sph/SampleSchedule.h"

#include <Eigen/Core>

#include <algorithm>
#include <vector>

namespace vsim::sim::sph {

struct CrossSection
{
    Eigen::Vector3d centreM = Eigen::Vector3d::Zero();
    Eigen::Vector3d normal = Eigen::Vector3d::UnitX(); ///< unit, the flow's direction
    double radiusM = 0.0;                              ///< the disk that holds the section
    double thicknessM = 0.0;                           ///< the slab (a few spacings)
};

struct SectionFlow
{
    double areaM2 = 0.0, flowRateM3S = 0.0, meanVelocityMS = 0.0, peakVelocityMS = 0.0, meanPressurePa = 0.0;
    int particles = 0;
};

/// A window of each cycle: the times t with fromS <= t mod periodS <= toS (s). A period of 0: no window.
struct PhaseWindow
{
    double periodS = 0.0, fromS = 0.0, toS = 0.0;
    bool empty() const { return !(periodS > 0.0) || !(toS > fromS); }
    /// How much of the span (t - spanS, t] lies in the window (s): the weight in it of a sample at t that stands for
    /// the time since the last one (a span shorter than the cycle).
    double overlap(double timeS, double spanS) const;
};

/// The section's flow from the fluid particles (buffers and walls left out).
SectionFlow sectionFlow(const ParticleState& particles, const FluidModel& fluid, const CrossSection& section);

/// sum += weight x flow over the averaged quantities (the particles: the larger count).
void addWeighted(SectionFlow& sum, const SectionFlow& flow, double weight);
/// The sums (`sections` of them) divided by their total weight; empty flows when the weight is 0.
std::vector<SectionFlow> averaged(std::vector<SectionFlow> sums, std::size_t sections, double weight);

/// Time averages of sections' flows.
class SectionSeries
{
public:
    SectionSeries() = default;
    /// Samples every `everySteps`-th call of sample() (many sections over many particles), each weighted by the time
    /// since the last one taken.
    SectionSeries(std::vector<CrossSection> sections, double fromTimeS, int everySteps = 1)
        : m_sections(std::move(sections)), m_schedule(fromTimeS, everySteps)
    {
    }

    bool empty() const { return m_sections.empty(); }
    const std::vector<CrossSection>& sections() const { return m_sections; }
    /// Adds the state at time t (s) held for `weightS` (the step), once t >= the averaging start (every N-th call:
    /// weighted by the steps since the last).
    void sample(const ParticleState& particles, const FluidModel& fluid, double timeS, double weightS);
    /// The time averages (peakVelocityMS: the average peak); empty flows before any sample.
    std::vector<SectionFlow> averages() const;
    /// Also averages, from the same start, over the samples inside `window` of each cycle (each weighted by its time
    /// in the window): phaseAverages().
    void setPhaseWindow(PhaseWindow window) { m_window = window; }
    const PhaseWindow& phaseWindow() const { return m_window; }
    /// The averages over the phase window's samples; empty flows without a window or before its first sample.
    std::vector<SectionFlow> phaseAverages() const;
    double phaseAveragedTime() const { return m_phaseWeight; } ///< s
    /// The largest peak velocity of each section over the samples (m/s).
    const std::vector<double>& largestPeaks() const { return m_largestPeak; }
    double averagedTime() const { return m_weight; } ///< s
    /// Forgets the samples (a new run).
    void reset()
    {
        m_weight = m_phaseWeight = 0.0, m_schedule.reset(), m_sums.clear(), m_phaseSums.clear(), m_largestPeak.clear();
    }
    void sampleEveryCall() { m_schedule.everyCall(); } ///< the caller keeps the cadence (SampleSchedule.h)
    /// What the averages have summed so far and where their schedule stands (SphCheckpoint.h); restore() goes on
    /// from it. Throws vsim::Error for sums of another number of sections.
    struct Sums
    {
        double weightS = 0.0;
        std::vector<SectionFlow> flows; ///< weighted sums
        std::vector<double> largestPeaks;
        SampleSchedule::State schedule;
        double phaseWeightS = 0.0;
        std::vector<SectionFlow> phaseFlows; ///< weighted sums over the phase window (none without one)
    };
    Sums sums() const { return {m_weight, m_sums, m_largestPeak, m_schedule.state(), m_phaseWeight, m_phaseSums}; }
    void restore(Sums sums);

private:
    std::vector<CrossSection> m_sections;
    SampleSchedule m_schedule;
    double m_weight = 0.0; ///< s averaged
    std::vector<SectionFlow> m_sums;
    PhaseWindow m_window;
    double m_phaseWeight = 0.0; ///< s averaged inside the phase window
    std::vector<SectionFlow> m_phaseSums;
    std::vector<double> m_largestPeak;
};

} // namespace vsim::sim::sph
