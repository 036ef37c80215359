#pragma once

// The smoke benchmark's plume (issue 21), shared by tests/bench/bench_smoke.cpp and the GPU parity test: a
// cautery-like source at the floor of a 1 m box of n^3 cells, open at the top, with buoyancy, cooling, vorticity
// confinement 0.3 and vortex particles (strength 0.3, radius 2 cells, 600 born a second); MGPCG to 1e-4.

#include "vsim/sim/smoke/SmokeForces.h"
#include "vsim/sim/smoke/SmokeSimulation.h"

#include <memory>

namespace vsim::test {

inline sim::smoke::SmokeSettings plumeSettings(int n)
{
    sim::smoke::SmokeSettings settings;
    settings.buoyancyAlpha = sim::smoke::kGravity / sim::smoke::kAirDensity;
    settings.buoyancyBeta = sim::smoke::kGravity / sim::smoke::kAmbientK;
    settings.confinement = 0.3;
    settings.particleStrength = 0.3;
    settings.particleRadius = 2.0 / n;
    settings.coolingPerS = 0.5;
    return settings;
}

/// The plume's box: n^3 cells of 1/n m, open at the top.
inline sim::smoke::SmokeGrid plumeGrid(int n)
{
    sim::smoke::DomainBoundaries boundaries{};
    boundaries[5] = sim::smoke::DomainBoundary::Open;
    return sim::smoke::SmokeGrid::make(n, n, n, 1.0 / n, boundaries);
}

/// The plume's simulation on `backend` (the CPU's when null); `rateFactor` scales the source's smoke rate.
inline std::unique_ptr<sim::smoke::SmokeSimulation> plumeSimulation(int n, std::unique_ptr<sim::smoke::SmokeBackend> backend,
                                                                    double rateFactor = 1.0)
{
    using namespace sim::smoke;
    auto simulation = std::make_unique<SmokeSimulation>(plumeGrid(n), plumeSettings(n), std::move(backend));
    SmokeSource source;
    source.centre = {0.5, 0.5, 0.1};
    source.radius = 0.06;
    source.densityRate = 1e-3 * rateFactor;
    source.temperatureK = 80.0;
    source.velocity = {0.0, 0.0, 0.5};
    source.particlesPerSecond = 600.0;
    simulation->addSource(source);
    return simulation;
}

} // namespace vsim::test
