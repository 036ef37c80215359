#pragma once

#include "CliCommands.h"

namespace vsim::cli {

/// `validate <case|all>`: runs analytic validation cases of the solvers (fem-patch, fem-rotation, fem-cantilever,
/// fem-lame, fem-damping), prints each as JSON (figures, expected values, tolerances); exit 0 only when every
/// figure is within tolerance, 1 otherwise (naming the figures out of tolerance).
int validateSolvers(const Arguments& arguments, const Progress& progress);

} // namespace vsim::cli
