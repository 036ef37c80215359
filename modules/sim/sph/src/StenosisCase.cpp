// sph-stenosis: steady flow through a 50 % diameter stenosis (issue 18; the problem in StenosisPipe.h). R0 = 0.8 mm (8
// spacings of 0.1 mm), 5.6 mm long, the cosine narrowing over 1.6 mm about x = 2.4 mm; the parabolic inflow (mean 0.05
// m/s upstream, 0.2 m/s in the throat: Re 48 there in blood) ramped over 10 ms (more than a period of the pipe's
// quarter-wave mode, 4 L / c0 = 6.4 ms); the time step at the stenosis Courant number (kStenosisCfl, SphSolver.h).
// Sections every 0.2 mm are averaged from 15 to 25 ms; the throat is compared with the sections 1.6 mm (2 R0)
// upstream and downstream. The mean velocity ratio against the particles' own area ratio is the mass check (within
// 5 %); the area ratio against the analytic 4 checks the lattice's throat; the peak velocity ratio and the pressure
// drop are checked against OpenFOAM on the same problem by tests/bench/bench_sph_openfoam.

#include "SphCases.h"

#include "vsim/core/Error.h"
#include "vsim/core/StoredText.h"
#include "vsim/sim/sph/SphSolver.h"
#include "vsim/sim/sph/StenosisPipe.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vsim::sim::sph {
namespace {

constexpr double kRingStepMm = 0.05; // the wall rings' spacing along the axis
constexpr int kAround = 8;           // points on each ring

/// The pipe's lattice, walls and the two ends' buffers (a kernel support deep: four spacings at h = 2 spacings).
detail::PipeShape pipeShape(const StenosisPipe& pipe)
{
    detail::PipeShape shape;
    shape.spacingMm = pipe.spacingMm, shape.lengthMm = pipe.lengthMm;
    shape.bufferDepthMm = 2.0 * pipe.smoothingRatio * pipe.spacingMm;
    shape.radiusMm = [pipe](double xMm) { return pipe.radiusAtMm(xMm); };
    return shape;
}

} // namespace

StenosisPipe StenosisPipe::atFlow(double meanSpeed, double length) const
{
    if (!(meanSpeed > 0.0) || !(length >= throatAtMm + halfLengthMm + compareMm + 2.0 * sectionStepMm))
        throw Error(Pattern{"the stenosis pipe needs a mean speed > 0 and room for the sections past the throat "
                            "(length >= %1 mm)",
                            {std::to_string(throatAtMm + halfLengthMm + compareMm + 2.0 * sectionStepMm)}});
    StenosisPipe pipe = *this;
    pipe.soundSpeedMS = soundSpeedMS * meanSpeed / meanSpeedMS;
    pipe.meanSpeedMS = meanSpeed, pipe.lengthMm = length;
    pipe.rampS = rampS * (length / lengthMm) * (meanSpeedMS / meanSpeed); // the same number of quarter-wave periods
    const double jetTransitS = 1e-3 * (length - throatAtMm) / (4.0 * meanSpeed); // the throat's mean: 4 x (area ratio)
    pipe.averageFromS = pipe.rampS + 1.5 * jetTransitS, pipe.endTimeS = pipe.rampS + 2.5 * jetTransitS;
    pipe.cfl = stenosisCfl(pipe.throatReynolds(), cfl, throatReynolds());
    if (pipe.throatReynolds() > throatReynolds())
        pipe.wallRepulsion = std::max(wallRepulsion, 0.01);
    return pipe;
}

StenosisPipe StenosisPipe::pulsatile(double periodS, double amplitude) const
{
    if (!(periodS > 0.0) || !(amplitude >= 0.0 && amplitude < 1.0))
        throw Error(Pattern{"a pulsatile inflow needs a period > 0 s and an amplitude in [0, 1), not %1 s and %2",
                            {numberText(periodS), numberText(amplitude)}});
    const StenosisPipe peak = atFlow(meanSpeedMS * (1.0 + amplitude), lengthMm);
    StenosisPipe pipe = *this;
    pipe.soundSpeedMS = peak.soundSpeedMS, pipe.cfl = peak.cfl, pipe.wallRepulsion = peak.wallRepulsion;
    constexpr int kPieces = 64;
    pipe.inflowWaveform.points.clear();
    for (int k = 0; k <= kPieces; ++k)
        pipe.inflowWaveform.points.emplace_back(periodS * k / kPieces,
                                                1.0 + amplitude * std::sin(2.0 * std::numbers::pi * k / kPieces));
    pipe.averageFromS = periodS * std::ceil(averageFromS / periodS - 1e-9);
    pipe.endTimeS = pipe.averageFromS + periodS;
    pipe.systole = {periodS, 0.2 * periodS, 0.3 * periodS};
    return pipe;
}

