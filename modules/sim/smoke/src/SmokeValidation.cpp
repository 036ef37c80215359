#include "vsim/sim/smoke/SmokeValidation.h"

#include "vsim/core/Error.h"
#include "vsim/core/StoredText.h"
#include "vsim/sim/smoke/SmokeForces.h"
#include "vsim/sim/smoke/SmokeSimulation.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <cstdio>
#include <random>

namespace vsim::sim::smoke {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kTaylorGreenParticles = 1100; // the thesis demo's count

/// Kinetic energy per unit density, 1/2 integral |u|^2 (m^5/s^2), from the face values.
double kineticEnergy(const SmokeGrid& grid)
{
    double sum = 0.0;
    for (const std::vector<float>* component : {&grid.u, &grid.v, &grid.w})
        for (float value : *component)
            sum += double(value) * value;
    return 0.5 * sum * grid.h * grid.h * grid.h;
}

/// Enstrophy integral |w|^2 dV (m^3/s^2).
double enstrophy(const SmokeGrid& grid)
{
    double sum = 0.0;
    for (const Eigen::Vector3f& omega : cellVorticity(grid))
        sum += double(omega.squaredNorm());
    return sum * grid.h * grid.h * grid.h;
}

ValidationResult divergenceCase(const Progress& progress)
{
    ValidationResult result;
    result.description = storedText("a random velocity field (uniform in +-1 m/s on the faces) in a 1 m box of 48^3 "
                                    "cells, walls with an open top and a solid sphere of 0.15 m radius at the centre, "
                                    "projected by MGPCG to a relative residual of 1e-6 on three seeds: the largest "
                                    "|div u| h / max |u| left");
    double worstRatio = 0.0, worstResidual = 0.0;
    int iterations = 0;
    for (unsigned seed = 1; seed <= 3; ++seed)
    {
        DomainBoundaries boundaries{};
        boundaries[5] = DomainBoundary::Open;
        SmokeGrid grid = SmokeGrid::make(48, 48, 48, 1.0 / 48.0, boundaries);
        for (int k = 0; k < grid.nz; ++k)
            for (int j = 0; j < grid.ny; ++j)
                for (int i = 0; i < grid.nx; ++i)
                    if ((grid.centre(i, j, k) - Eigen::Vector3d(0.5, 0.5, 0.5)).norm() <= 0.15)
                        grid.solid[grid.cell(i, j, k)] = 1;
        std::mt19937 random(seed);
        std::uniform_real_distribution<float> speed(-1.0f, 1.0f);
        for (std::vector<float>* component : {&grid.u, &grid.v, &grid.w})
            for (float& value : *component)
                value = speed(random);
        SmokeSettings settings;
        settings.tolerance = 1e-6;
        settings.maxIterations = 500;
        SmokeSimulation simulation(std::move(grid), settings);
        const ProjectionReport report = simulation.project();
        worstRatio = std::max(worstRatio, report.divergenceRatio);
        worstResidual = std::max(worstResidual, report.relativeResidual);
        iterations = std::max(iterations, report.iterations);
        progress.report(seed / 3.0);
    }
    result.figures.push_back({"largest |div u| h / max |u| (worst of 3 seeds)", worstRatio, 0.0, 1e-4, ""});
    result.figures.push_back({"relative residual reached (worst of 3 seeds)", worstResidual, 0.0, 1e-6, ""});
    result.figures.push_back({"MGPCG iterations (most of 3 seeds; at most 60)", double(iterations), 30.0, 30.0, ""});
    return result;
}

/// The Taylor-Green vortex in a 1 m free-slip box of n^3 cells at 1 m/s, run for 1 s: E(0), E(end), the largest E,
/// and the effective viscosity -(E_end - E_0) / integral of the enstrophy over time (m^2/s).
struct TaylorGreenRun
{
    double initialEnergy = 0.0, finalEnergy = 0.0, largestEnergy = 0.0, viscosity = 0.0;
};

TaylorGreenRun taylorGreen(int n, double confinement, double particleStrength, const Progress& progress)
{
    const double h = 1.0 / n;
    SmokeGrid grid = SmokeGrid::make(n, n, n, h);
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
        {
            for (int i = 0; i <= n; ++i)
                grid.u[grid.uFace(i, j, k)] = float(std::sin(kPi * i * h) * std::cos(kPi * (j + 0.5) * h) * std::cos(kPi * (k + 0.5) * h));
        }
    for (int k = 0; k < n; ++k)
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i < n; ++i)
                grid.v[grid.vFace(i, j, k)] =
                    float(-std::cos(kPi * (i + 0.5) * h) * std::sin(kPi * j * h) * std::cos(kPi * (k + 0.5) * h));
    SmokeSettings settings;
    settings.confinement = confinement;
    settings.particleStrength = particleStrength;
    settings.particleRadius = 2.0 * h;
    settings.cfl = 1.0;
    SmokeSimulation simulation(std::move(grid), settings);
    simulation.project();
    if (particleStrength > 0.0)
        simulation.seedParticles(Eigen::Vector3d(0.5, 0.5, 0.5), 0.5, kTaylorGreenParticles);
    TaylorGreenRun run;
    run.initialEnergy = run.largestEnergy = kineticEnergy(simulation.grid());
    double enstrophyTime = 0.0, previousEnstrophy = enstrophy(simulation.grid());
    const double end = 1.0, dt = h; // one cell per step at the peak speed of 1 m/s
    while (simulation.time() < end - 1e-9)
    {
        const SmokeStepReport report = simulation.step(std::min(dt, end - simulation.time()));
        if (!report.guard.empty())
            throw Error(Pattern{"smoke-taylor-green: %1", {report.guard}});
        const double current = enstrophy(simulation.grid());
        enstrophyTime += 0.5 * (previousEnstrophy + current) * report.dt;
        previousEnstrophy = current;
        run.largestEnergy = std::max(run.largestEnergy, kineticEnergy(simulation.grid()));
        progress.report(simulation.time() / end);
    }
    run.finalEnergy = kineticEnergy(simulation.grid());
    run.viscosity = -(run.finalEnergy - run.initialEnergy) / enstrophyTime;
    return run;
}

