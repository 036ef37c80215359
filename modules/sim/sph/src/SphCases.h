#pragma once

// The validation cases behind SphValidation.h, one file per kind: KernelCases.cpp (sph-kernel, sph-fpm),
// HydrostaticCase.cpp (sph-hydrostatic), PoiseuilleCase.cpp (sph-poiseuille), WomersleyCase.cpp (sph-womersley).

#include "vsim/core/Progress.h"
#include "vsim/core/Validation.h"
#include "vsim/sim/common/RunDriver.h"
#include "vsim/sim/sph/SphSolver.h"

#include <string>

namespace vsim::sim::sph::detail {

/// The solver's parameters for a case: the lattice spacing (mm) and the fluid's density (kg/m^3), viscosity (Pa s)
/// and numerical sound speed (m/s); the rest at their defaults.
ParameterSet caseParameters(double spacingMm, double density, double viscosity, double soundSpeed);
/// Runs `particles` with `parameters` on the driver (frames to `control`'s sink only) and returns the run; throws
/// vsim::Error naming `caseName` when it did not run to its end.
SolverRun runCase(const std::string& caseName, SphSolver& solver, ParticleSet particles, const ParameterSet& parameters,
                  const Progress& progress, RunControl control = {});

ValidationResult kernelCase();
ValidationResult fpmCase(const Progress& progress);
ValidationResult hydrostaticCase(const Progress& progress);
ValidationResult poiseuilleCase(const Progress& progress);
ValidationResult womersleyCase(const Progress& progress);

} // namespace vsim::sim::sph::detail
