#include "SphCases.h"

#include "vsim/core/Error.h"

#include <algorithm>
#include <cmath>

namespace vsim::sim::sph::detail {

ParameterSet caseParameters(double spacingMm, double density, double viscosity, double soundSpeed)
{
    ParameterSet parameters(sphParameters());
    parameters.set("spacing_mm", spacingMm);
    parameters.set("density_kg_m3", density);
    parameters.set("viscosity_pa_s", viscosity);
    parameters.set("sound_speed_m_s", soundSpeed);
    return parameters;
}

SolverRun runCase(const std::string& caseName, SphSolver& solver, ParticleSet particles, const ParameterSet& parameters,
                  const Progress& progress, RunControl control)
{
    SimulationInput input;
    input.data["particles"] = std::move(particles);
    control.keepFramesInMemory = false;
    SolverRun run = runSolver(solver, input, parameters, control, progress);
    if (!run.status.complete())
        throw Error(Pattern{"%1: the run stopped: %2", {caseName, run.status.stopText()}});
    return run;
}

} // namespace vsim::sim::sph::detail

namespace vsim::sim::sph::detail {

namespace {

/// The distance (mm) from the point at x, radius r outside the wall to the wall's profile R(x') (sampled at a hundredth
/// of a spacing within the wall layers' reach; the buffers continue the end sections).
double surfaceDistance(const PipeShape& shape, double x, double r)
{
    const double reach = (shape.wallLayers + 1) * shape.spacingMm, step = 0.01 * shape.spacingMm;
    double nearest = INFINITY;
    for (double at = x - reach; at <= x + reach; at += step)
    {
        const double profile = shape.radiusMm(std::clamp(at, 0.5 * shape.spacingMm, shape.lengthMm - 0.5 * shape.spacingMm));
        nearest = std::min(nearest, std::hypot(x - at, r - profile));
    }
    return nearest;
}

} // namespace

ParticleSet pipeParticles(const PipeShape& shape)
{
    ParticleSet set;
    auto& wall = set.fields["wall"];
    auto& depth = set.fields["wall_depth_mm"];
    std::vector<double> buffer;
    const double dx = shape.spacingMm;
    const long slices = std::lround(shape.lengthMm / dx), buffered = long(std::ceil(shape.bufferDepthMm / dx - 1e-9));
    double widest = 0.0;
    for (long k = -buffered; k < slices + buffered; ++k)
        widest = std::max(widest, shape.radiusMm(std::clamp((k + 0.5) * dx, 0.0, shape.lengthMm)));
    const long across = long(std::ceil(widest / dx)) + shape.wallLayers + 1;
    for (long k = -buffered; k < slices + buffered; ++k)
    {
        // The buffers continue the end sections (the lumen extruded).
        const double x = (k + 0.5) * dx, xWall = std::clamp(x, 0.5 * dx, shape.lengthMm - 0.5 * dx);
        const double radius = shape.radiusMm(xWall);
        for (long j = -across; j < across; ++j)
            for (long i = -across; i < across; ++i)
            {
                const Eigen::Vector3d point = dx * Eigen::Vector3d(double(k) + 0.5, double(i) + 0.5, double(j) + 0.5);
                const double r = std::hypot(point.y(), point.z());
                if (r >= radius + shape.wallLayers * dx)
                    continue;
                set.positionsMm.push_back(point);
                const bool isWall = r >= radius;
                wall.push_back(isWall ? 1.0 : 0.0);
                depth.push_back(isWall ? surfaceDistance(shape, x, r) : 0.0);
                buffer.push_back(isWall ? 0.0 : k < 0 ? 1.0 : k >= slices ? 2.0 : 0.0);
            }
    }
    if (shape.bufferDepthMm > 0.0)
        set.fields["open_boundary"] = std::move(buffer);
    return set;
}

std::vector<OpenBoundary> pipeEnds(const PipeShape& shape, double radiusMm, double flowRateM3S, double rampS)
{
    OpenBoundary inlet;
    inlet.name = "inlet";
    inlet.centreM = Eigen::Vector3d::Zero();
    inlet.normal = Eigen::Vector3d::UnitX();
    inlet.radiusM = 1e-3 * radiusMm;
    inlet.prescribed = OpenBoundary::Prescribed::Velocity;
    inlet.flowRateM3S = flowRateM3S;
    inlet.rampS = rampS;
    OpenBoundary outlet;
    outlet.name = "outlet";
    outlet.centreM = Eigen::Vector3d(1e-3 * shape.lengthMm, 0.0, 0.0);
    outlet.normal = -Eigen::Vector3d::UnitX();
    outlet.radiusM = 1e-3 * radiusMm;
    outlet.prescribed = OpenBoundary::Prescribed::Pressure;
    return {inlet, outlet};
}

} // namespace vsim::sim::sph::detail
