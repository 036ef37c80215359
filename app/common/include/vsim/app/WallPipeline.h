#pragma once

// The wall-mechanics steps as the CLI and the workstation both run them: the wall mesh of a study's vessel label
// and centerlines, and a wall run added to the study, each with its provenance.

#include "vsim/viz/Callout.h"
#include "vsim/core/Parameters.h"
#include "vsim/core/Progress.h"
#include "vsim/mesh/WallBoundary.h"
#include "vsim/mesh/WallMesh.h"
#include "vsim/sim/fem/FemRun.h"
#include "vsim/sim/fem/StaticSolver.h"
#include "vsim/study/Study.h"

#include <string>

namespace vsim::app {

/// The wall mesh's parameters: thickness_mm (1.5) and target_vertices (3,000).
std::vector<ParameterSpec> wallMeshParameters();

struct WallMeshBuild
{
    mesh::WallMesh wall;
    std::size_t lumenVertices = 0;
    double remeshEdgeMm = 0.0;
    double smallestSurfaceAngleDeg = 0.0;
};

/// Lumen surface of `label` decimated to `targetVertices`, remeshed (edges of the budget, 0.8 of the local radius
/// in thin vessels), and the wall of `thicknessMm` opened at the centerline ends; with the AAA sac's labels
/// (`sacLabels`: 1 lumen, 4 thrombus, 5 wall) the intraluminal thrombus as its own layer inside the sac.
WallMeshBuild buildWallMesh(const LabelVolume& label, const SkeletonGraph& centerlines, double thicknessMm,
                            double targetVertices, const Progress& progress = {}, const LabelVolume* sacLabels = nullptr);

/// A thin "cloth-type" sheet (thesis ch. 4.7.3: 0.5 mm; 5 / 20 / 100 MPa) of width x length mm in the x-y plane,
/// `cellMm` cells, one element layer of `thicknessMm`, as a wall: the lower face is the loaded side (wall_layer
/// 0), the two edges across x are fixed (end sets 1 and 2).
TetMesh clothSheet(double widthMm, double lengthMm, double thicknessMm, double cellMm);

/// A tetrahedral mesh from outside (mm) made usable as a wall: a VascuSim wall (wall_layer and end_set fields) is
/// kept as it is when nothing is selected; otherwise the pressure faces and held nodes are marked as `selection`
/// says (mesh::markWallBoundary). Throws vsim::Error naming the options when a mesh without wall fields comes with
/// no selection, and when no face or node results.
mesh::MarkedWall asWall(TetMesh mesh, const mesh::WallBoundarySelection& selection);

/// Adds the wall to the study (provenance: label and centerlines, thickness, budget; quality as attributes);
/// returns its id. The study is not saved.
std::string addWallMesh(study::Study& study, const WallMeshBuild& build, const std::string& labelId,
                        const std::string& centerlinesId, double thicknessMm, double targetVertices,
                        const std::string& sacId = {});

/// Where a wall run's implicit steps run.
struct WallBackend
{
    std::string name = "cpu";         ///< "cpu" or "cuda", as recorded in the provenance
    std::string device;               ///< the GPU, for "cuda"
    sim::fem::StepperFactory stepper; ///< empty for the CPU
    sim::fem::StaticModelFactory staticModel; ///< the quasi-static tearing's equilibria; empty for the CPU
};

/// The sac's PWS and PWRI nodal maxima of a physiological run artifact as callouts for 3D pictures: "PWS 242 kPa,
/// 4.04 h (posterior)" (3 to 9 o'clock seen from the feet is the far side from the front); none without the sac's
/// figures.
std::vector<viz::Callout> sacPeakCallouts(const study::Artifact& run);

/// Resolves `requested` for `protocol`: "cpu"; "cuda" (throws vsim::Error when the GPU plugin is not installed,
/// there is no device, the run is the quadratic hyperelastic wall, or the material model is not the co-rotational
/// one); "auto": the GPU when "cuda" would work, else the CPU.
WallBackend chooseWallBackend(const std::string& requested, const std::string& protocol, const ParameterSet& parameters);

/// Runs `protocol` ("thesis-rupture" or "physiological") on the wall artifact `wallId` (centerlines needed by the
/// physiological protocol) on `backend`. With flow_wall_pressure 1 the lumen also carries the study's newest
/// blood-flow wall pressure (FlowWallPressure.h): the run's record names that artifact as its input
/// kFlowWallLoadsInput, and metrics flow_pressure_lumen_points, flow_pressure_covered_share and
/// flow_pressure_min_pa / _max_pa (the pressure added, relative to the flow's outlets) say what it carried.
/// Throws vsim::Error for an unknown protocol.
sim::fem::FemRunResult runWallProtocol(const study::Study& study, const std::string& protocol, const std::string& wallId,
                                       const std::string& centerlinesId, const ParameterSet& parameters,
                                       const WallBackend& backend = {}, const Progress& progress = {});

/// The run record's input naming the blood flow's wall loads a coupled run carried.
inline constexpr const char* kFlowWallLoadsInput = "flow_wall_loads";
/// Below this share of the lumen reached by the flow's wall pressure, the run says so (addWallRun's warnings).
inline constexpr double kFlowPressureCoveredWarning = 0.95;

/// Adds a run to the study: its last frame ("Wall stress (protocol)", metrics as attributes, warnings and an early
/// stop as warnings, the backend in the provenance) and the whole run ("Wall run (protocol)", a Run artifact with
/// the same provenance; the stress artifact's attribute run_artifact names it). The study is not saved.
struct WallRunIds
{
    std::string stress; ///< the last frame with its metrics ("Wall stress (<protocol>)"): the report's
    std::string run;    ///< the whole run (a Run artifact: every frame, the record), for the player and ParaView
};
WallRunIds addWallRun(study::Study& study, const sim::fem::FemRunResult& run, const std::string& protocol,
                      const std::string& wallId, const std::string& centerlinesId, const ParameterSet& parameters,
                      const WallBackend& backend = {});

/// The boundary of a run frame (mm) with the cell field `cellField` carried to its points (mean over the
/// boundary faces around each point), for colouring.
TriangleMesh frameSurface(const TetMesh& frame, const std::string& cellField);

} // namespace vsim::app
