// sph-stenosis: steady flow through a 50 % diameter stenosis (issue 18). A rigid pipe of radius R0 = 0.8 mm (8 spacings
// of 0.1 mm), 5.6 mm long, narrowed by a cosine stenosis R(x) = R0 (1 - 0.25 (1 + cos(pi (x - 2.4 mm) / 0.8 mm)))
// over 1.6 mm (the throat R0 / 2, area ratio 4), a parabolic velocity inlet (mean 0.05 m/s upstream, 0.2 m/s in the
// throat: Re 48 there in blood), ramped over 10 ms (more than a period of the pipe's quarter-wave mode, 4 L / c0 =
// 6.4 ms), and a pressure outlet; the time step at the stenosis Courant number (kStenosisCfl, SphSolver.h). Sections
// every 0.2 mm are averaged from 15 to 25 ms; the throat is compared with the sections 1.6 mm (2 R0) upstream and
// downstream. The mean velocity ratio against the particles' own area ratio is the mass check (within 5 %); the area
// ratio against the analytic 4 checks the lattice's throat; the peak velocity ratio and the pressure drop are printed
// for the OpenFOAM comparison (tests/bench).

#include "SphCases.h"

#include "vsim/core/Error.h"
#include "vsim/sim/sph/SphSolver.h"
#include "vsim/sim/sph/StenosisFigures.h"

#include <cmath>
#include <numbers>

namespace vsim::sim::sph::detail {
namespace {

constexpr double kSpacingMm = 0.1, kRadiusMm = 0.8, kLengthMm = 5.6, kThroatAtMm = 2.4, kHalfLengthMm = 0.8;
constexpr double kMeanSpeed = 0.05, kSoundSpeed = 4.0, kRampS = 0.010, kAverageFromS = 0.015, kEndTimeS = 0.025;
constexpr double kCompareMm = 1.6, kSectionStepMm = 0.2;

double stenosisRadiusMm(double xMm)
{
    const double u = (xMm - kThroatAtMm) / kHalfLengthMm;
    return std::abs(u) >= 1.0 ? kRadiusMm : kRadiusMm * (1.0 - 0.25 * (1.0 + std::cos(std::numbers::pi * u)));
}

} // namespace

ValidationResult stenosisCase(const Progress& progress)
{
    ValidationResult result;
    result.name = "sph-stenosis";
    PipeShape shape;
    shape.spacingMm = kSpacingMm, shape.lengthMm = kLengthMm, shape.bufferDepthMm = 4.0 * kSpacingMm;
    shape.radiusMm = stenosisRadiusMm;
    const double flowRate = kMeanSpeed * std::numbers::pi * std::pow(1e-3 * kRadiusMm, 2); // m^3/s
    ParameterSet parameters = caseParameters(kSpacingMm, 1060.0, 3.5e-3, kSoundSpeed);
    parameters.set("end_time_s", kEndTimeS);
    parameters.set("cfl", kStenosisCfl);
    SphSolver solver;
    solver.setOpenBoundaries(pipeEnds(shape, kRadiusMm + 0.5 * kSpacingMm, flowRate, kRampS));
    std::vector<CrossSection> sections;
    std::vector<double> arcMm;
    for (double x = 2.0 * kSectionStepMm; x <= kLengthMm - 2.0 * kSectionStepMm + 1e-9; x += kSectionStepMm)
    {
        sections.push_back({Eigen::Vector3d(1e-3 * x, 0.0, 0.0), Eigen::Vector3d::UnitX(), 1e-3 * (kRadiusMm + kSpacingMm),
                            2e-3 * kSpacingMm});
        arcMm.push_back(x);
    }
    solver.setSections(sections, kAverageFromS);
    const SolverRun run = runCase(result.name, solver, pipeParticles(shape), parameters, progress);

    const std::vector<SectionFlow> flows = solver.sections().averages();
    const StenosisFigures figures = stenosisFigures(arcMm, flows, kCompareMm);
    const double analyticRatio = std::pow(kRadiusMm / stenosisRadiusMm(kThroatAtMm), 2);
    result.figures.push_back({"throat's position (mm)", figures.throatArcMm, kThroatAtMm, 0.2 + 1e-9, "mm"});
    result.figures.push_back({"mean velocity ratio / the particles' area ratio (mass)", figures.meanRatio / figures.areaRatio, 1.0, 0.05, ""});
    result.figures.push_back({"throat flow rate / upstream flow rate", figures.flowRateRatio, 1.0, 0.05, ""});
    result.figures.push_back({"the particles' area ratio / analytic (4)", figures.areaRatio / analyticRatio, 1.0, 0.1, ""});
    result.figures.push_back({"largest density variation", run.metrics.at("largest_density_variation"), 0.0, 0.02, ""});
    const SectionFlow &up = flows[figures.upstream], &throat = flows[figures.throat];
    result.description =
        "50 % diameter cosine stenosis in a 1.6 mm pipe, 0.05 m/s mean inflow (Re 48 in the throat), averaged 15-25 ms: "
        "peak velocity ratio " + numberText(figures.peakRatio) + " upstream (" + numberText(up.peakVelocityMS) + " -> " +
        numberText(throat.peakVelocityMS) + " m/s), " + numberText(figures.peakRatioDownstream) +
        " downstream; mean ratio " + numberText(figures.meanRatio) + " (area ratio " + numberText(figures.areaRatio) +
        "); pressure drop " + numberText(figures.pressureDropPa) + " Pa over 3.2 mm; " +
        std::to_string(long(run.metrics.at("steps"))) + " steps, " +
        std::to_string(long(run.metrics.at("particles"))) + " particles";
    return result;
}

} // namespace vsim::sim::sph::detail
