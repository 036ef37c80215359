#include "vsim/cuda_smoke/CudaSmokeBackend.h"

#include "SmokeKernels.cuh"

#include "vsim/core/Error.h"
#include "vsim/cuda_common/CudaCheck.h"
#include "vsim/cuda_common/DeviceBuffer.cuh"
#include "vsim/cuda_common/DeviceInfo.h"
#include "vsim/sim/smoke/PoissonMultigrid.h"
#include "vsim/sim/smoke/PressureWarmStart.h"
#include "vsim/sim/smoke/SmokeSimulation.h"

#include <algorithm>
#include <cmath>

namespace vsim::cuda {

using namespace vsim::cuda::smoke;
namespace host = vsim::sim::smoke;

namespace {

constexpr int kCoarsestSweeps = 30;
constexpr std::size_t kCoarsestCells = 512;
constexpr int kCgAttempts = 3;       // as PressureProjection.cpp
constexpr int kStallIterations = 10;

template <typename T>
void copyIn(Buffer<T>& buffer, const T* host, std::size_t n)
{
    if (buffer.count != n)
        buffer.allocate(n);
    if (n > 0)
        VSIM_CUDA_CHECK(cudaMemcpy(buffer.data, host, n * sizeof(T), cudaMemcpyHostToDevice));
}

template <typename T>
void copyOut(const Buffer<T>& buffer, T* host, std::size_t n)
{
    if (n > 0)
        VSIM_CUDA_CHECK(cudaMemcpy(host, buffer.data, n * sizeof(T), cudaMemcpyDeviceToHost));
}

template <typename T>
void ensure(Buffer<T>& buffer, std::size_t n)
{
    if (buffer.count != n)
        buffer.zero(n);
}

} // namespace

struct CudaSmokeBackend::Device
{
    struct Level
    {
        int nx = 0, ny = 0, nz = 0;
        bool byColour = false; // the finest level's cells by colour (SmokeKernels.cuh's LevelView)
        Buffer<std::uint8_t> fluid, ambient, code; // each in the level's slots
        Buffer<float> x, b;
        LevelView view() const { return {nx, ny, nz, code.data, byColour}; }
        std::size_t cells() const { return std::size_t(nx) * ny * nz; }
        std::size_t slots() const { return view().slots(); }
    };

    GridView g;
    Buffer<float> u, v, w, density, temperature, solidVelocity;
    Buffer<std::uint8_t> solid, staticSolid;
    Buffer<float> u0, v0, w0, forward, start, spareDensity, spareTemperature, force, omega, magnitude;
    Buffer<float> psi, previousPsi, b, r, z, p, q, sink;
    host::PressureWarmStart warmStart;
    Buffer<double> scratch, partials, particles, places;
    Buffer<int> changed, keep;
    std::vector<Level> levels;
    bool singular = false, prepared = false, hasVent = false, haveSink = false;
    bool anySolid = true;   ///< a cell is not fluid (a solid, the ball, a vent): the general boundary pass
    bool staticAny = false; ///< the static anatomy has a cell that is not fluid
    /// The largest |u|, |v|, |w| of the faces as they are (m/s), when `speedsKnown`: measured after a projection
    /// and used until the velocity changes (the next step's transport sub-steps, maxSpeed).
    double speeds[3] = {0.0, 0.0, 0.0};
    bool speedsKnown = false;

    void measureSpeeds()
    {
        faceSpeeds(g, scratch.data, speeds);
        speedsKnown = true;
    }

    void bind()
    {
        g.u = u.data, g.v = v.data, g.w = w.data, g.density = density.data, g.temperature = temperature.data;
        g.solid = solid.data, g.solidVelocity = solidVelocity.data;
    }

