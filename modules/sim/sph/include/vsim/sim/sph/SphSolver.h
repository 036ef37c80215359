#pragma once

// The weakly compressible SPH solver on the run driver (issue 18; thesis ch. 5.1-5.4): particles given as the
// input "particles" (a ParticleSet in mm with the field "wall", 1 at the dynamic-boundary particles, and
// optionally "wall_depth_mm", a wall particle's depth below the wall's surface for the no-slip velocity of
// SphRates.h, "pressure_pa" to start from, "velocity_x_m_s" .. "velocity_z_m_s", "void_fraction", "tracer" and
// "open_boundary", k + 1 at the buffer particles of the open boundary k given by setOpenBoundaries()), stepped by
// leapfrog
// (kick-drift-kick: one rate evaluation per step) with the adaptive time step of SphRates.h. Guards: a value
// that is not finite, a density more than `density_guard` from the rest density (the weak compressibility
// broken: a sound speed too low for the flow, or particles piling up), a particle leaving the domain's box
// grown by `escape_margin_mm`, a fluid particle half a spacing into a wall of known depths. A guard puts the
// particles back to the step's start. After each drift the open boundaries exchange particles with the fluid
// (OpenBoundary.h), and tracer particles that come within `absorption_distance_mm` of a wall's surface are absorbed
// (removed, their mass counted: drug uptake).

#include "vsim/sim/common/Solver.h"
#include "vsim/sim/sph/CrossSections.h"
#include "vsim/sim/sph/WallShear.h"
#include "vsim/sim/sph/FluidModel.h"
#include "vsim/sim/sph/NeighbourGrid.h"
#include "vsim/sim/sph/OpenBoundary.h"
#include "vsim/sim/sph/ParticleState.h"
#include "vsim/sim/sph/QuarticKernel.h"
#include "vsim/sim/sph/SphCheckpoint.h"
#include "vsim/sim/sph/SphRates.h"
#include "vsim/sim/sph/SphStepper.h"

#include <memory>