double StenosisPipe::inflowFactor(double timeS) const
{
    return rampFactor(timeS, rampS) * inflowWaveform.factorAt(timeS);
}

double StenosisPipe::womersleyNumber() const
{
    const double period = inflowWaveform.period();
    return period > 0.0 ? 1e-3 * radiusMm * std::sqrt(2.0 * std::numbers::pi / period * densityKgM3 / viscosityPaS) : 0.0;
}

double StenosisPipe::throatReynolds() const
{
    return densityKgM3 * throatMeanSpeedMS() * 1e-3 * radiusMm / viscosityPaS; // the throat's diameter is R0
}

double StenosisPipe::radiusAtMm(double xMm) const
{
    const double u = (xMm - throatAtMm) / halfLengthMm;
    return std::abs(u) >= 1.0 ? radiusMm : radiusMm * (1.0 - 0.25 * (1.0 + std::cos(std::numbers::pi * u)));
}

std::vector<double> StenosisPipe::sectionArcsMm() const
{
    std::vector<double> arcs;
    for (double x = 2.0 * sectionStepMm; x <= lengthMm - 2.0 * sectionStepMm + 1e-9; x += sectionStepMm)
        arcs.push_back(x);
    return arcs;
}

double StenosisPipe::flowRateM3S() const
{
    return meanSpeedMS * std::numbers::pi * std::pow(1e-3 * radiusMm, 2);
}

std::vector<WallPoint> StenosisPipe::wallPoints(double stepMm, int around) const
{
    const std::vector<double> sections = sectionArcsMm();
    std::vector<WallPoint> points;
    for (double x = sections.front(); x <= sections.back() + 1e-9; x += stepMm)
    {
        // The surface r = R(x): its outward normal is (-R'(x), cos t, sin t) normalised.
        const double u = (x - throatAtMm) / halfLengthMm;
        const double slope = std::abs(u) >= 1.0 ? 0.0
                                                 : 0.25 * radiusMm * std::numbers::pi / halfLengthMm * std::sin(std::numbers::pi * u);
        for (int k = 0; k < around; ++k)
        {
            const double t = 2.0 * std::numbers::pi * k / around, r = radiusAtMm(x);
            const Eigen::Vector3d outward = Eigen::Vector3d(-slope, std::cos(t), std::sin(t)).normalized();
            points.push_back({1e-3 * Eigen::Vector3d(x, r * std::cos(t), r * std::sin(t)), -outward});
        }
    }
    return points;
}

ParameterSet stenosisPipeParameters(const StenosisPipe& pipe)
{
    ParameterSet parameters =
        detail::caseParameters(pipe.spacingMm, pipe.densityKgM3, pipe.viscosityPaS, pipe.soundSpeedMS);
    parameters.set("end_time_s", pipe.endTimeS);
    parameters.set("smoothing_ratio", pipe.smoothingRatio);
    parameters.set("cfl", pipe.cfl);
    parameters.set("particle_shifting", pipe.particleShifting);
    parameters.set("shifting_speed_m_s", pipe.particleShifting > 0.0 ? pipe.throatMeanSpeedMS() : 0.0);
    parameters.set("shift_correction", pipe.shiftCorrection ? 1.0 : 0.0);
    parameters.set("wall_repulsion", pipe.wallRepulsion);
    parameters.set("density_summation", pipe.densitySummation ? 1.0 : 0.0);
    parameters.set("density_relaxation_s", pipe.densityRelaxationS);
    return parameters;
}

ParticleSet stenosisPipeParticles(const StenosisPipe& pipe)
{
    return detail::pipeParticles(pipeShape(pipe));
}

void configureStenosisPipe(const StenosisPipe& pipe, SphSolver& solver, int sectionEvery, int wallEvery)
{
    std::vector<OpenBoundary> ends =
        detail::pipeEnds(pipeShape(pipe), pipe.radiusMm + 0.5 * pipe.spacingMm, pipe.flowRateM3S(), pipe.rampS);
    ends.front().waveform = pipe.inflowWaveform; // the inlet
    solver.setOpenBoundaries(std::move(ends));
    std::vector<CrossSection> sections;
    for (double x : pipe.sectionArcsMm())
        sections.push_back({Eigen::Vector3d(1e-3 * x, 0.0, 0.0), Eigen::Vector3d::UnitX(),
                            1e-3 * (pipe.radiusMm + pipe.spacingMm), 1e-3 * pipe.sectionThicknessMm()});
    solver.setSections(sections, pipe.averageFromS, sectionEvery);
    solver.setSectionsPhaseWindow(pipe.systole);
    solver.setWallPoints(pipe.wallPoints(kRingStepMm, kAround), pipe.averageFromS, wallEvery);
}

