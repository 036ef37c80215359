#pragma once

// The run driver of the wall solver: a vessel wall (TetMesh in mm, as mesh::buildWallMesh makes it) under a
// lumen pressure curve, stepped by WallSimulation (ends fixed, backward Euler, optional tearing) until the curve
// ends, a guard stops it (NaN, inverted elements, PCG breakdown: the last good frame is kept) or the fracture
// entropy passes its end value; frames every N steps. SI inside, mm / kPa in the frames.

#include "vsim/core/Progress.h"
#include "vsim/core/RunStatus.h"
#include "vsim/core/SolverRun.h"
#include "vsim/core/TetMesh.h"
#include "vsim/sim/fem/BackwardEuler.h"
#include "vsim/sim/fem/ElasticMaterial.h"
#include "vsim/sim/fem/ImplicitStepper.h"

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace vsim::sim::fem {

struct FemRunSetup
{
    TetMesh wall;                                 ///< mm; point fields "wall_layer" and "end_set"
    ElasticMaterial material;
    BackwardEulerSettings integrator;
    /// Lumen pressure (Pa) over time (s).
    std::function<double(double timeS)> pressurePa;
    /// Which lumen faces carry the pressure (face centroid, mm); empty: all of them.
    std::function<bool(const Eigen::Vector3d& centroidMm)> loaded;
    int steps = 100;
    int frameEvery = 20;
    bool tearing = false;
    double tearStressPa = 0.0;     ///< largest principal stress that tears an element
    double entropyEnd = 0.0;       ///< stop once the fracture entropy passes this (nats); 0: never
    StepperFactory stepper;        ///< where the implicit steps run (the CUDA backend); empty: this CPU
    /// > 0: the damped steps are only the load path; at the end the static equilibrium at the final pressure is
    /// solved to this relative force residual (WallSimulation::equilibrate) and the last frame is that state. The
    /// run status then records the equilibrium's linear solves and force residual, and the path's capped
    /// conjugate-gradient steps go to the metrics as path_* (a fixed budget, not the figures' convergence).
    double equilibriumTolerance = 0.0;
    int equilibriumMaxUpdates = 50;
};

struct FemRunResult
{
    /// Frames in mm with point fields displacement_x/y/z_mm, displacement_mm and cell fields von_mises_kpa,
    /// max_principal_kpa; each frame has its own mesh (tearing splits nodes). Frame attributes: time and pressure.
    std::vector<TetMesh> frames;
    std::vector<double> frameTimesS, framePressuresPa;
    std::map<std::string, double> metrics;
    std::vector<std::pair<double, double>> entropyCurve; ///< (pressure Pa, entropy) after each tear
    std::string stopReason;                              ///< why the run ended early, empty when it ran through
    /// Every implicit step's PCG solve (iterations, relative residual against the tolerance), how the run stopped
    /// and the pressure it reached (kPa) against the curve's end; its metrics() are in `metrics` too.
    RunStatus status;
    /// Per implicit step, in order: the PCG iterations and the final relative residual of its solve.
    std::vector<int> stepIterations;
    std::vector<double> stepResiduals;
    /// The relative force residual before each equilibrium update and at the end (empty without one).
    std::vector<double> equilibriumResiduals;
    /// The run driver's record of the run (axis, which frames it kept at which step and position, provenance); its
    /// frames hold no data (that is `frames`): runOf() puts them together.
    SolverRun record;
};

/// The run as the study keeps it (a Run artifact): the record with the frames, the status and the metrics. A
/// result without a driver record (quasi-static tearing) gets one frame per pressure on the pressure axis.
SolverRun runOf(const FemRunResult& result);

/// The last frame's peaks as metrics: peak_von_mises_kpa and its element's centroid peak_von_mises_{x,y,z}_mm,
/// peak_max_principal_kpa, max_displacement_mm; over the elements `counted` marks (empty: all; the wall, not the
/// thrombus).
void addPeakMetrics(FemRunResult& result, const std::vector<std::uint8_t>& counted = {});

/// Runs the setup. Throws vsim::Error for a mesh that is not a wall (fields missing, no fixed end, no lumen face)
/// and vsim::Cancelled when cancelled; a run that a guard stops returns normally with `stopReason` set.
FemRunResult runFem(const FemRunSetup& setup, const Progress& progress = {});

} // namespace vsim::sim::fem
