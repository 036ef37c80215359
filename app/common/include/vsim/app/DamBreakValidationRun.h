#pragma once

// `vascusim-cli validate sph-dambreak` (issue 18): SPHERIC benchmark 2 against MARIN's probes
// (sim/sph's DamBreakValidation.h) on the backend asked for. At its default million particles the case takes
// about 2 minutes on a GPU and about 20 hours on 2 CPU cores (2.4e5 particle-steps/s, RESULTS.md), so "auto"
// runs it only where there is a GPU.

#include "vsim/core/Progress.h"
#include "vsim/core/Validation.h"
#include "vsim/sim/sph/DamBreakValidation.h"

#include <string>

namespace vsim::app {

/// Runs the case on `backend`: "cuda" (refused without the GPU plugin or a device), "cpu", or "auto" (the GPU;
/// refused without one, saying how to run it on the CPU). Throws vsim::Error for those refusals, an unknown
/// backend or bad options.
ValidationResult validateDamBreak(const std::string& backend, const sim::sph::DamBreakCheckOptions& options,
                                  const Progress& progress);

/// Why a run of every case (`validate all|sph`) leaves the dam break out on `backend`: "" when it runs it (a GPU
/// for "auto"; any other name, so that "cpu" runs it and "cuda" without a GPU or an unknown name is refused).
std::string whyDamBreakLeftOut(const std::string& backend);

} // namespace vsim::app