namespace vsim::sim::sph {

/// spacing_mm, smoothing_ratio, density_kg_m3, viscosity_pa_s, sound_speed_m_s, delta_sph, particle_shifting, cfl,
/// gravity_{x,y,z}_m_s2 (patient frame, LPS: a supine patient's is +y), end_time_s, density_guard,
/// escape_margin_mm, reorder_every, body_force_{x,y,z}_m_s2 and body_force_frequency_hz, periodic_{x,y,z}_mm
/// (validation channels), free_surface, wall_repulsion, absorption_distance_mm.
std::vector<ParameterSpec> sphParameters();

/// The Courant number (parameter `cfl`) for flows through a stenosis: the solver's default 0.2 of h / c0 is 0.4 of a
/// spacing per step at h = 2 spacings, and a stenosis's jet went unstable with it (sph-stenosis: a particle on the
/// axis 1 mm past the throat 3.07 % off the rest density at 13.9 ms; at c0 6 m/s already at 9.1 ms); at 0.1 the case
/// runs through with the density within 0.62 % (2026-11-27, RESULTS.md). The validation channels (hydrostatic,
/// Poiseuille, Womersley, mass) pass at the default and keep it.
constexpr double kStenosisCfl = 0.1;
/// The throat Reynolds number (rho U d / mu of the narrowest section's mean flow) up to which kStenosisCfl holds:
/// sph-stenosis's pipe, 0.2 m/s through a 0.8 mm throat in blood (StenosisPipe's defaults).
constexpr double kStenosisCflReynolds = 48.457;
/// The stenosis Courant number for a jet of `throatReynolds`: `cflAtReference` scaled by min(1, `referenceReynolds`
/// / `throatReynolds`). A faster jet needs the smaller step: at throat Re 97 the jet blew up at 0.1 (0.05 mm
/// particles, with and without the stenosis numerics below: the density guard on the axis in the throat at 12.4 and
/// 13.7 ms) and held at 0.05; at Re 200 0.024 held (2026-11-30 and 2026-12-06, RESULTS.md). StenosisPipe::atFlow
/// and the study pipeline (app/BloodFlowPipeline) both take it.
inline double stenosisCfl(double throatReynolds, double cflAtReference = kStenosisCfl,
                          double referenceReynolds = kStenosisCflReynolds)
{
    return throatReynolds > referenceReynolds ? cflAtReference * referenceReynolds / throatReynolds : cflAtReference;
}

/// A stenosis's other numerics, those of the 0.05 mm cross-check against OpenFOAM at throat Re 97 (2026-12-04,
/// RESULTS.md; sim/sph/README.md): particle shifting A 2 (without it the recovering jet tore into streaks and voids
/// and stopped at the density guard), its speed floor the narrowest section's mean speed (without it the slow
/// separation zone clumped) and the continuity density relaxed towards summation over 20 h / c0 (without it the
/// jet's wake thinned out: 4.1 % of the fluid lost at 0.1 mm). With them the run kept its fluid (net outflow 0.08 %)
/// and read the peak velocity ratio 1.1 % and the pressure drop 3.1 % from simpleFoam's.
constexpr double kStenosisShifting = 2.0;
constexpr double kStenosisRelaxationSmoothingTimes = 20.0; ///< tau in units of h / c0

/// The walls' backstop's reach r0 in spacings (FluidModel.h): short of the lattice's spacing, so that the
/// fluid at the wall's lattice distance feels none (single precision's rounding of it had the GPU push where
/// the CPU did not: parity after 100 steps 5.7e-4 with r0 one spacing) and a pass between four wall particles
/// (0.71 spacings) meets its plateau.
constexpr double kWallRepulsionReach = 0.9;

/// A density's departure (rho / rho0 - 1) as the density guard prints it: percent with its sign, "+3.01" or
/// "-3.01" (compressed or stretched: which one tells a jet's impact from a tensile void).
std::string signedPercentText(double fraction);

/// A particle's position (m) as the guards print it: "(x, y, z) mm" (the CPU's and the GPU's the same).
std::string positionText(const Eigen::Vector3d& positionM);

/// What a step needs besides the particles and the fluid: the GPU backend (cuda/sph) takes it from the CPU solver.
struct SphStepSettings
{
    double cfl = 0.2;
    double densityGuard = 0.03;      ///< |rho / rho0 - 1| that stops a step
    double spacingM = 0.0;
    bool freeSurface = false;        ///< walls extrapolate no suction (SphRates.h)
    Eigen::Vector3d boxLowM, boxHighM; ///< a particle outside has escaped (the escape margin included)
    Eigen::Vector3d periodicLengthM; ///< 0 per open axis
    bool openBoundaries = false, absorption = false;
};

class SphSolver : public Solver
{
public:
    std::string name() const override { return "sph"; }
    std::vector<ParameterSpec> parameters() const override { return sphParameters(); }
    /// Inlets and outlets for the next initialize(); none by default (closed or periodic domains).
    void setOpenBoundaries(std::vector<OpenBoundary> boundaries) { m_openBoundaries = OpenBoundaries(std::move(boundaries)); }
    /// Cross-sections whose flow is averaged over time from `fromTimeS` on, sampled every `everySteps` steps
    /// (CrossSections.h): the stenosis figures.
    void setSections(std::vector<CrossSection> sections, double fromTimeS, int everySteps = 1)
    {
        m_sections = SectionSeries(std::move(sections), fromTimeS, everySteps);
    }
    /// The sections' phase window (CrossSections.h: a pulsatile run's systole), after setSections().
    void setSectionsPhaseWindow(PhaseWindow window) { m_sections.setPhaseWindow(window); }
    const SectionSeries& sections() const { return m_sections; }
    /// Points on the wall where the wall shear stress and pressure are averaged over time from `fromTimeS` on,
    /// sampled every `everySteps` steps (WallShear.h).
    void setWallPoints(std::vector<WallPoint> points, double fromTimeS, int everySteps = 1)
    {
        m_wallLoads = WallLoadSeries(std::move(points), fromTimeS, everySteps);
    }
    const WallLoadSeries& wallLoads() const { return m_wallLoads; }
    /// Steps with another stepper of the same algorithm (the GPU's), made at the next initialize(); the
    /// particles come back every `syncEvery` steps (and for frames and metrics), when the sections and the wall
    /// loads take their samples (each then at that cadence, whatever setSections / setWallPoints asked), each
    /// weighted by the time since the last. A guard then ends the run where it
    /// stopped (no step back). An empty factory, or one that returns none: the CPU steps.
    void setStepper(SphStepperFactory factory, int syncEvery = 10)
    {
        m_stepperFactory = std::move(factory), m_syncEvery = std::max(1, syncEvery);
    }
    bool steppedElsewhere() const { return m_stepper != nullptr; }
    /// Goes on from a saved run (SphCheckpoint.h) at the next initialize(): the input's particles still set up the
    /// box, the open boundaries' profiles and the walls (their depths, guard depths and backstop), then the saved
    /// particles take their place, each wall particle matched to the input's by its number, with the saved time,
    /// steps, mass ledger and time averages. initialize() throws vsim::Error when the saved walls or open
    /// boundaries are not the input's. Null: start from the input.
    void setStartState(std::shared_ptr<const SphCheckpoint> saved) { m_startState = std::move(saved); }
    /// The run now, to go on from later (the particles and the next kick's rates fetched from the stepper).
    SphCheckpoint checkpoint() const;
    /// For a stepper made after initialize(): the saved rates the first kick takes, in particles()' order, when
    /// it went on from a checkpoint that holds them (the stepper takes these rather than evaluating its own);
    /// null otherwise, and once the solver has stepped.
    const SphRates* savedStartRates() const { return m_tookSavedRates ? &m_rates : nullptr; }
    void initialize(const SimulationInput& input, const ParameterSet& parameters) override;
    RunAxis axis() const override { return {"time", "s", m_endTimeS}; }
    double position() const override { return m_timeS; }
    StepOutcome step(RunStatus& status, const Progress& progress) override;
    /// Every particle (mm) with speed_m_s, velocity_{x,y,z}_m_s, pressure_pa, density_kg_m3, void_fraction, wall,
    /// open_boundary and tracer, by number (those given first, in their order, then those the inlets let in).
    SimulationData snapshot() const override;
    /// particles, fluid_particles, time_step_s (the last), steps, largest_speed_m_s, largest_density_variation
    /// (|rho / rho0 - 1| over the fluid), kinetic_energy_j, fluid_mass_kg; with open boundaries or absorption also
    /// inflow_kg, outflow_kg, absorbed_kg, fluid_mass_change_kg and per boundary <name>_flow_rate_ml_s (into the
    /// domain), <name>_pressure_pa and <name>_net_inflow_kg.
    std::map<std::string, double> metrics() const override;

