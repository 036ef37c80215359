#pragma once

// The analytic validation cases of the wall solver, shared by its tests and `vascusim-cli validate <case>`:
//  fem-patch       constant-strain patch test: a linear displacement on the boundary is reproduced inside (1e-8)
//  fem-rotation    a 90-degree rigid rotation produces no elastic force (co-rotation)
//  fem-cantilever  tip deflection of a clamped beam within 3 % of Timoshenko beam theory
//  fem-lame        thick-walled cylinder under internal pressure (plane strain, nu = 0.45): radial displacement
//                  within 2 %, hoop stress within 5 % of Lame's solution
//  fem-lame-quadratic  the same with quadratic (10-node) tets at nu = 0.49, where linear tets lock: radial
//                  displacement and every element's hoop stress within 2 % (mean; 5 % the worst element)
//  fem-damping     with Rayleigh damping and no load the total energy decays monotonically

#include "vsim/core/Progress.h"
#include "vsim/core/Validation.h"

#include <string>
#include <vector>

namespace vsim::sim::fem {

/// The case names above, in order.
std::vector<std::string> femValidationCases();
/// The solver settings the cases run with (CPU, static solves to 1e-8 or tighter with up to 20,000 PCG iterations).
ValidationConfiguration femValidationConfiguration();
/// Runs one case. Throws vsim::Error for an unknown name (listing the known ones).
ValidationResult runFemValidation(const std::string& name, const Progress& progress = {});

} // namespace vsim::sim::fem
