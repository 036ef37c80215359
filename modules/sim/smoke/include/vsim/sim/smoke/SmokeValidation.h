#pragma once

// The smoke solver's validation cases, shared by its test and `vascusim-cli validate <case>` (issue 21):
//  smoke-divergence    a random velocity field in a 1 m box with a solid sphere and an open top, projected on three
//                      seeds: the largest |div u| h / max |u| left (<= 1e-4) and the relative residual reached.
//  smoke-taylor-green  the Taylor-Green vortex in a free-slip box, inviscid: the effective numerical viscosity
//                      -(dE/dt) / integral |w|^2 of the plain scheme, with vorticity confinement and with vortex
//                      particles seeded from the initial vorticity; both must dissipate less than the plain
//                      scheme, and the energy must not grow.
//  smoke-mass          a buoyant puff of smoke in a closed box, 500 steps of MacCormack with the limiter: the smoke
//                      mass drift (no renormalisation) within 1 %.
//  smoke-ball          a ball falling through still air: no flow through the ball (the faces it touches move with
//                      it), the air divergence-free around it, and the air pushed aside.

#include "vsim/core/Progress.h"
#include "vsim/core/Validation.h"

#include <string>
#include <vector>

namespace vsim::sim::smoke {

std::vector<std::string> smokeValidationCases();
/// Runs one case. Throws vsim::Error for an unknown name (listing the known ones).
ValidationResult runSmokeValidation(const std::string& name, const Progress& progress = {});
/// The settings the cases run with, to set beside a reported run's.
ValidationConfiguration smokeValidationConfiguration();

} // namespace vsim::sim::smoke