ValidationResult taylorGreenCase(const Progress& progress)
{
    ValidationResult result;
    result.description = storedText("the inviscid Taylor-Green vortex u = (sin x cos y cos z, -cos x sin y cos z, 0) "
                                    "(pi/m, 1 m/s) in a 1 m free-slip box of 32^3 cells for 1 s: the effective "
                                    "numerical viscosity -(dE/dt) / integral |w|^2 with vorticity confinement "
                                    "(epsilon 0.5) and with vortex particles (epsilon 0.5, r = 2 h) against the plain "
                                    "semi-Lagrangian scheme");
    const TaylorGreenRun plain = taylorGreen(32, 0.0, 0.0, progress.subRange(0.0, 0.3));
    const TaylorGreenRun confined = taylorGreen(32, 0.5, 0.0, progress.subRange(0.3, 0.6));
    const TaylorGreenRun particles = taylorGreen(32, 0.0, 0.5, progress.subRange(0.6, 1.0));
    result.figures.push_back({"plain scheme: energy lost in 1 s (share of the initial)",
                              1.0 - plain.finalEnergy / plain.initialEnergy, 0.5, 0.5, ""});
    result.figures.push_back({"numerical viscosity with confinement / plain", confined.viscosity / plain.viscosity, 0.5, 0.5, ""});
    result.figures.push_back({"numerical viscosity with vortex particles / plain", particles.viscosity / plain.viscosity, 0.5, 0.5, ""});
    result.figures.push_back({"largest energy with confinement / initial (no growth)",
                              confined.largestEnergy / confined.initialEnergy, 1.0, 1e-3, ""});
    result.figures.push_back({"largest energy with vortex particles / initial (no growth)",
                              particles.largestEnergy / particles.initialEnergy, 1.0, 1e-3, ""});
    return result;
}

/// The relative change of the smoke mass of a buoyant puff in a closed box over 500 steps, the smoke moved by
/// `scalarScheme` (the velocity by MacCormack with the limiter).
double massDrift(AdvectionScheme scalarScheme, const Progress& progress)
{
    SmokeGrid grid = SmokeGrid::make(32, 32, 32, 1.0 / 32.0);
    for (int k = 0; k < grid.nz; ++k)
        for (int j = 0; j < grid.ny; ++j)
            for (int i = 0; i < grid.nx; ++i)
                if ((grid.centre(i, j, k) - Eigen::Vector3d(0.5, 0.5, 0.3)).norm() <= 0.15)
                {
                    grid.density[grid.cell(i, j, k)] = 1e-3f;
                    grid.temperature[grid.cell(i, j, k)] = 30.0f;
                }
    SmokeSettings settings;
    settings.scheme = AdvectionScheme::MacCormack;
    settings.scalarScheme = scalarScheme;
    settings.buoyancyAlpha = kGravity / kAirDensity;
    settings.buoyancyBeta = kGravity / kAmbientK;
    settings.confinement = 0.2;
    SmokeSimulation simulation(std::move(grid), settings);
    const double initial = simulation.grid().smokeMass();
    for (int step = 0; step < 500; ++step)
    {
        const SmokeStepReport report = simulation.step(simulation.stableStep(0.01));
        if (!report.guard.empty())
            throw Error(Pattern{"smoke-mass: %1", {report.guard}});
        progress.report((step + 1) / 500.0);
    }
    return simulation.grid().smokeMass() / initial - 1.0;
}

