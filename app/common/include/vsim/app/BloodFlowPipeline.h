#pragma once

// Blood flow in a study's vessels (issue 18): the SPH solver on the lumen label the centerlines were extracted from.
// The vessel ends come from the centerlines (the network of NetworkPipeline.h): each end's plane lies a little inside
// the vessel (half its radius, at least two spacings), perpendicular to the centerline there, with a disk of 1.5 radii;
// one end is the inlet (a flow rate, a mean velocity or a pressure, steady or scaled by a waveform, ramped up from
// rest), the others are pressure outlets. The particles are seeded on the label with the ends open
// (mesh/ParticleSeeding.h). Sections every two spacings along the centerline from the inlet to the outlet whose path is
// the narrowest are averaged over the run's second half (steady) or its last cycle (a waveform), and give the stenosis
// figures (sim/sph/StenosisFigures.h); the wall shear stress and pressure on the lumen's surface are averaged over the
// same window (sim/sph/WallShear.h).

#include "vsim/core/Parameters.h"
#include "vsim/core/Progress.h"
#include "vsim/core/SolverRun.h"
#include "vsim/core/TriangleMesh.h"
#include "vsim/sim/common/RunDriver.h"
#include "vsim/sim/sph/CrossSections.h"
#include "vsim/sim/sph/OpenBoundary.h"
#include "vsim/sim/sph/SphSolver.h"
#include "vsim/sim/sph/StenosisFigures.h"
#include "vsim/study/Study.h"

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace vsim::app {

struct BloodFlowInlet
{
    enum class Kind { FlowRate, MeanVelocity, Pressure };
    Kind kind = Kind::FlowRate;
    double value = 0.0;  ///< m^3/s, m/s (mean over the inlet's section) or Pa
    int endNode = -1;    ///< the network's end node; -1: the root (the end of the largest vessel)
    sim::sph::Waveform waveform;
    bool parabolic = true;
};

struct BloodFlowSetup
{
    std::string centerlinesId;
    BloodFlowInlet inlet;
    double outletPressurePa = 0.0; ///< every outlet (gauge); also the solver's reference pressure unless given
    double compareMm = 6.0;        ///< the stenosis figures' comparison distance (the thesis's hand case: 6 mm)
    /// The solver's parameters; spacing_mm, sound_speed_m_s, cfl (sim::sph::stenosisCfl of the narrowest section's
    /// Re), end_time_s,
    /// reference_pressure_pa (the outlets' pressure), fluid_loss_guard (0.1), particle_shifting
    /// (sim::sph::kStenosisShifting), shifting_speed_m_s (the narrowest section's mean speed at the inflow's
    /// peak) and density_relaxation_s (20 h / c0; not with density_summation) are chosen (runBloodFlow) unless
    /// `given` names them.
    ParameterSet parameters{sim::sph::sphParameters()};
    std::vector<std::string> given; ///< parameter names the user set
    double rampS = -1.0;            ///< the inflow's rise from rest; < 0: 8 L / c0 (L the path's length)
    int frames = 20;                ///< frames over the run, when the run control asks for none
    /// auto (the GPU when there is one and it runs the case), cpu or cuda (refused without a device)
    std::string backend = "auto";
};

struct BloodFlowRun
{
    SolverRun run;
    std::vector<sim::sph::OpenBoundary> boundaries;
    std::vector<double> sectionArcMm;          ///< along the compared path, from the inlet's plane
    std::vector<Eigen::Vector3d> sectionCentresMm;
    std::vector<sim::sph::SectionFlow> sections; ///< time averages
    std::vector<double> sectionLargestPeaks;      ///< m/s
    double averagedFromS = 0.0, averagedS = 0.0;
    std::optional<sim::sph::StenosisFigures> stenosis;
    ParameterSet parameters{sim::sph::sphParameters()}; ///< as run (the chosen values filled in)
    double rampS = 0.0;
    /// The compared path's settling time (s): its Poiseuille resistance times its compliance V / (rho c0^2); the
    /// default end time leaves five of them after the ramp (0 for a pressure inlet).
    double settlingS = 0.0;
    /// The lumen's surface (mesh/VesselSurface.h, 20,000 vertices at most) with the wall loads averaged with the
    /// sections (sim/sph/WallShear.h): point fields tawss_pa, osi and wall_pressure_pa (NaN where no fluid lies
    /// against the vertex: past an open end's plane).
    TriangleMesh wallSurface;
    std::vector<std::string> warnings;
    std::string backend = "cpu"; ///< what stepped it: cpu (double precision) or cuda (single)
    std::string device;          ///< the GPU, with cuda
};

/// The setup as a form declares it (the workstation's Flow > Blood Flow Parameters): inlet_mean_velocity_m_s,
/// inlet_flow_rate_ml_s (> 0 replaces the velocity), outlet_pressure_mmhg, compare_mm, spacing_mm and end_time_s (0:
/// chosen), frames.
std::vector<ParameterSpec> bloodFlowSetupParameters();
/// The solver parameters runBloodFlow chooses for the vessel unless `given` names them (BloodFlowSetup::parameters):
/// the workstation's "Automatic" ticks.
const std::vector<std::string>& bloodFlowChosenParameters();
/// The setup from that form and the solver's parameters: every solver parameter counts as given but those in
/// `automatic` (runBloodFlow chooses them), a value equal to its default included; the form's spacing and end time at
/// 0 are chosen.
BloodFlowSetup bloodFlowSetupFrom(const ParameterSet& form, const ParameterSet& solverParameters,
                                  const std::set<std::string>& automatic);

/// Runs the blood flow of the study's centerlines (their label's lumen) under `control` (without a frame schedule:
/// setup.frames over the end time). Throws vsim::Error for a
/// study without the centerlines' label, an inlet node that is not an end, a network of fewer than two ends, or what
/// the seeding and the solver refuse.
BloodFlowRun runBloodFlow(const study::Study& study, const BloodFlowSetup& setup, sim::RunControl control,
                          const Progress& progress = {});

/// What the CLI prints and the run folder keeps (JSON text): the run status, the boundaries, the metrics, the stenosis
/// figures with their definitions and units, the sections along the path.
std::string bloodFlowDocument(const BloodFlowRun& flow, const BloodFlowSetup& setup);

struct BloodFlowArtifacts
{
    std::string run;       ///< "Blood flow (SPH)"
    std::string wallLoads; ///< "Wall loads (SPH)"; empty when the run ended before its averaging window
    std::vector<std::string> ids() const { return wallLoads.empty() ? std::vector{run} : std::vector{run, wallLoads}; }
};

/// Adds the run ("Blood flow (SPH)": a Run artifact of particle frames) with the metrics, the stenosis figures and the
/// sections along the centerline (attribute "sections_along_centerline") as attributes, and the wall loads' surface
/// ("Wall loads (SPH)", made from the run); the study is not saved.
BloodFlowArtifacts addBloodFlowRun(study::Study& study, const BloodFlowRun& flow, const BloodFlowSetup& setup,
                            const std::vector<std::string>& inputs);

/// One cross-section of a blood-flow run, time-averaged over the run's window (sim/sph/CrossSections.h).
struct SectionAlongCenterline
{
    double arcMm = 0.0;                             ///< along the path from the inlet
    double peakVelocityMS = 0.0, meanVelocityMS = 0.0; ///< the fastest 5 % of its particles; flow rate / area
    double meanPressurePa = 0.0;                    ///< gauge (the outlets at their given pressure)
};
/// The sections a run artifact made by addBloodFlowRun() carries, in order along the path (empty for other runs).
std::vector<SectionAlongCenterline> sectionsAlongCenterline(const study::Artifact& run);

} // namespace vsim::app
