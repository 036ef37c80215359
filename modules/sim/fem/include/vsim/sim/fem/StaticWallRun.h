#pragma once

// The converged wall analysis (issue 16): the wall mesh's tets made quadratic (10 nodes), hyperelastic laws per
// element (the Raghavan-Vorp 2000 wall by default, Hyperelastic.h), ends held, the lumen pressure as a follower
// load on the 6-node lumen faces, applied in load increments (one by default; one that fails is retried at half
// the size), each solved to static equilibrium by Newton's method (consistent tangent + the pressure's load
// stiffness, each linear solve to 1e-8 by GMRES with a kept CHOLMOD or UMFPACK preconditioner, TangentSolver.h;
// the line search of Matthies & Strang 1979): intermediate increments to
// `intermediateTolerance`, the last to `tolerance` (||f_int - f_ext|| / ||f_ext||). The frames are
// the rest state and each increment's equilibrium, on the linear wall mesh (corner displacements, each element's
// mean Cauchy stress over its four quadrature points). The run status records every Newton update's linear
// solve and the final force residual. The unloaded reference is the imaged (loaded) geometry: CT shows the
// vessel at its pressure, so the figures overestimate the stretch a little (stated in the report).

#include "vsim/core/Progress.h"
#include "vsim/core/TetMesh.h"
#include "vsim/sim/fem/FemRun.h"
#include "vsim/sim/fem/Hyperelastic.h"
#include "vsim/sim/fem/StaticSolver.h"

#include <cstdint>
#include <vector>

namespace vsim::sim::fem {

/// A wall point field (Pa) added to the lumen pressure where the wall has it: each lumen face carries the pressure
/// plus the mean of its corners' values, all scaled by the load factor (a pressure that varies over the lumen, e.g.
/// a blood-flow run's time-averaged wall pressure: one-way coupling).
inline constexpr const char* kLumenExtraPressureField = "lumen_added_pressure_pa";

struct StaticWallSetup
{
    TetMesh wall; ///< mm; point fields wall_layer and end_set, and kLumenExtraPressureField where it has one
    std::vector<HyperelasticMaterial> materials;    ///< [0]: the wall, [1]: the thrombus (where elements have it)
    std::vector<std::uint8_t> elementMaterial;      ///< per tet, an index into materials; empty: all the wall
    double pressurePa = 0.0;
    int loadIncrements = 1;                         ///< first try; halved where one fails
    double tolerance = 1e-6;                        ///< the last increment's relative force residual
    double intermediateTolerance = 1e-3;
    int maxUpdatesPerIncrement = 15;                ///< Newton converges in 5-10 or not at all
    /// An increment whose line search takes a step under this fraction of the Newton step is given up and retried
    /// at half the size (StaticSolveSettings::stallStep; the largest seen in a converging solve was 0.26)
    double stallStep = 0.01;
    /// An increment whose first linear solve needs more GMRES iterations than this on the stand-in's Cholesky is
    /// given up and retried at half the size, while it can still be halved (StaticSolveSettings::firstSolveBudget;
    /// 0: never). Converging increments took 25-50.
    int firstSolveBudget = 100;
    /// Each Newton update's linear solve: GMRES to 1e-8 with a kept CHOLMOD preconditioner, or UMFPACK LU.
    LinearSolver linear = LinearSolver::CholeskyGmres;
    /// CholeskyGmres: the tangent's own Cholesky below this force residual (StaticSolveSettings; a negative value:
    /// the definite stand-in only, as before 2026-12-01, which bench_fem_static compares)
    double tangentCholeskyBelow = StaticSolveSettings{}.tangentCholeskyBelow;
};

/// The unloaded (zero-pressure) geometry by the backward displacement method (Bols et al. 2013, J Comput Appl Math
/// 246:10, "A computational method to assess the in vivo stresses and unloaded configuration of patient-specific
/// blood vessels"): the reference X is moved by the mismatch of its loaded shape with the image, X <- X - (x(X) -
/// x_image), each x(X) a full runStaticWall, until the largest mismatch is under `toleranceMm` or `maxIterations`
/// runs. The result is the last run's with the frames' points the imaged geometry (the displacement fields from the
/// unloaded reference) and metrics zero_pressure_iterations, zero_pressure_mismatch_mm (largest, at the end) and
/// zero_pressure_converged (0/1); a run that fails is returned as it is.
FemRunResult runStaticWallFromZeroPressure(const StaticWallSetup& setup, int maxIterations, double toleranceMm,
                                           const Progress& progress = {});

/// Runs the setup. Throws vsim::Error for a mesh that is not a wall or a bad material, vsim::Cancelled when
/// cancelled (progress follows the Newton updates). An increment that does not converge (or inverts every step)
/// even at 1/16 of the pressure stops the run as a guard with the last converged frame kept and the residual it
/// reached in the status. Metrics as runFem's (the peaks over the wall's elements, material 0), with element_order
/// 2, quadratic_nodes, thrombus_elements, load_increments (those converged), load_cutbacks, equilibrium_updates
/// and equilibrium_factorisations.
/// The frames carry the wall's "material" cell field when it has one.
FemRunResult runStaticWall(const StaticWallSetup& setup, const Progress& progress = {});

} // namespace vsim::sim::fem
