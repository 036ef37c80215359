#pragma once

// The OpenFOAM side of the blood-flow cross-check (issue 18, bench_sph_openfoam): the sph-stenosis problem
// (StenosisPipe.h) as an axisymmetric OpenFOAM v1912 case (Debian package `openfoam`; `scripts/install-deps.sh
// --bench`): a 5-degree wedge about the pipe's axis, one blockMesh block whose wall edges follow R(x) through a
// polyLine at every axial cell, cells graded towards the wall; the parabolic inflow written face by face from the
// inlet's face centres, a pressure outlet at 0, no slip on the wall; simpleFoam (steady, laminar, Newtonian),
// SIMPLEC to a pressure residual of 1e-11, second-order (linear) convection; or, transient, pimpleFoam from rest
// with the SPH's ramped inflow (the parabola at the face centres, 40 steps of the ramp, linear between them:
// constant/boundaryData) at a Courant number of 0.5, backward differences in time, the fields averaged over the
// SPH's window (fieldAverage); a pulsatile inflow (StenosisPipe::pulsatile) likewise, its fields also written 40 times a
// cycle, of which those in the systole give the systolic sections (the trapezoid rule over them), and run one cycle
// past the SPH's end (the averages stop at it), whose systole shows how periodic the flow has become. Its cells are then read back into the SPH's section definitions (CrossSections.h):
// each section a slab of the same thickness, its peak the mean of the fastest 5 % of the slab's volume, its
// pressure the volume mean. The wall shear stress is OpenFOAM's wallShearStress function object times the density
// (transient: the time average of its magnitude, the TAWSS).

#include "vsim/sim/sph/StenosisPipe.h"

#include <filesystem>
#include <string>
#include <vector>

namespace vsim::bench {

struct OpenFoamMesh
{
    int axialCells = 224, radialCells = 32;
    double wallGrading = 0.4;  ///< the last radial cell's size / the first's (towards the wall)
    double wedgeDegrees = 5.0;
    /// Classic SIMPLE (U relaxed 0.7, p 0.3) in place of SIMPLEC (consistent, U 0.9, p 1): slower, but it settles
    /// where SIMPLEC swings (the fine wedge at a throat Re of 97: the pressure residual 0.15-0.68 for 836 iterations).
    bool classicSimple = false;
    /// pimpleFoam from rest through the SPH's run (its inflow ramp, then steady), the fields averaged over the SPH's
    /// window (StenosisPipe::averageFromS to endTimeS) in place of simpleFoam's steady state: whether the flow has
    /// settled in that window (the jet's recovery downstream is viscous, R0^2 / nu = 0.19 s at a throat Re of 97).
    bool transient = false;
};

struct OpenFoamStenosisFlow
{
    std::vector<sim::sph::SectionFlow> sections; ///< at StenosisPipe::sectionArcsMm(); areas: the lumen's
    sim::sph::StenosisFigures figures;
    std::vector<double> wallArcMm, wallShearPa; ///< each wall face's axial position and |tau_w|
    double throatWallShearPa = 0.0;             ///< |tau_w| averaged over the wall faces in the throat's slab
    /// Pulsatile: the sections over the averaged cycle's systole and their figures, and the figures of the next
    /// cycle's systole (OpenFOAM runs one cycle past the SPH's end: how periodic the flow has become).
    std::vector<sim::sph::SectionFlow> systolicSections;
    sim::sph::StenosisFigures systolicFigures, nextSystolicFigures;
    double inletFlowRateM3S = 0.0;              ///< the discrete inflow (the parabola sampled at the face centres)
    int cells = 0, iterations = 0; ///< SIMPLE iterations; transient: time steps
    /// The last SIMPLE iteration's initial pressure residual; transient: the largest over the time steps' last
    /// pressure corrections, each of which solves to 1e-10 absolute.
    double pressureResidual = 0.0;
    bool converged = false; ///< simpleFoam stopped at its residual control; transient: pimpleFoam reached the end
    double seconds = 0.0;          ///< blockMesh + simpleFoam + the field writers (when it was solved)
    bool reused = false;           ///< read from the same case solved before in its folder
};

/// Writes and runs the case in `directory` (created; a directory that exists must hold an earlier case of this
/// bench, marked by its file VASCUSIM-OPENFOAM-CASE, and is then replaced), or reads the solution there again when
/// that earlier run solved the same case (the same pipe, flow and mesh; another spacing reads it through other
/// sections). Throws vsim::Error when a step fails, naming its log.
OpenFoamStenosisFlow runOpenFoamStenosis(const sim::sph::StenosisPipe& pipe, const OpenFoamMesh& mesh,
                                         const std::filesystem::path& directory);

} // namespace vsim::bench