StenosisPipeFlow stenosisPipeFlow(const StenosisPipe& pipe, const SectionSeries& sections,
                                  const WallLoadSeries& wallLoads, std::map<std::string, double> metrics)
{
    StenosisPipeFlow flow;
    flow.arcMm = pipe.sectionArcsMm();
    flow.flows = sections.averages();
    flow.figures = stenosisFigures(flow.arcMm, flow.flows, pipe.compareMm);
    if (!pipe.systole.empty() && sections.phaseAveragedTime() > 0.0)
    {
        flow.systolicFlows = sections.phaseAverages();
        flow.systolicFigures = stenosisFigures(flow.arcMm, flow.systolicFlows, pipe.compareMm);
    }
    flow.metrics = std::move(metrics);
    const std::vector<WallLoadAverage> loads = wallLoads.averages();
    const std::vector<WallPoint>& points = wallLoads.points();
    double throatSum = 0.0;
    int throatRings = 0;
    for (std::size_t ring = 0; ring * kAround < loads.size(); ++ring)
    {
        double shear = 0.0, pressure = 0.0;
        for (std::size_t k = ring * kAround; k < (ring + 1) * kAround; ++k)
            shear += loads[k].tawssPa / kAround, pressure += loads[k].meanPressurePa / kAround;
        const double xMm = 1e3 * points[ring * kAround].positionM.x();
        flow.wallArcMm.push_back(xMm), flow.wallShearPa.push_back(shear), flow.wallPressurePa.push_back(pressure);
        if (std::abs(xMm - pipe.throatAtMm) <= 0.5 * pipe.sectionThicknessMm() + 1e-9)
            throatSum += shear, ++throatRings;
    }
    flow.throatWallShearPa = throatRings > 0 ? throatSum / throatRings : 0.0;
    return flow;
}

StenosisPipeFlow runStenosisPipe(const StenosisPipe& pipe, const Progress& progress)
{
    SphSolver solver;
    configureStenosisPipe(pipe, solver);
    const SolverRun run =
        detail::runCase("sph-stenosis", solver, stenosisPipeParticles(pipe), stenosisPipeParameters(pipe), progress);
    return stenosisPipeFlow(pipe, solver.sections(), solver.wallLoads(), run.metrics);
}

namespace detail {

ValidationResult stenosisCase(const Progress& progress)
{
    ValidationResult result;
    result.name = "sph-stenosis";
    const StenosisPipe pipe;
    const StenosisPipeFlow flow = runStenosisPipe(StenosisPipe{}, progress);
    const StenosisFigures& figures = flow.figures;
    const double analyticRatio = std::pow(pipe.radiusMm / pipe.radiusAtMm(pipe.throatAtMm), 2);
    result.figures.push_back({"throat's position (mm)", figures.throatArcMm, pipe.throatAtMm, pipe.sectionStepMm + 1e-9, "mm"});
    result.figures.push_back({"mean velocity ratio / the particles' area ratio (mass)", figures.meanRatio / figures.areaRatio, 1.0, 0.05, ""});
    result.figures.push_back({"throat flow rate / upstream flow rate", figures.flowRateRatio, 1.0, 0.05, ""});
    result.figures.push_back({"the particles' area ratio / analytic (4)", figures.areaRatio / analyticRatio, 1.0, 0.1, ""});
    result.figures.push_back({"largest density variation", flow.metrics.at("largest_density_variation"), 0.0, 0.02, ""});
    const SectionFlow &up = flow.flows[figures.upstream], &throat = flow.flows[figures.throat];
    // Two stored texts (a pattern holds nine values at most), read one by one where they are joined by "; ".
    result.description =
        storedText(Pattern{"50 % diameter cosine stenosis in a 1.6 mm pipe, 0.05 m/s mean inflow (Re 48 in the throat), "
                           "averaged 15-25 ms: peak velocity ratio %1 upstream (%2 -> %3 m/s), %4 downstream",
                           {numberText(figures.peakRatio), numberText(up.peakVelocityMS),
                            numberText(throat.peakVelocityMS), numberText(figures.peakRatioDownstream)}}) +
        "; " +
        storedText(Pattern{"mean ratio %1 (area ratio %2); pressure drop %3 Pa over 3.2 mm; throat wall shear stress "
                           "%4 Pa (TAWSS); %5 steps, %6 particles",
                           {numberText(figures.meanRatio), numberText(figures.areaRatio),
                            numberText(figures.pressureDropPa), numberText(flow.throatWallShearPa),
                            std::to_string(long(flow.metrics.at("steps"))),
                            std::to_string(long(flow.metrics.at("particles")))}});
    return result;
}

} // namespace detail
} // namespace vsim::sim::sph
