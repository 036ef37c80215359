#pragma once

// The validation cases behind SphValidation.h, one file per kind: KernelCases.cpp (sph-kernel, sph-fpm),
// HydrostaticCase.cpp (sph-hydrostatic), PoiseuilleCase.cpp (sph-poiseuille), WomersleyCase.cpp (sph-womersley).

#include "vsim/core/Progress.h"
#include "vsim/core/Validation.h"

namespace vsim::sim::sph::detail {

ValidationResult kernelCase();
ValidationResult fpmCase(const Progress& progress);
ValidationResult hydrostaticCase(const Progress& progress);
ValidationResult poiseuilleCase(const Progress& progress);
ValidationResult womersleyCase(const Progress& progress);

} // namespace vsim::sim::sph::detail
