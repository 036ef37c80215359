// sph-womersley: pulsatile flow in a rigid pipe (issue 18; Womersley 1955). A pipe of radius R = 10 particle
// spacings (0.1 mm) in four layers of wall particles with their exact depths r - R, periodic along its axis, driven
// from rest by the oscillating body force A cos(omega t) (a pressure gradient) at Womersley numbers
// alpha = R sqrt(omega / nu) 4 and 8. Over the last of three (alpha 4: four) cycles, the velocity of the particles
// next to the axis is fitted with c + a cos + b sin, and its amplitude and phase are compared with the exact
// solution u(r, t) = Re{A / (i omega) [1 - J0(i^3/2 alpha r / R) / J0(i^3/2 alpha)] e^(i omega t)} at the same
// particles' radii.

#include "SphCases.h"

#include "vsim/core/Error.h"
#include "vsim/core/StoredText.h"
#include "vsim/sim/common/RunDriver.h"
#include "vsim/sim/sph/SphSolver.h"

#include <Eigen/Dense>

#include <cmath>
#include <complex>
#include <numbers>

namespace vsim::sim::sph::detail {
namespace {

using Complex = std::complex<double>;

constexpr int kRadius = 10, kLength = 12, kWallLayers = 4; // spacings
constexpr double kSpacingMm = 0.1, kDensity = 1000.0, kViscosity = 0.1, kPeakSpeed = 0.1; // Pa s, m/s

/// J0 by its power series (|z| <= 12 here: 60 terms reach double precision).
Complex besselJ0(Complex z)
{
    Complex term = 1.0, sum = 1.0;
    const Complex quarter = -0.25 * z * z;
    for (int k = 1; k < 60; ++k)
    {
        term *= quarter / double(k * k);
        sum += term;
    }
    return sum;
}

/// The exact velocity's complex amplitude at radius r (m) per unit body-force amplitude.
Complex womersleyAmplitude(double r, double radius, double omega, double alpha)
{
    const Complex k = std::polar(1.0, 0.75 * std::numbers::pi) * alpha / radius; // i^(3/2) alpha / R
    return 1.0 / Complex(0.0, omega) * (1.0 - besselJ0(k * r) / besselJ0(k * radius));
}

ParticleSet pipe()
{
    PipeShape shape;
    shape.spacingMm = kSpacingMm, shape.lengthMm = kLength * kSpacingMm, shape.wallLayers = kWallLayers;
    shape.radiusMm = [](double) { return kRadius * kSpacingMm; };
    return pipeParticles(shape);
}

struct Harmonic
{
    double amplitude = 0.0, phase = 0.0; ///< of c + amplitude cos(omega t + phase)
};

Harmonic fit(const std::vector<double>& times, const std::vector<double>& values, double omega)
{
    Eigen::MatrixXd basis(Eigen::Index(times.size()), 3);
    Eigen::VectorXd rhs(Eigen::Index(times.size()));
    for (std::size_t s = 0; s < times.size(); ++s)
    {
        basis.row(Eigen::Index(s)) << 1.0, std::cos(omega * times[s]), std::sin(omega * times[s]);
        rhs[Eigen::Index(s)] = values[s];
    }
    const Eigen::Vector3d c = basis.colPivHouseholderQr().solve(rhs);
    return {std::hypot(c[1], c[2]), std::atan2(-c[2], c[1])};
}

struct WomersleyErrors
{
    double amplitudeRatio = 0.0, phaseErrorCycles = 0.0;
    long steps = 0;
};

WomersleyErrors runWomersley(double alpha, int cycles, const Progress& progress)
{
    const double radius = kRadius * kSpacingMm * 1e-3, nu = kViscosity / kDensity;
    const double omega = alpha * alpha * nu / (radius * radius), period = 2.0 * std::numbers::pi / omega;
    const double force = kPeakSpeed / std::abs(womersleyAmplitude(0.0, radius, omega, alpha)); // m/s^2
    ParameterSet parameters = caseParameters(kSpacingMm, kDensity, kViscosity, 10.0 * kPeakSpeed);
    parameters.set("periodic_x_mm", kLength * kSpacingMm);
    parameters.set("end_time_s", cycles * period);
    parameters.set("body_force_x_m_s2", force);
    parameters.set("body_force_frequency_hz", omega / (2.0 * std::numbers::pi));
    // The particles next to the axis, their velocity over the last cycle and the exact one at their radii.
    std::vector<double> times, measured, exact;
    RunControl control;
    control.frameEverySteps = 1;
    control.frameSink = [&](const RunFrame& frame) {
        if (frame.position < (cycles - 1) * period)
            return;
        const ParticleSet& particles = std::get<ParticleSet>(frame.data);
        double sum = 0.0, exactSum = 0.0;
        int count = 0;
        for (std::size_t i = 0; i < particles.size(); ++i)
        {
            const double r = 1e-3 * std::hypot(particles.positionsMm[i].y(), particles.positionsMm[i].z());
            if (particles.fields.at("wall")[i] > 0.5 || r > 1.5 * kSpacingMm * 1e-3)
                continue;
            sum += particles.fields.at("velocity_x_m_s")[i];
            exactSum += std::real(force * womersleyAmplitude(r, radius, omega, alpha) *
                                  std::exp(Complex(0.0, omega * frame.position)));
            ++count;
        }
        times.push_back(frame.position), measured.push_back(sum / count), exact.push_back(exactSum / count);
    };
    SphSolver solver;
    const SolverRun run = runCase("sph-womersley at alpha " + numberText(alpha), solver, pipe(), parameters, progress, control);
    const Harmonic sph = fit(times, measured, omega), truth = fit(times, exact, omega);
    double phase = (sph.phase - truth.phase) / (2.0 * std::numbers::pi);
    phase -= std::round(phase);
    return {sph.amplitude / truth.amplitude, phase, long(run.metrics.at("steps"))};
}

} // namespace

ValidationResult womersleyCase(const Progress& progress)
{
    ValidationResult result;
    result.name = "sph-womersley";
    result.description = storedText("pulsatile flow in a rigid pipe 20 particles across (0.1 mm, periodic along its "
                                    "axis) from rest, alpha 4 (four cycles) and 8 (three): the velocity next to the "
                                    "axis over the last cycle against Womersley's solution");
    const WomersleyErrors four = runWomersley(4.0, 4, progress.subRange(0.0, 0.6));
    const WomersleyErrors eight = runWomersley(8.0, 3, progress.subRange(0.6, 1.0));
    result.figures.push_back({"alpha 4: centerline amplitude / exact", four.amplitudeRatio, 1.0, 0.05, ""});
    result.figures.push_back({"alpha 4: centerline phase error", four.phaseErrorCycles, 0.0, 0.05, "cycles"});
    result.figures.push_back({"alpha 8: centerline amplitude / exact", eight.amplitudeRatio, 1.0, 0.05, ""});
    result.figures.push_back({"alpha 8: centerline phase error", eight.phaseErrorCycles, 0.0, 0.05, "cycles"});
    result.description += " (" + std::to_string(four.steps) + " and " + std::to_string(eight.steps) + " steps)";
    return result;
}

} // namespace vsim::sim::sph::detail
