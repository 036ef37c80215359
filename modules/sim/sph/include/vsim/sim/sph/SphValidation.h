#pragma once

// The blood-flow solver's validation cases (issue 18), shared by its tests and `vascusim-cli validate sph`:
//  sph-kernel  the quartic kernel (QuarticKernel.h): its integral over space (Gauss-Legendre in r, to 1e-6),
//  W(2h) = 0,
//              dW/dr against a central difference of W, and the kernel's first moment on a particle lattice
//              at h = 2 spacings (sum_j V_j (x_j - x_i) grad_i W_ij = I within 0.5 %: the consistency the
//              pressure force relies on; at h = 1.3 spacings it is 5.7 % off, which is why the solver's
//              default is 2);
//  sph-fpm     the gradient of a linear field on jittered particles next to a wall (half the support cut
//  away), three
//              jitter seeds: the Finite Particle Method exact to 1e-8 relative, where plain SPH is off by
//              tens of percent (its error is reported beside it, and must be that large: the case shows the
//              difference).
// The flow cases (Poiseuille, Womersley, hydrostatic, mass, dam break, stenosis) come with the solver.

#include "vsim/core/Progress.h"
#include "vsim/core/Validation.h"

#include <string>
#include <vector>

namespace vsim::sim::sph {

std::vector<std::string> sphValidationCases();
/// Runs one case. Throws vsim::Error for an unknown name (listing the known ones).
ValidationResult runSphValidation(const std::string& name, const Progress& progress = {});

} // namespace vsim::sim::sph
