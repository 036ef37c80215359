#pragma once

// SPHERIC benchmark 2 as a validation case (issue 18's `sph-dambreak`): the dam break with the experiment's
// obstacle (DamBreak.h) run on any stepper of SphSolver's algorithm (the CPU's, or the GPU's through
// SphSolver::setStepper), the four probes read every 20 ms of simulated time (DamBreakProbes.h) against MARIN's
// record (Kleefsman et al. 2005). Shared by `vascusim-cli validate sph-dambreak` and the GPU benchmark
// tests/bench/bench_sph_cuda_dambreak.
//
// The tolerance is this project's own (modules/sim/sph/README.md: no SPH paper found gives one for these probes):
// each probe's RMS difference over the record within 10 % of the column's height (55 mm), each front's arrival
// (the first time its height passes 20 mm; H1-H3, H4 stands in the column) within 50 ms, and the run must cover
// the whole record (a run a guard stopped, or one asked to end earlier, never passes).

#include "vsim/core/Parameters.h"
#include "vsim/core/Progress.h"
#include "vsim/core/Validation.h"
#include "vsim/sim/sph/QuarticKernel.h"
#include "vsim/sim/sph/SphStepper.h"

#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace vsim::sim::sph {

constexpr double kDamBreakSampleS = 0.02;      ///< the probes' sampling interval (s), the record's
constexpr double kDamBreakArrivalM = 0.02;     ///< a front has arrived where the water stands this high (m)
constexpr double kDamBreakRmsToleranceM = 0.055; ///< 10 % of the column's 0.55 m
constexpr double kDamBreakArrivalToleranceS = 0.05;

struct DamBreakCheckOptions
{
    double particles = 1e6;        ///< about this many in all, walls included (DamBreak.h's damBreakCase)
    double untilS = 0.0;           ///< the run's end (s); 0: the record's end (1.02 s)
    double soundSpeedFactor = 20.0; ///< c0 = factor sqrt(g H) (DualSPHysics' CoefSound)
    std::vector<std::string> settings; ///< "parameter=value" after the case's own (SphSolver's parameters)
    /// Called at every sample with the particles and the time (s), after the probes read them: where a benchmark
    /// looks further (a map of the water's depth).
    std::function<void(const ParticleState&, const QuarticKernel&, double)> onSample;
};

/// One probe's two series at the run's samples, and what is compared.
struct DamBreakProbeSeries
{
    std::vector<double> simulatedM, measuredM;
    double rmsDifferenceM = 0.0;
    double arrivalS = -1.0, measuredArrivalS = -1.0; ///< -1: none by the run's end
};

/// What a run gave.
struct DamBreakCheck
{
    std::size_t particles = 0, wallParticles = 0;
    double spacingMm = 0.0;
    ParameterSet parameters;
    bool steppedElsewhere = false; ///< the stepper given (the GPU's) took the steps
    double endS = 0.0;             ///< where the run stopped (s)
    double recordEndS = 0.0;       ///< the record's last sample (s)
    long steps = 0;
    double steppingSeconds = 0.0;
    double largestDensityVariation = 0.0; ///< the largest |rho / rho0 - 1| over the fluid at the samples
    std::string guard;                    ///< why a guard stopped the run, or ""
    std::vector<double> timesS;
    std::array<DamBreakProbeSeries, 4> probes; ///< H1, H2, H3, H4
    bool withinTolerance() const;
};

/// SphSolver's parameters for the experiment's dam break at `spacingMm` (damBreakParameters and what a breaking
/// flow with an impact needs; DamBreakValidation.cpp gives each one's reason), run to `endS`.
ParameterSet damBreakCheckParameters(double spacingMm, double soundSpeedFactor, double endS);

/// Runs the dam break with the obstacle to the record's end (or options.untilS) on `stepper` (an empty factory:
/// the CPU) and compares the probes. A guard ends the run early (DamBreakCheck::guard). Progress by simulated time;
/// Cancel between steps (vsim::Cancelled). Throws vsim::Error for bad options.
DamBreakCheck runDamBreakCheck(const DamBreakCheckOptions& options, const SphStepperFactory& stepper,
                               const Progress& progress = {});

/// The check as validation figures: each probe's RMS difference, H1-H3's arrivals and the record covered.
ValidationResult damBreakValidation(const DamBreakCheck& check);

} // namespace vsim::sim::sph
