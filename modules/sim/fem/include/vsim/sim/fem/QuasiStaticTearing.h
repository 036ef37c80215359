#pragma once

// Tearing that does not depend on the ramp (issue 16 item 6): the pressure is raised in increments and the wall
// brought to static equilibrium at each (WallSimulation::equilibrate: Newton to `equilibriumTolerance`, no
// inertia or damping, so no lag behind the load). When an element's largest principal stress passes the tear
// strength, the onset pressure is bracketed by bisection between the last pressure without one and the first with
// one, each trial an equilibrium from the last state without, to `onsetTolerance` of the pressure. At the upper
// end of the bracket the most stressed element is released (detached, its separated nodes split) and the
// equilibrium solved again before the next release, one element at a time, until none is over its strength; then
// the ramp goes on. The dynamic protocol instead tears every element over the limit in the same step, after a
// damped lag that depends on the ramp rate (thesis ch. 4.6-4.7). The run ends at the ramp's end, when the fracture
// entropy passes `entropyEnd`, or when the torn wall holds no equilibrium at the pressure (it ruptures). The
// equilibria run on this CPU, or with the modified Newton iteration on the GPU (the element stresses, the releases
// and the bisection stay here: the same code decides on both).

#include "vsim/core/Progress.h"
#include "vsim/core/TetMesh.h"
#include "vsim/sim/fem/ElasticMaterial.h"
#include "vsim/sim/fem/FemRun.h"
#include "vsim/sim/fem/StaticSolver.h"

#include <functional>

namespace vsim::sim::fem {

struct QuasiStaticTearingSetup
{
    TetMesh wall;                 ///< mm; point fields "wall_layer" and "end_set"
    ElasticMaterial material;
    /// Which lumen faces carry the pressure (face centroid, mm); empty: all of them.
    std::function<bool(const Eigen::Vector3d& centroidMm)> loaded;
    double startPa = 0.0;         ///< the first pressure solved (the ramp's start)
    double endPa = 0.0;           ///< the ramp's end
    double incrementPa = 0.0;     ///< pressure step of the ramp (> 0)
    double tearStressPa = 0.0;    ///< largest principal stress that tears an element (> 0)
    double onsetTolerance = 0.005; ///< the onset bracket's width relative to the pressure
    double equilibriumTolerance = 1e-8;
    int equilibriumMaxUpdates = 30;
    double entropyEnd = 0.0;      ///< stop once the fracture entropy passes this (nats); 0: never
    int maxTears = 1000;          ///< elements released in all
    /// The equilibria by the modified Newton iteration with multigrid PCG instead of the full one
    /// (WallSimulation::setEquilibriumSolver), on this CPU or, with `equilibriumElsewhere`, on the GPU; it may take
    /// 5 x equilibriumMaxUpdates.
    bool modifiedNewton = false;
    StaticModelFactory equilibriumElsewhere;
};

/// Runs the setup. Throws vsim::Error for a bad setup or a mesh that is not a wall, vsim::Cancelled when
/// cancelled. Frames (as runFem's), converged equilibria only: the first, the onset's before any release, the one
/// after each pressure's releases, and the last the run reached (its pressure is final_pressure_kpa and the status's
/// reached pressure). Metrics as runFem's (peaks of the last frame) and
/// tear_onset_pressure_mpa (the bracket's upper end; -1 without a tear), tear_onset_bracket_mpa (its width),
/// first_torn_element (the wall mesh's index), torn_elements, fracture_entropy, equilibrium_solves and
/// failed_equilibria. The run status records the linear solves of the converged equilibria (the states the frames
/// show); a failed equilibrium leaves the state as it was. One that fails before any tear stops the run as a guard
/// (status and stopReason), one after a tear as the wall's rupture (an end condition), and one inside the
/// bisection keeps the bracket as it is.
FemRunResult runQuasiStaticTearing(const QuasiStaticTearingSetup& setup, const Progress& progress = {});

} // namespace vsim::sim::fem