ValidationResult massCase(const Progress& progress)
{
    ValidationResult result;
    const double conservative = massDrift(AdvectionScheme::Conservative, progress.subRange(0.0, 0.5));
    const double semiLagrangian = massDrift(AdvectionScheme::MacCormack, progress.subRange(0.5, 1.0));
    result.description = storedText(Pattern{
        "a puff of smoke (1e-3 kg/m^3, 30 K above the ambient, 0.15 m radius) rising by buoyancy in a closed 1 m box "
        "of 32^3 cells, 500 steps (the velocity by MacCormack with the limiter): the smoke mass at the end against the "
        "start, without renormalisation, moved by the limited finite-volume transport; moved by semi-Lagrangian "
        "MacCormack instead it drifted by %1 %",
        {storedNumber(100.0 * semiLagrangian, 1)}});
    result.figures.push_back({"smoke mass drift after 500 steps (no renormalisation)", conservative, 0.0, 0.01, "relative"});
    return result;
}

ValidationResult ballCase(const Progress& progress)
{
    ValidationResult result;
    result.description = storedText("a ball of 0.1 m radius dropped from rest at 0.75 m in still air (a 1 m box of "
                                    "48^3 cells, open at the top), falling under gravity for 0.25 s: the flow through "
                                    "the ball (the faces it touches against its own velocity), the divergence left "
                                    "around it, and the air pushed aside");
    DomainBoundaries boundaries{};
    boundaries[5] = DomainBoundary::Open;
    SmokeGrid grid = SmokeGrid::make(48, 48, 48, 1.0 / 48.0, boundaries);
    SmokeSettings settings;
    settings.tolerance = 1e-5;
    SmokeSimulation simulation(std::move(grid), settings);
    simulation.setSphere({Eigen::Vector3d(0.5, 0.5, 0.75), 0.1, Eigen::Vector3d::Zero(), true});
    double throughBall = 0.0, worstRatio = 0.0, pushedAside = 0.0;
    while (simulation.time() < 0.25 - 1e-9)
    {
        const SmokeStepReport report = simulation.step(simulation.stableStep(0.005));
        if (!report.guard.empty())
            throw Error(Pattern{"smoke-ball: %1", {report.guard}});
        worstRatio = std::max(worstRatio, report.projection.divergenceRatio);
        const SmokeGrid& g = simulation.grid();
        const Eigen::Vector3d ball = simulation.sphere()->velocity;
        const double speed = ball.norm();
        // Every face with a ball cell on either side moves with the ball; the fastest air beside it.
        double fastestAir = 0.0;
        for (int k = 0; k < g.nz; ++k)
            for (int j = 0; j < g.ny; ++j)
                for (int i = 0; i < g.nx; ++i)
                {
                    if (!g.isSolid(i, j, k))
                    {
                        fastestAir = std::max(fastestAir, g.cellVelocity(i, j, k).norm());
                        continue;
                    }
                    const float faces[6] = {g.u[g.uFace(i, j, k)], g.u[g.uFace(i + 1, j, k)], g.v[g.vFace(i, j, k)],
                                            g.v[g.vFace(i, j + 1, k)], g.w[g.wFace(i, j, k)], g.w[g.wFace(i, j, k + 1)]};
                    for (int f = 0; f < 6; ++f)
                        throughBall = std::max(throughBall, std::abs(faces[f] - ball[f / 2]) / std::max(speed, 1e-12));
                }
        pushedAside = std::max(pushedAside, fastestAir / std::max(speed, 1e-12));
        progress.report(simulation.time() / 0.25);
    }
    result.figures.push_back({"flow through the ball: largest |u_face - u_ball| / |u_ball|", throughBall, 0.0, 1e-6, ""});
    result.figures.push_back({"largest |div u| h / max |u| around the ball", worstRatio, 0.0, 1e-3, ""});
    result.figures.push_back({"fastest air beside the ball / the ball's speed", pushedAside, 0.75, 0.5, ""});
    return result;
}

} // namespace

std::vector<std::string> smokeValidationCases()
{
    return {"smoke-divergence", "smoke-taylor-green", "smoke-mass", "smoke-ball"};
}

ValidationResult runSmokeValidation(const std::string& name, const Progress& progress)
{
    const auto start = std::chrono::steady_clock::now();
    ValidationResult result;
    if (name == "smoke-divergence")
        result = divergenceCase(progress);
    else if (name == "smoke-taylor-green")
        result = taylorGreenCase(progress);
    else if (name == "smoke-mass")
        result = massCase(progress);
    else if (name == "smoke-ball")
        result = ballCase(progress);
    else
        throw Error(Pattern{"unknown validation case '%1' (known: smoke-divergence, smoke-taylor-green, smoke-mass, "
                            "smoke-ball)",
                            {name}});
    result.name = name;
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

ValidationConfiguration smokeValidationConfiguration()
{
    return {"cpu", 500, 1e-4, "on the CPU in single precision, the projection by MGPCG to a relative residual of 1e-4 "
                              "(1e-6 in smoke-divergence), at most 500 iterations"};
}

} // namespace vsim::sim::smoke
