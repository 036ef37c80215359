#pragma once

// The needle injection of thesis scenario (a) (ch. 5.5.1, Table 5.1; issue 18) on a study's vessels: blood
// injected through a needle at the top of an artery, void at the start, running down the vessel and out of
// its open lower end into a collection box below it ("an 'invisible' box at the bottom"), where it gathers
// with a free surface. The set-up as this pipeline reads the thesis:
// - the vessel is held upright: gravity (9.81 m/s^2) points from the needle's end of the vessel towards the
//   mean of its other ends (the thesis injects "from the top part of the blood vessel" and collects "at the
//   bottom"); the patient's own orientation plays no part;
// - the vessel is empty at the start (the thesis's void) and its other ends are open: the wall particles past
//   their planes are removed, and nothing holds the blood in but gravity and the walls;
// - the needle is a velocity inlet (OpenBoundary.h) at the needle end's plane, a bore of `needleBoreMm` with
//   a wall plug around it (the needle's body), emitting `particlesPerSecond` particles of the run's spacing a
//   second (Table 5.1: 300/s) as a parabolic profile;
// - the injected blood is the thesis's mixture (void fraction 0.2, Table 5.1) and the gauge pressure (5,332
//   Pa, 40 mmHg) is the level every reported pressure sits on (the solver's reference pressure, as for the
//   hand and heart scenarios);
// - the collection box is wall particles in the frame of gravity: a floor `collectionDepthMm` below the
//   lowest wall particle of the vessel and sides `collectionMarginMm` beyond the open ends' disks, rising as
//   far again above the box's top around the vessel's end, open at the top; what lies below its top is
//   "collected".
// What is followed over the frames: how much was injected, how much is in the vessel, in the box and absorbed
// by the walls (tracer absorption: CPU only), and how far down the vessel the blood has run.

#include "vsim/core/Parameters.h"
#include "vsim/core/Progress.h"
#include "vsim/core/SolverRun.h"
#include "vsim/sim/common/RunDriver.h"
#include "vsim/sim/sph/OpenBoundary.h"
#include "vsim/sim/sph/SphSolver.h"
#include "vsim/study/Study.h"

#include <Eigen/Core>

#include <set>
#include <string>
#include <vector>

namespace vsim::app {

struct InjectionSetup
{
    std::string centerlinesId;
    int needleEndNode = -1;          ///< the vessel end the needle enters; -1: the root (the end of the largest vessel)
    double needleBoreMm = 1.2;       ///< the needle's inner diameter (16 G: 1.19 mm)
    double particlesPerSecond = 300; ///< thesis Table 5.1's generation rate, particles of the run's spacing
    double collectionDepthMm = 15.0; ///< the box's floor below the vessel's lowest wall particle
    double collectionMarginMm = 10.0; ///< the box's sides beyond the open ends' disks
    /// The solver's parameters; spacing_mm (a third of the bore), void_fraction (0.2), reference_pressure_pa (5,332),
    /// sound_speed_m_s, end_time_s, free_surface (1), fluid_tension (0: the falling stream breaks up), cfl (0.1),
    /// wall_repulsion (0.01: the thesis's repelling walls) and gravity_* (along the vessel) are chosen unless
    /// `given` names them.
    ParameterSet parameters{sim::sph::sphParameters()};
    std::vector<std::string> given;
    int frames = 10;               ///< frames over the run, when the run control asks for none
    std::string backend = "auto";  ///< as BloodFlowSetup's
};

/// The injected blood at one frame (volumes at the rest density: particles x spacing^3).
struct InjectionFill
{
    double timeS = 0.0;
    double inVesselMl = 0.0;    ///< fluid not in the box (in the vessel or falling from it)
    double collectedMl = 0.0;   ///< fluid inside the collection box
    double frontMm = 0.0;       ///< the farthest fluid outside the box, along gravity from the needle's plane
};

struct InjectionRun
{
    SolverRun run;
    sim::sph::OpenBoundary needle;
    Eigen::Vector3d gravityDirection = Eigen::Vector3d::UnitZ(); ///< unit, patient frame
    Eigen::Vector3d boxLowMm = Eigen::Vector3d::Zero(), boxHighMm = Eigen::Vector3d::Zero(); ///< in gravity's frame
    Eigen::Matrix3d boxFrame = Eigen::Matrix3d::Identity(); ///< columns: two across gravity, gravity
    std::vector<int> openEnds;                              ///< the network's end nodes left open
    std::vector<InjectionFill> fill;                        ///< at every kept frame
    double firstCollectedS = -1.0; ///< the first frame with fluid in the box (-1: none)
    double vesselLengthMm = 0.0;   ///< along gravity, from the needle's plane to the vessel's lowest wall particle
    ParameterSet parameters{sim::sph::sphParameters()}; ///< as run
    std::vector<std::string> warnings;
    std::string backend = "cpu";
    std::string device;
};

/// The set-up as a form declares it (the workstation's Flow > Blood Flow Parameters, "Needle injection"):
/// needle_bore_mm, particles_per_s, box_depth_mm, box_margin_mm, spacing_mm and end_time_s (0: chosen), frames.
std::vector<ParameterSpec> injectionSetupParameters();
/// The solver parameters runInjection chooses unless `given` names them (InjectionSetup::parameters): its spacing,
/// sound speed, Courant number, tension, backstop, gravity, void fraction, gauge level and end time.
const std::vector<std::string>& injectionChosenParameters();
/// The set-up from that form and the solver's parameters: every solver parameter counts as given but those in
/// `automatic` (runInjection chooses them), a value equal to its default included; the form's spacing and end time
/// at 0 are chosen.
InjectionSetup injectionSetupFrom(const ParameterSet& form, const ParameterSet& solverParameters,
                                  const std::set<std::string>& automatic);

/// Runs the needle injection on the study's centerlines (their label's lumen) under `control` (without a frame
/// schedule: setup.frames over the end time). Throws vsim::Error for a study without the centerlines' label, a needle
/// node that is not an end, a network of fewer than two ends, a bore under two spacings, or what the seeding and the
/// solver refuse.
InjectionRun runInjection(const study::Study& study, const InjectionSetup& setup, sim::RunControl control,
                          const Progress& progress = {});

/// What the CLI prints and the run folder keeps (JSON text): the run status, the set-up, the fill over the frames,
/// the mass balance with its definitions and units.
std::string injectionDocument(const InjectionRun& injection, const InjectionSetup& setup);

/// Adds the run ("Needle injection (SPH)": a Run artifact of particle frames) with the fill's figures as attributes;
/// the study is not saved.
std::string addInjectionRun(study::Study& study, const InjectionRun& injection, const InjectionSetup& setup);

} // namespace vsim::app