    /// The operator's hierarchy for the solids now (PoissonMultigrid::prepare).
    void prepareMultigrid()
    {
        if (levels.empty() || levels.front().nx != g.nx || levels.front().ny != g.ny || levels.front().nz != g.nz)
        {
            levels.clear();
            levels.emplace_back();
            levels.back().nx = g.nx, levels.back().ny = g.ny, levels.back().nz = g.nz;
            levels.back().byColour = true;
            while (levels.back().cells() > kCoarsestCells)
            {
                const Level& fine = levels.back();
                const int cx = (fine.nx + 1) / 2, cy = (fine.ny + 1) / 2, cz = (fine.nz + 1) / 2;
                if (cx < 2 || cy < 2 || cz < 2)
                    break;
                levels.emplace_back();
                levels.back().nx = cx, levels.back().ny = cy, levels.back().nz = cz;
            }
            for (Level& level : levels)
            {
                const std::size_t n = level.slots();
                level.fluid.zero(n), level.ambient.zero(n), level.code.zero(n);
                level.x.zero(n), level.b.zero(n);
            }
        }
        finestFlags(g, levels[0].view(), levels[0].fluid.data, levels[0].ambient.data);
        for (std::size_t d = 1; d < levels.size(); ++d)
        {
            const Level &fine = levels[d - 1];
            Level& coarse = levels[d];
            coarsenFlags(fine.view(), fine.fluid.data, fine.ambient.data, coarse.view(), coarse.fluid.data,
                         coarse.ambient.data);
        }
        for (Level& level : levels)
            levelCodes(level.view(), level.fluid.data, level.ambient.data, g.open, level.code.data);
        singular = std::none_of(g.open, g.open + 6, [](std::uint8_t o) { return o != 0; }) && !hasVent;
        prepared = true;
    }

    void vcycle(std::size_t depth, const float* rhs, float* x)
    {
        Level& level = levels[depth];
        const LevelView view = level.view();
        if (depth + 1 == levels.size())
        {
            solveCoarsest(view, x, rhs, kCoarsestSweeps);
            return;
        }
        const int sweeps = host::PoissonMultigrid::smoothingSweeps(depth);
        if (depth + 2 == levels.size() && bottomFits(view, levels.back().view()))
        {
            solveBottom(view, levels.back().view(), rhs, x, sweeps, kCoarsestSweeps);
            return;
        }
        smoothLevelFromZero(view, x, rhs, 0); // x = 0 and the first sweep's first pass, in one
        for (int sweep = 1; sweep < sweeps; ++sweep)
            smoothLevel(view, x, rhs, 0);
        Level& coarse = levels[depth + 1];
        restrictResidual(view, rhs, x, coarse.view(), coarse.b.data);
        vcycle(depth + 1, coarse.b.data, coarse.x.data);
        prolongCorrection(view, x, coarse.view(), coarse.x.data);
        for (int sweep = 0; sweep < sweeps; ++sweep)
            smoothLevel(view, x, rhs, 1);
    }

    void removeNullSpace(float* x)
    {
        if (!singular)
            return;
        double sum = 0.0, count = 0.0;
        sumOnFluid(x, levels[0].fluid.data, levels[0].slots(), scratch.data, sum, count);
        subtractOnFluid(levels[0].view(), x, count > 0.0 ? float(sum / count) : 0.0f);
    }

    void precondition(const float* rhs, float* x)
    {
        vcycle(0, rhs, x);
        removeNullSpace(x);
    }

