#pragma once

// The validation cases behind SphValidation.h, one file per kind: KernelCases.cpp (sph-kernel, sph-fpm),
// HydrostaticCase.cpp (sph-hydrostatic), PoiseuilleCase.cpp (sph-poiseuille), WomersleyCase.cpp (sph-womersley),
// MassCase.cpp (sph-mass), StenosisCase.cpp (sph-stenosis); the shared case builders in CaseSupport.cpp.

#include "vsim/core/Progress.h"
#include "vsim/core/Validation.h"
#include "vsim/sim/common/RunDriver.h"
#include "vsim/sim/sph/SphSolver.h"

#include <functional>
#include <string>

namespace vsim::sim::sph::detail {

/// The solver's parameters for a case: the lattice spacing (mm) and the fluid's density (kg/m^3), viscosity (Pa s)
/// and numerical sound speed (m/s); the rest at their defaults.
ParameterSet caseParameters(double spacingMm, double density, double viscosity, double soundSpeed);
/// Runs `particles` with `parameters` on the driver (frames to `control`'s sink only) and returns the run; throws
/// vsim::Error naming `caseName` when it did not run to its end.
SolverRun runCase(const std::string& caseName, SphSolver& solver, ParticleSet particles, const ParameterSet& parameters,
                  const Progress& progress, RunControl control = {});

/// A straight pipe along x on a lattice of the given spacing (points at (k + 1/2) spacings), fluid where the distance
/// from the axis r < R(x), wall particles out to R(x) + wallLayers spacings with their depths below the wall's
/// surface (their distance to the profile r = R(x)). The fluid fills 0 <= x < length; with a buffer depth > 0
/// the ends are open, each with its buffer of that depth (field "open_boundary": 1 behind x = 0, 2 beyond x = length;
/// the walls continue around them).
struct PipeShape
{
    double spacingMm = 0.1, lengthMm = 1.0, bufferDepthMm = 0.0;
    int wallLayers = 4;
    std::function<double(double xMm)> radiusMm;
};
ParticleSet pipeParticles(const PipeShape& shape);
/// The open ends of pipeParticles(): a velocity inlet at x = 0 with `flowRateM3S` (parabolic, ramped over `rampS`)
/// and a pressure outlet at x = length at 0 Pa, disks of radius `radiusMm`.
std::vector<OpenBoundary> pipeEnds(const PipeShape& shape, double radiusMm, double flowRateM3S, double rampS);

ValidationResult kernelCase();
ValidationResult fpmCase(const Progress& progress);
ValidationResult hydrostaticCase(const Progress& progress);
ValidationResult poiseuilleCase(const Progress& progress);
ValidationResult womersleyCase(const Progress& progress);
ValidationResult massCase(const Progress& progress);
ValidationResult stenosisCase(const Progress& progress);

} // namespace vsim::sim::sph::detail
