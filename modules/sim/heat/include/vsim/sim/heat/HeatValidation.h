#pragma once

// The template solver's validation case, shared by its test and `vascusim-cli validate heat`:
//  heat-decay  the slowest mode of a 20 mm cube (D 0.14 mm^2/s) after one decay time L^2 / (3 pi^2 D), run on the
//              run driver at 16, 32 and 64 cells: the relative L2 error against the exact solution (<= 0.5 % at 32
//              cells) and its observed order of convergence (2 for FTCS with dt ~ h^2, within 0.3).

#include "vsim/core/Progress.h"
#include "vsim/core/Validation.h"

#include <string>
#include <vector>

namespace vsim::sim::heat {

std::vector<std::string> heatValidationCases();
/// Runs one case. Throws vsim::Error for an unknown name (listing the known ones).
ValidationResult runHeatValidation(const std::string& name, const Progress& progress = {});

} // namespace vsim::sim::heat