    /// The particles now (fetched from the stepper when it has stepped since).
    const ParticleState& particles() const;
    const FluidModel& fluid() const { return m_fluid; }
    const QuarticKernel& kernel() const { return *m_kernel; }
    const OpenBoundaries& openBoundaries() const { return m_openBoundaries; }
    SphStepSettings stepSettings() const;
    const MassLedger& massLedger() const { return m_stepper ? m_stepper->massLedger() : m_ledger; }
    /// The pressure of every particle (Pa), in the particles' current order.
    std::vector<double> pressure() const { return pressures(particles(), m_fluid); }

private:
    void updateRates(double timeS);
    /// The fluid particles' mass now (kg).
    long double fluidMass() const;
    /// Removes the tracer particles within the absorption distance of a wall (the start's wall distances).
    void absorbTracer();
    /// Clears `backstop` at the wall particles within a support of an open end's buffer (SphSolver.cpp).
    void releaseBackstopAtOpenEnds();
    /// Sets ParticleState::guardDepth from the particles as given (SphSolver.cpp).
    void setGuardDepths();
    /// Puts the saved run in place of the particles as given (setStartState); true when it took the saved rates.
    bool goOnFrom(const SphCheckpoint& saved);
    /// A step on the other stepper, and every m_syncEvery steps the particles back and the samples.
    StepOutcome stepElsewhere();
    /// The fluid loss guard's words at time t (s) when the ledger's net outflow exceeds its share of the first fluid
    /// mass; "" otherwise or when it is off.
    std::string fluidLossText(double timeS) const;

    FluidModel m_fluid;
    std::unique_ptr<QuarticKernel> m_kernel;
    std::unique_ptr<NeighbourGrid> m_grid;
    mutable ParticleState m_particles; ///< with a stepper: the last fetched (m_stale: it has stepped since)
    mutable bool m_stale = false;
    SphStepperFactory m_stepperFactory;
    std::unique_ptr<SphStepper> m_stepper;
    std::shared_ptr<const SphCheckpoint> m_startState;
    int m_syncEvery = 10;
    double m_pendingS = 0.0; ///< stepped since the last samples (s)
    SphRates m_rates;
    bool m_tookSavedRates = false; ///< m_rates are the checkpoint's (no step since)
    OpenBoundaries m_openBoundaries;
    SectionSeries m_sections;
    WallLoadSeries m_wallLoads;
    MassLedger m_ledger;
    long double m_initialFluidMass = 0.0;
    double m_absorptionDistanceM = 0.0;
    bool m_freeSurface = false;
    int m_nextId = 0;
    double m_timeS = 0.0, m_endTimeS = 0.0, m_stepS = 0.0, m_cfl = 0.2, m_densityGuard = 0.03, m_spacingM = 0.0;
    double m_fluidLossGuard = 0.0; ///< share of the first fluid mass (0: off)
    Eigen::Vector3d m_boxLow = Eigen::Vector3d::Zero(),
                    m_boxHigh = Eigen::Vector3d::Zero(); ///< m, with the margin
    long m_steps = 0;
    int m_reorderEvery = 20;
};

} // namespace vsim::sim::sph
