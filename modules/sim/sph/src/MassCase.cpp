// sph-mass: the open boundaries' mass ledger (issue 18). A pipe of radius 0.5 mm (5 spacings of 0.1 mm), 2 mm long,
// with a velocity inlet at one end (parabolic, 0.039 ml/s: a mean 0.05 m/s, Re 15 in blood, ramped over 3 ms) that
// lets in tracer particles (an injected drug), a pressure outlet at 0 Pa at the other, and walls that absorb the
// tracer within one spacing of their surface. After 6 ms: inflow - outflow - absorbed against the fluid's mass change
// (exact but for rounding: each particle's mass is counted once where it crosses), outflow and absorption both
// nonzero, and the mass the inlet let in (net of particles that drifted back into it) against the prescribed
// rho0 x integral of Q(t) dt (to the particle: the buffer particles, tracer too, enter whole).

#include "SphCases.h"

#include "vsim/core/Error.h"
#include "vsim/core/StoredText.h"
#include "vsim/sim/sph/SphSolver.h"

#include <cmath>
#include <numbers>

namespace vsim::sim::sph::detail {
namespace {

constexpr double kSpacingMm = 0.1, kRadiusMm = 0.5, kLengthMm = 2.0, kMeanSpeed = 0.05; // m/s
// The ramp spans about one period of the pipe's quarter-wave mode (4 L / c0 = 2.8 ms with the buffers): the flow
// through the pipe still rings at +-15 % at the end, which the ledger must account for all the same.
constexpr double kEndTimeS = 0.006, kRampS = 0.003, kSoundSpeed = 4.0, kDensity = 1060.0; // s, s, m/s, kg/m^3

} // namespace

ValidationResult massCase(const Progress& progress)
{
    ValidationResult result;
    result.name = "sph-mass";
    PipeShape shape;
    shape.spacingMm = kSpacingMm, shape.lengthMm = kLengthMm, shape.bufferDepthMm = 4.0 * kSpacingMm;
    shape.radiusMm = [](double) { return kRadiusMm; };
    const double flowRate = kMeanSpeed * std::numbers::pi * std::pow(1e-3 * kRadiusMm, 2); // m^3/s
    std::vector<OpenBoundary> ends = pipeEnds(shape, kRadiusMm + 0.5 * kSpacingMm, flowRate, kRampS);
    ends[0].tracer = true;
    ParameterSet parameters = caseParameters(kSpacingMm, kDensity, 3.5e-3, kSoundSpeed);
    parameters.set("end_time_s", kEndTimeS);
    parameters.set("absorption_distance_mm", kSpacingMm);
    SphSolver solver;
    solver.setOpenBoundaries(ends);
    const SolverRun run = runCase(result.name, solver, pipeParticles(shape), parameters, progress);

    const MassLedger& ledger = solver.massLedger();
    const double change = run.metrics.at("fluid_mass_change_kg");
    const double inflow = double(ledger.totalInflow()), outflow = double(ledger.totalOutflow());
    const double absorbed = double(ledger.absorbedKg);
    const double imbalance = std::abs(double(ledger.totalInflow() - ledger.totalOutflow() - ledger.absorbedKg) - change);
    const double prescribed = kDensity * flowRate * (0.5 * kRampS + (kEndTimeS - kRampS)); // the cosine ramp's mean is 1/2
    const double netInlet = double(ledger.inflowKg[0] - ledger.outflowKg[0]);
    result.figures.push_back({"|inflow - outflow - absorbed - mass change| / inflow", imbalance / inflow, 0.0, 1e-12, ""});
    result.figures.push_back({"outflow / inflow (nonzero)", outflow / inflow, 1.0, 0.5, ""});
    result.figures.push_back({"absorbed / inflow (nonzero)", absorbed / inflow, 0.1, 0.099, ""});
    // The inlet lets in whole particles: each of its 78 columns gains or loses up to half a particle against its share
    // of the integral (about 180 particles in all), hence the tolerance.
    result.figures.push_back({"inlet's net mass / rho0 x integral of Q dt", netInlet / prescribed, 1.0, 0.08, ""});
    result.figures.push_back({"largest density variation", run.metrics.at("largest_density_variation"), 0.0, 0.01, ""});
    result.description = storedText(Pattern{
        "pipe 1 mm across, 2 mm long, velocity inlet (parabolic, mean 0.05 m/s, tracer) and pressure outlet, tracer "
        "absorbed within 0.1 mm of the wall, 6 ms: inflow %1 ug, outflow %2 ug, absorbed %3 ug, mass change %4 ug (%5 "
        "steps)",
        {numberText(1e9 * inflow), numberText(1e9 * outflow), numberText(1e9 * absorbed), numberText(1e9 * change),
         std::to_string(long(run.metrics.at("steps")))}});
    return result;
}

} // namespace vsim::sim::sph::detail