    /// r = b - A psi (null space removed); returns ||r||.
    double trueResidual()
    {
        const std::size_t n = levels[0].slots();
        residualOf(levels[0].view(), b.data, psi.data, r.data);
        removeNullSpace(r.data);
        return std::sqrt(dot(r.data, r.data, n, scratch.data));
    }
};

CudaSmokeBackend::CudaSmokeBackend(const host::SmokeGrid& grid) : m_device(std::make_unique<Device>())
{
    if (devices().empty())
        throw Error("the smoke's CUDA backend needs a CUDA device, and there is none");
    // The kernels index faces in 32 bits.
    if (double(grid.nx + 1) * double(grid.ny + 1) * double(grid.nz + 1) >= 2147483648.0)
        throw Error("the smoke's CUDA backend takes grids of fewer than 2^31 cells");
    Device& d = *m_device;
    d.g.nx = grid.nx, d.g.ny = grid.ny, d.g.nz = grid.nz, d.g.h = grid.h;
    d.g.ox = grid.origin.x(), d.g.oy = grid.origin.y(), d.g.oz = grid.origin.z();
    for (int f = 0; f < 6; ++f)
        d.g.open[f] = grid.boundaries[std::size_t(f)] == host::DomainBoundary::Open;
    d.scratch.zero(3);
    d.partials.zero(std::max(partialCount(LevelView{grid.nx, grid.ny, grid.nz, nullptr, true}),
                             partialCount(LevelView{grid.nx, grid.ny, grid.nz, nullptr, false})));
    d.changed.zero(1);
}

CudaSmokeBackend::~CudaSmokeBackend() = default;

std::string CudaSmokeBackend::name() const
{
    return "cuda";
}

void CudaSmokeBackend::upload(const host::SmokeGrid& grid)
{
    Device& d = *m_device;
    if (grid.nx != d.g.nx || grid.ny != d.g.ny || grid.nz != d.g.nz)
        throw Error("the smoke's CUDA backend was made for another grid");
    const std::size_t cells = grid.cells();
    copyIn(d.u, grid.u.data(), grid.u.size());
    copyIn(d.v, grid.v.data(), grid.v.size());
    copyIn(d.w, grid.w.data(), grid.w.size());
    copyIn(d.density, grid.density.data(), cells);
    copyIn(d.temperature, grid.temperature.data(), cells);
    copyIn(d.solid, grid.solid.data(), cells);
    copyIn(d.solidVelocity, grid.solidVelocity.empty() ? nullptr : grid.solidVelocity.front().data(), 3 * cells);
    d.hasVent = std::any_of(grid.solid.begin(), grid.solid.end(), [](std::uint8_t s) { return s == host::kVent; });
    d.anySolid = std::any_of(grid.solid.begin(), grid.solid.end(), [](std::uint8_t s) { return s != host::kFluid; });
    const std::size_t largestLattice = std::max({grid.u.size(), grid.v.size(), grid.w.size()});
    ensure(d.u0, grid.u.size()), ensure(d.v0, grid.v.size()), ensure(d.w0, grid.w.size());
    ensure(d.forward, largestLattice), ensure(d.start, 2 * cells);
    ensure(d.spareDensity, cells), ensure(d.spareTemperature, cells);
    ensure(d.force, 3 * cells), ensure(d.omega, 3 * cells), ensure(d.magnitude, cells);
    // The projection's vectors in the finest level's slots (by colour).
    const std::size_t slots = LevelView{grid.nx, grid.ny, grid.nz, nullptr, true}.slots();
    for (Buffer<float>* work : {&d.psi, &d.previousPsi, &d.b, &d.r, &d.z, &d.p, &d.q})
        ensure(*work, slots);
    d.bind();
    d.prepared = false; // the solids may differ from the last upload
    d.speedsKnown = false;
}

void CudaSmokeBackend::download(host::SmokeGrid& grid)
{
    const Device& d = *m_device;
    const std::size_t cells = grid.cells();
    copyOut(d.u, grid.u.data(), grid.u.size());
    copyOut(d.v, grid.v.data(), grid.v.size());
    copyOut(d.w, grid.w.data(), grid.w.size());
    copyOut(d.density, grid.density.data(), cells);
    copyOut(d.temperature, grid.temperature.data(), cells);
    copyOut(d.solid, grid.solid.data(), cells);
    grid.solidVelocity.resize(cells);
    copyOut(d.solidVelocity, grid.solidVelocity.front().data(), 3 * cells);
}

void CudaSmokeBackend::applySource(host::SmokeGrid& grid, const host::SmokeSource& source, double dt, bool setVelocity)
{
    // The box of cells searched, as the CPU's (CpuSmokeBackend.cpp).
    m_device->speedsKnown = m_device->speedsKnown && !setVelocity;
    const Eigen::Vector3d reach = Eigen::Vector3d::Constant(source.radius / grid.h + 1.0);
    const Eigen::Vector3d low = (source.centre - grid.origin) / grid.h - reach;
    const Eigen::Vector3d high = (source.centre - grid.origin) / grid.h + reach;
    const int lo[3] = {std::max(0, int(low.x())), std::max(0, int(low.y())), std::max(0, int(low.z()))};
    const int hi[3] = {std::min(grid.nx - 1, int(high.x())), std::min(grid.ny - 1, int(high.y())), std::min(grid.nz - 1, int(high.z()))};
    smoke::applySource(m_device->g, lo, hi, source.centre.x(), source.centre.y(), source.centre.z(), source.radius,
                       float(source.densityRate * dt), float(source.temperatureK), float(source.velocity.x()),
                       float(source.velocity.y()), float(source.velocity.z()), setVelocity);
}

void CudaSmokeBackend::advect(host::SmokeGrid& grid, double dt, const host::SmokeSettings& settings, bool reverseSweeps)
{
    Device& d = *m_device;
    const std::size_t cells = grid.cells();
    if (!d.speedsKnown)
        d.measureSpeeds();
    const double startSpeeds[3] = {d.speeds[0], d.speeds[1], d.speeds[2]}; // the faces' at the step's start
    d.speedsKnown = false;
    VSIM_CUDA_CHECK(cudaMemcpyAsync(d.u0.data, d.u.data, d.u.bytes(), cudaMemcpyDeviceToDevice));
    VSIM_CUDA_CHECK(cudaMemcpyAsync(d.v0.data, d.v.data, d.v.bytes(), cudaMemcpyDeviceToDevice));
    VSIM_CUDA_CHECK(cudaMemcpyAsync(d.w0.data, d.w.data, d.w.bytes(), cudaMemcpyDeviceToDevice));
    const float dtCells = float(dt / grid.h);
    const host::AdvectionScheme forVelocity =
        settings.scheme == host::AdvectionScheme::Conservative ? host::AdvectionScheme::MacCormack : settings.scheme;
    const bool mac = forVelocity == host::AdvectionScheme::MacCormack;
    float* fields[3] = {d.u.data, d.v.data, d.w.data};
    const float* old[3] = {d.u0.data, d.v0.data, d.w0.data};
    for (int kind = 0; kind < 3; ++kind)
        advectLattice(d.g, kind, fields[kind], old[kind], d.u0.data, d.v0.data, d.w0.data, dtCells, mac, d.forward.data);
    VSIM_CUDA_CHECK(cudaMemcpyAsync(d.start.data, d.density.data, cells * sizeof(float), cudaMemcpyDeviceToDevice));
    VSIM_CUDA_CHECK(cudaMemcpyAsync(d.start.data + cells, d.temperature.data, cells * sizeof(float), cudaMemcpyDeviceToDevice));
    if (settings.scalarScheme == host::AdvectionScheme::Conservative)
    {
        float *density = d.density.data, *temperature = d.temperature.data;
        float *spareDensity = d.spareDensity.data, *spareTemperature = d.spareTemperature.data;
        for (int pass = 0; pass < 3; ++pass)
        {
            const int axis = reverseSweeps ? 2 - pass : pass;
            const int substeps = host::transportSubsteps(startSpeeds[axis], dt, grid.h);
            // The last sub-step clamps as it writes (clampScalars' floats).
            transportAxis(d.g, axis, old[axis], substeps, float(dt / substeps / grid.h), d.start.data, density, temperature,
                          spareDensity, spareTemperature, pass == 2);
        }
        // The sub-steps alternate between each field's two buffers: keep the result's as the field's.
        if (density != d.density.data)
            std::swap(d.density, d.spareDensity);
        if (temperature != d.temperature.data)
            std::swap(d.temperature, d.spareTemperature);
        d.bind();
    }
    else
    {
        const bool scalarMac = settings.scalarScheme == host::AdvectionScheme::MacCormack;
        advectLattice(d.g, 3, d.density.data, d.start.data, d.u0.data, d.v0.data, d.w0.data, dtCells, scalarMac, d.forward.data);
        advectLattice(d.g, 3, d.temperature.data, d.start.data + cells, d.u0.data, d.v0.data, d.w0.data, dtCells, scalarMac,
                      d.forward.data);
        clampScalars(d.g);
    }
}

void CudaSmokeBackend::addHeatForces(host::SmokeGrid&, double dt, const host::SmokeSettings& settings)
{
    m_device->speedsKnown = false;
    const float keep = settings.coolingPerS > 0.0 ? float(std::exp(-settings.coolingPerS * dt)) : 1.0f;
    const double up[3] = {settings.up.x(), settings.up.y(), settings.up.z()};
    smoke::addHeatForces(m_device->g, keep, dt, settings.buoyancyAlpha, settings.buoyancyBeta, up);
}

void CudaSmokeBackend::addVortexForces(host::SmokeGrid&, double dt, const host::SmokeSettings& settings,
                                       const host::VortexParticles& particles)
{
    Device& d = *m_device;
    d.speedsKnown = false;
    vorticityConfinement(d.g, settings.confinement, d.force.data, d.omega.data, d.magnitude.data);
    const std::size_t count = particles.size();
    if (count > 0 && settings.particleStrength > 0.0)
    {
        if (d.particles.count < 6 * count)
            d.particles.allocate(6 * count);
        VSIM_CUDA_CHECK(cudaMemcpy(d.particles.data, particles.particles().front().position.data(),
                                   6 * count * sizeof(double), cudaMemcpyHostToDevice));
        particleForcing(d.g, d.particles.data, int(count), settings.particleStrength, settings.particleRadius, d.force.data);
    }
    smoke::addCellForces(d.g, d.force.data, float(dt));
}

void CudaSmokeBackend::placeSolids(host::SmokeGrid&, const std::vector<std::uint8_t>& staticSolid,
                                   const host::MovingSphere* sphere)
{
    Device& d = *m_device;
    if (d.staticSolid.count != staticSolid.size())
    {
        d.staticSolid.upload(staticSolid);
        d.staticAny = std::any_of(staticSolid.begin(), staticSolid.end(), [](std::uint8_t s) { return s != host::kFluid; });
    }
    d.anySolid = sphere || d.staticAny;
    d.speedsKnown = false; // the projection's boundary pass will read the solids' velocity
    VSIM_CUDA_CHECK(cudaMemsetAsync(d.changed.data, 0, sizeof(int)));
    smoke::placeSolids(d.g, d.staticSolid.data, sphere ? sphere->centre.x() : 0.0, sphere ? sphere->centre.y() : 0.0,
                       sphere ? sphere->centre.z() : 0.0, sphere ? sphere->radius : 0.0,
                       sphere ? float(sphere->velocity.x()) : 0.0f, sphere ? float(sphere->velocity.y()) : 0.0f,
                       sphere ? float(sphere->velocity.z()) : 0.0f, d.changed.data);
    int changed = 0;
    VSIM_CUDA_CHECK(cudaMemcpy(&changed, d.changed.data, sizeof(int), cudaMemcpyDeviceToHost));
    if (changed || !d.prepared)
        d.prepareMultigrid();
}

void CudaSmokeBackend::setSink(const std::vector<float>& sink)
{
    m_device->sink.upload(sink);
    m_device->haveSink = true;
}

host::ProjectionReport CudaSmokeBackend::project(host::SmokeGrid& grid, double tolerance, int maxIterations, bool withSink,
                                                 double stepS)
{
    Device& d = *m_device;
    if (!d.prepared)
        d.prepareMultigrid();
    const std::size_t n = d.levels[0].slots();
    const float* sink = withSink && d.haveSink ? d.sink.data : nullptr;
    applySolidBoundaries(d.g, d.anySolid);
    projectionRightSide(d.g, d.levels[0].view(), d.levels[0].fluid.data, sink, d.b.data, d.warmStart.weights(stepS), d.psi.data,
                        d.previousPsi.data);
    d.removeNullSpace(d.b.data);
    host::ProjectionReport report;
    const double bNorm = std::sqrt(dot(d.b.data, d.b.data, n, d.scratch.data));
    // Preconditioned conjugate gradients from the last psi, restarted from its psi when the true residual is
    // above the tolerance, from 0 when stalled (PressureProjection.cpp).
    bool stalled = false;
    for (int attempt = 0; attempt < kCgAttempts && bNorm > 0.0 && report.iterations < maxIterations; ++attempt)
    {
        if (attempt > 0 && report.relativeResidual <= tolerance)
            break;
        if (stalled)
            VSIM_CUDA_CHECK(cudaMemsetAsync(d.psi.data, 0, n * sizeof(float)));
        double residual = d.trueResidual() / bNorm;
        d.precondition(d.r.data, d.z.data);
        VSIM_CUDA_CHECK(cudaMemcpyAsync(d.p.data, d.z.data, n * sizeof(float), cudaMemcpyDeviceToDevice));
        double rz = dot(d.r.data, d.z.data, n, d.scratch.data);
        int iteration = 0, sinceProgress = 0;
        double best = residual;
        stalled = false;
        while (residual > tolerance && report.iterations + iteration < maxIterations && rz > 0.0)
        {
            const double pq = applyLevelDot(d.levels[0].view(), d.p.data, d.q.data, d.partials.data, d.scratch.data);
            if (!(pq > 0.0))
                break;
            const double rr = updateSolution(n, float(rz / pq), d.p.data, d.q.data, d.psi.data, d.r.data, d.scratch.data);
            ++iteration;
            residual = std::sqrt(rr) / bNorm;
            if (residual <= tolerance)
                break;
            if (residual < 0.5 * best)
                best = residual, sinceProgress = 0;
            else if (++sinceProgress >= kStallIterations)
            {
                stalled = true;
                break;
            }
            d.precondition(d.r.data, d.z.data);
            const double rzNext = dot(d.r.data, d.z.data, n, d.scratch.data);
            const float beta = float(rzNext / rz);
            rz = rzNext;
            updateDirection(n, beta, d.z.data, d.p.data);
        }
        // The true residual of the final psi (the recurrence drifts in single precision).
        report.iterations += iteration;
        report.relativeResidual = d.trueResidual() / bNorm;
    }
    report.converged = report.relativeResidual <= tolerance;
    d.warmStart.record(stepS);
    correctVelocity(d.g, d.levels[0].view(), d.psi.data);
    report.maxDivergence = largestDivergenceLeft(d.g, sink, d.scratch.data);
    d.measureSpeeds();
    const double speed = maxSpeed(grid);
    report.divergenceRatio = speed > 0.0 ? report.maxDivergence * grid.h / speed : 0.0;
    return report;
}

void CudaSmokeBackend::advanceParticles(const host::SmokeGrid&, host::VortexParticles& particles, double dt)
{
    Device& d = *m_device;
    const std::size_t count = particles.size();
    if (count == 0)
        return;
    if (d.particles.count < 6 * count)
        d.particles.allocate(6 * count);
    if (d.keep.count < count)
        d.keep.allocate(count);
    VSIM_CUDA_CHECK(cudaMemcpy(d.particles.data, particles.particles().front().position.data(), 6 * count * sizeof(double),
                               cudaMemcpyHostToDevice));
    smoke::advanceParticles(d.g, d.particles.data, int(count), dt, d.keep.data);
    std::vector<host::VortexParticle> moved(count);
    std::vector<int> keep(count);
    VSIM_CUDA_CHECK(cudaMemcpy(moved.front().position.data(), d.particles.data, 6 * count * sizeof(double),
                               cudaMemcpyDeviceToHost));
    VSIM_CUDA_CHECK(cudaMemcpy(keep.data(), d.keep.data, count * sizeof(int), cudaMemcpyDeviceToHost));
    std::vector<host::VortexParticle> kept;
    kept.reserve(count);
    for (std::size_t n = 0; n < count; ++n)
        if (keep[n])
            kept.push_back(moved[n]);
    particles.replace(std::move(kept));
}

void CudaSmokeBackend::seedParticles(const host::SmokeGrid&, host::VortexParticles& particles,
                                     const std::vector<Eigen::Vector3d>& places)
{
    Device& d = *m_device;
    const std::size_t count = places.size();
    if (count == 0)
        return;
    d.places.upload(places.front().data(), 3 * count);
    Buffer<double> born;
    born.allocate(6 * count);
    Buffer<int> keep;
    keep.allocate(count);
    smoke::seedParticles(d.g, d.places.data, int(count), born.data, keep.data);
    std::vector<host::VortexParticle> seeded(count);
    std::vector<int> inside(count);
    VSIM_CUDA_CHECK(cudaMemcpy(seeded.front().position.data(), born.data, 6 * count * sizeof(double), cudaMemcpyDeviceToHost));
    VSIM_CUDA_CHECK(cudaMemcpy(inside.data(), keep.data, count * sizeof(int), cudaMemcpyDeviceToHost));
    for (std::size_t n = 0; n < count; ++n)
        if (inside[n])
            particles.add(seeded[n]);
}

double CudaSmokeBackend::maxSpeed(const host::SmokeGrid&)
{
    Device& d = *m_device;
    if (!d.speedsKnown)
        d.measureSpeeds();
    return std::max({d.speeds[0], d.speeds[1], d.speeds[2]});
}

bool CudaSmokeBackend::finite(const host::SmokeGrid&)
{
    return countNotFinite(m_device->g, m_device->scratch.data) == 0.0;
}

std::size_t CudaSmokeBackend::deviceBytes() const
{
    const Device& d = *m_device;
    std::size_t bytes = 0;
    for (const Buffer<float>* b : {&d.u, &d.v, &d.w, &d.density, &d.temperature, &d.solidVelocity, &d.u0, &d.v0, &d.w0,
                                   &d.forward, &d.start, &d.spareDensity, &d.spareTemperature, &d.force, &d.omega, &d.magnitude, &d.psi, &d.previousPsi, &d.b, &d.r,
                                   &d.z, &d.p, &d.q, &d.sink})
        bytes += b->bytes();
    bytes += d.solid.bytes() + d.staticSolid.bytes() + d.particles.bytes() + d.places.bytes() + d.partials.bytes();
    for (const Device::Level& level : d.levels)
        bytes += level.fluid.bytes() * 3 + level.x.bytes() * 2;
    return bytes;
}

host::SmokeBackendFactory cudaSmokeBackendFactory()
{
    return [](const host::SmokeGrid& grid) -> std::unique_ptr<host::SmokeBackend> {
        return std::make_unique<CudaSmokeBackend>(grid);
    };
}

} // namespace vsim::cuda
