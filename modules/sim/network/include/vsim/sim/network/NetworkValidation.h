#pragma once

// The analytic validation cases of the drug network, shared by its tests and `vascusim-cli validate network`:
//  network-cylinder      the conical resistance with R1 = R2 equals Hagen-Poiseuille 8 mu L / (pi R^4) (1e-12)
//  network-cone          the closed form (eq. 6.6) against eq. 6.4 integrated numerically (1e-9)
//  network-conservation  Kirchhoff: flows balance at every junction of a seeded random tree of 2,000 segments
//                        (1e-12 of the injected flow) and the outlets drain what is injected
//  network-bifurcation   a tip segment splitting into two branches with terminal resistances into different
//                        pressures: flows and pressures equal the closed-form solution (1e-9)
//  network-confluence    a second inlet held at a pressure joining the injected branch before one outlet: the
//                        same (1e-9)
//  network-annulus       a catheter in a pipe: the annulus's Hagen-Poiseuille resistance (1e-12); a cone's panels
//  network-mixing        blood from the root, an injection at the tip and a second inlet at a confluence: flows
//                        and injected fractions against a hand-solved 3 x 3 system (1e-9)
//  network-two-phase-split  the injected mixture's viscosity shifts the split between the tip's branch and its
//                        sibling: flows against the closed form (1e-9), the shift itself to 1e-7 % points

#include "vsim/core/Progress.h"
#include "vsim/core/Validation.h"

#include <string>
#include <vector>

namespace vsim::sim::network {

/// The case names above, in order.
std::vector<std::string> networkValidationCases();
/// The solver settings the cases run with: the run's own direct (LDL^T) solve on the CPU.
ValidationConfiguration networkValidationConfiguration();
/// Runs one case. Throws vsim::Error for an unknown name (listing the known ones).
ValidationResult runNetworkValidation(const std::string& name, const Progress& progress = {});

} // namespace vsim::sim::network
