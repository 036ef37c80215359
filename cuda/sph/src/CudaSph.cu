#include "vsim/cuda_sph/CudaSph.h"

#include "CudaSphDevice.cuh"

#include <algorithm>
#include <cmath>
#include <vector>

namespace vsim::cuda {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// The indices of `id` in the order of the numbers they hold (download()'s order).
std::vector<std::size_t> orderByNumber(const std::vector<int>& id)
{
    std::vector<std::size_t> order(id.size());
    for (std::size_t s = 0; s < order.size(); ++s)
        order[s] = s;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return id[a] < id[b]; });
    return order;
}

/// The open boundaries as the kernels see them (positions from the box's corner).
sph::OpenBoundaryArgs boundaryArgs(const sim::sph::OpenBoundaries& boundaries, const Eigen::Vector3d& boxLowM,
                                   int capacity)
{
    sph::OpenBoundaryArgs args;
    const auto& list = boundaries.boundaries();
    if (list.size() > std::size_t(sph::kMaxOpenBoundaries))
        throw Error(Pattern{"the CUDA SPH backend takes at most %1 open boundaries; this case has %2",
                            {std::to_string(sph::kMaxOpenBoundaries), std::to_string(list.size())}});
    args.count = int(list.size());
    args.depth = float(boundaries.depth());
    args.capacity = capacity;
    for (std::size_t k = 0; k < list.size(); ++k)
    {
        const sim::sph::OpenBoundary& b = list[k];
        if (b.tracer)
            throw Error(Pattern{"the CUDA SPH backend does not carry a tracer yet: inlet '%1' lets one in; run this "
                                "case on the CPU (--backend cpu)",
                                {b.name}});
        sph::OpenBoundaryParams& p = args.b[k];
        const Eigen::Vector3d centre = b.centreM - boxLowM;
        for (int a = 0; a < 3; ++a)
            p.centre[a] = float(centre[a]), p.normal[a] = float(b.normal[a]);
        p.radius = float(b.radiusM), p.equivalentRadius = float(boundaries.equivalentRadius(k));
        p.velocityPrescribed = b.prescribed == sim::sph::OpenBoundary::Prescribed::Velocity ? 1 : 0;
        p.parabolic = b.parabolic ? 1 : 0;
        p.joins = (b.prescribed == sim::sph::OpenBoundary::Prescribed::Pressure || b.flowRateM3S < 0.0) ? 1 : 0;
    }
    return args;
}

} // namespace

CudaSph::CudaSph(const sim::sph::SphSolver& solver)
{
    int devices = 0;
    if (cudaGetDeviceCount(&devices) != cudaSuccess || devices == 0)
        throw Error("no CUDA device: run the SPH solver on the CPU (--backend cpu)");
    const sim::sph::SphStepSettings settings = solver.stepSettings();
    if (settings.absorption || (settings.periodicLengthM.array() > 0.0).any())
        throw Error("the CUDA SPH backend runs no periodic axes or tracer absorption yet: run this case on the "
                    "CPU (--backend cpu)");
    const sim::sph::ParticleState& p = solver.particles();
    const sim::sph::FluidModel& fluid = solver.fluid();
    const double h = solver.kernel().smoothingLength();
    sph::SphParams params{};
    params.h = float(h), params.invH = float(1.0 / h);
    params.wNorm = float(315.0 / (208.0 * kPi * h * h * h));
    params.gradNorm = float(315.0 / (208.0 * kPi * h * h * h) / (h * h));
    params.support2 = float(4.0 * h * h);
    params.eta2 = float(0.001 * h * h);
    params.diffusion = float(fluid.densityDiffusion * h * fluid.soundSpeed);
    params.shifting = float(fluid.particleShifting * h);
    params.shiftingReciprocalWeight = float(fluid.shiftingReciprocalWeight);
    params.shiftingSpeed = float(fluid.shiftingSpeedMS);
    params.antiClumping = float(sim::sph::FluidModel::kAntiClumping);
    params.shiftCorrection = fluid.shiftCorrection ? 1 : 0;
    params.fpm = fluid.finiteParticleMethod ? 1 : 0;
    params.summation = fluid.densitySummation ? 1 : 0;
    params.summationScale = float(fluid.summationScale);
    const bool relaxing = fluid.densityRelaxationS > 0.0 && !fluid.densitySummation;
    params.relaxationRate = relaxing ? float(1.0 / fluid.densityRelaxationS) : 0.0f;
    params.soundSpeed = float(fluid.soundSpeed), params.gamma = float(fluid.gamma);
    params.restDensity = float(fluid.restDensity), params.gasDensity = float(fluid.gasDensity);
    params.viscosity = float(fluid.viscosity), params.gasViscosity = float(fluid.gasViscosity);
    for (int a = 0; a < 3; ++a)
        params.gravity[a] = float(fluid.gravity[a]);
    params.pressureFloor = settings.freeSurface ? 0.0f : -INFINITY;
    params.tension = fluid.tension ? 1 : 0;
    params.cell = float(h); // half the support, as NeighbourGrid
    params.betaMax = 10.0f;
    params.repulsion = float(fluid.wallRepulsion);
    params.repulsionRange = float(fluid.wallRepulsionRange);
    params.repulsionPlateau = float(sim::sph::FluidModel::kWallRepulsionPlateau);
    for (int a = 0; a < 3; ++a)
    {
        const double extent = settings.boxHighM[a] - settings.boxLowM[a];
        params.boxHigh[a] = float(extent);
        params.dims[a] = std::max(1, int(std::ceil(extent / h)));
    }
    // Tiles of 16 x 16 rows (rowOf): +2.8 % at 4.8 million particles on the H100, -0.8 % at 1-2 million
    // (RESULTS.md, 2026-11-27).
    params.tile = 16;
    params.tilesY = (params.dims[1] + params.tile - 1) / params.tile;
    const std::size_t tilesZ = std::size_t((params.dims[2] + params.tile - 1) / params.tile);
    const std::size_t cells = std::size_t(params.dims[0]) * std::size_t(params.tilesY) * tilesZ *
                              std::size_t(params.tile) * std::size_t(params.tile);
    if (cells >= (std::size_t(1) << 31))
        throw Error(Pattern{"the SPH domain spans too many cells for the GPU grid: %1", {std::to_string(cells)}});
    params.removedKey = unsigned(cells);
    // With open boundaries the count changes: room for a tenth more particles and two buffers' worth of
    // copies in one step.
    const std::size_t n = p.size();
    const std::size_t buffered =
        std::size_t(std::count_if(p.boundary.begin(), p.boundary.end(), [](auto b) { return b != 0; }));
    const std::size_t capacity = settings.openBoundaries ? n + n / 10 + 2 * buffered : n;
    m_device = std::make_unique<Device>(n, capacity, cells, fluid.particleShifting > 0.0, fluid.finiteParticleMethod);
    Device& d = *m_device;
    d.params = params, d.fluid = fluid, d.settings = settings;
    if (settings.openBoundaries)
    {
        d.boundaries = solver.openBoundaries();
        d.boundaryArgs = boundaryArgs(d.boundaries, settings.boxLowM, int(capacity));
        const std::size_t count = d.boundaries.boundaries().size();
        d.ledger = solver.massLedger();
        d.ledger.inflowKg.resize(count, 0.0), d.ledger.outflowKg.resize(count, 0.0);
        d.flowRate.assign(count, 0.0), d.pressure.assign(count, 0.0);
        for (std::size_t k = 0; k < count; ++k)
            d.flowRate[k] = d.boundaries.flowRate(k), d.pressure[k] = d.boundaries.pressure(k);
    }
    d.nextId = p.id.empty() ? 0 : *std::max_element(p.id.begin(), p.id.end()) + 1;
    d.fluidCount = int(std::count_if(p.wall.begin(), p.wall.end(), [](auto w) { return w == 0; })) - int(buffered);
    d.bufferCount = int(buffered);
    std::vector<float4> position(n), velocity(n), state(n);
    for (std::size_t i = 0; i < n; ++i)
    {
        const Eigen::Vector3d x = p.position[i] - settings.boxLowM;
        const float kind = !p.wall[i]              ? sph::kFluid
                           : p.wallDepth[i] >= 0.0 ? float(p.wallDepth[i])
                                                   : sph::kWallOfUnknownDepth;
        position[i] = make_float4(float(x.x()), float(x.y()), float(x.z()), kind);
        velocity[i] = make_float4(
            float(p.velocity[i].x()), float(p.velocity[i].y()), float(p.velocity[i].z()),
            p.wall[i] ? (p.backstop[i] ? float(std::max(0.0, p.guardDepth[i])) : sph::kWallWithoutBackstop)
                      : float(p.boundary[i]));
        state[i] = make_float4(float(p.density[i]), float(p.mass[i]), float(p.voidFraction[i]), 0.0f);
    }
    d.current.position.write(position), d.current.velocity.write(velocity), d.current.state.write(state);
    d.current.id.write(p.id);
    d.resetReductions();
    d.sort(d.n, d.n);
    if (const sim::sph::SphRates* saved = solver.savedStartRates())
        d.uploadRates(*saved, p.id);
    else
    {
        d.updateRates(solver.position());
        d.fetchReductions();
    }
    d.time = solver.position();
}

CudaSph::~CudaSph() = default;

std::string CudaSph::step()
{
    Device& d = *m_device;
    d.phases.lap("between steps (the caller's)");
    const double dt = d.stableStep();
    // What went wrong at the step's end time (SphSolver's guards, the same words).
    auto at = [&](const std::string& what) { return storedText(Pattern{"at t = %1 s %2", {numberText(d.time + dt), what}}); };
    d.resetReductions();
    sph::launchKickDrift(d.params, d.current.pointers(), d.rates(), float(dt), d.n);
    d.phases.lap("kick and drift");
    if (const std::string full = d.exchangeAndSort(); !full.empty())
        return at(full);
    d.updateRates(d.time + dt);
    sph::launchKick(d.params, d.current.pointers(), d.rates(), float(dt), float(0.5 * d.settings.spacingM),
                    d.n, d.reductions.data);
    d.phases.lap("kick");
    d.fetchReductions();
    d.phases.lap("reductions read back");
    d.time += dt;
    d.stepS = dt;
    if (d.last.notFinite)
        return at(storedText(
            Pattern{"particle %1 has a value that is not finite", {std::to_string(d.last.notFiniteId)}}));
    if (d.last.escaped)
        return at(storedText(Pattern{"particle %1 left the domain (through a wall or an open end without an outlet)",
                                     {std::to_string(d.last.escapedId)}}));
    if (d.last.throughWall)
    {
        const sph::ParticleAt where = d.particleAt(d.last.throughWallIndex);
        return at(storedText(Pattern{
            "fluid particle %1 went %2 mm into the wall at %3: the time step or the sound speed is too large for "
            "the flow, or the wall thinner than the kernel (a segmentation's ragged edge: the walls' backstop, "
            "parameter wall_repulsion 0.01)",
            {std::to_string(d.last.throughWallId), numberText(-1e3 * where.guardedWallDistanceM),
             sim::sph::positionText(where.positionM)}}));
    }
    if (largestDensityVariation() > d.settings.densityGuard)
    {
        const sph::ParticleAt where = d.particleAt(int(d.last.largestDensityVariation & 0xffffffffu));
        const std::string wall =
            std::isfinite(where.wallDistanceM)
                ? storedText(Pattern{"%1 mm from the wall", {numberText(1e3 * where.wallDistanceM)}})
                : storedText("away from the walls");
        const double departure = d.fluid.densityDeparture(where.densityKgM3, where.voidFraction);
        return at(storedText(Pattern{"particle %1's density is %2 % from the rest density (guard %3 %) at %4, "
                                     "%5: raise the sound speed or lower the inflow",
                                     {std::to_string(where.id), sim::sph::signedPercentText(departure),
                                      numberText(100.0 * d.settings.densityGuard),
                                      sim::sph::positionText(where.positionM), wall}}));
    }
    return {};
}

double CudaSph::timeS() const
{
    return m_device->time;
}
double CudaSph::lastStepS() const
{
    return m_device->stepS;
}
double CudaSph::largestDensityVariation() const
{
    return sph::asFloat(unsigned(m_device->last.largestDensityVariation >> 32));
}
std::size_t CudaSph::particleCount() const
{
    return std::size_t(m_device->n);
}
const sim::sph::MassLedger& CudaSph::massLedger() const
{
    return m_device->ledger;
}
double CudaSph::flowRate(std::size_t k) const
{
    return m_device->flowRate.at(k);
}
double CudaSph::pressure(std::size_t k) const
{
    return m_device->pressure.at(k);
}

sim::sph::ParticleState CudaSph::download() const
{
    const Device& d = *m_device;
    const std::size_t n = std::size_t(d.n);
    const auto position = d.current.position.read(n), velocity = d.current.velocity.read(n);
    const auto state = d.current.state.read(n);
    const auto id = d.current.id.read(n);
    sim::sph::ParticleState out;
    for (std::size_t s : orderByNumber(id))
    {
        const Eigen::Vector3d x =
            d.settings.boxLowM + Eigen::Vector3d(position[s].x, position[s].y, position[s].z);
        // The CPU's wall depth is -1 where unknown (and unused in the fluid).
        out.add(x, state[s].x, state[s].y, position[s].w != sph::kFluid, std::max(-1.0f, position[s].w),
                state[s].z);
        out.velocity.back() = Eigen::Vector3d(velocity[s].x, velocity[s].y, velocity[s].z);
        if (out.wall.back())
        {
            out.backstop.back() = velocity[s].w >= 0.0f ? 1 : 0;
            if (out.wallDepth.back() >= 0.0 && velocity[s].w >= 0.0f)
                out.guardDepth.back() = velocity[s].w;
        }
        else
            out.boundary.back() = std::uint8_t(velocity[s].w);
        out.id.back() = id[s];
    }
    return out;
}

sim::sph::SphRates CudaSph::nextRates() const
{
    const Device& d = *m_device;
    const std::size_t n = std::size_t(d.n);
    const auto id = d.current.id.read(n);
    const auto acceleration = d.acceleration.read(n), shift = d.shiftVelocity.read(n);
    const auto densityRate = d.densityRate.read(n), wallDistance = d.wallDistance.read(n);
    sim::sph::SphRates out;
    for (std::size_t s : orderByNumber(id))
    {
        out.acceleration.emplace_back(acceleration[s].x, acceleration[s].y, acceleration[s].z);
        out.densityRate.push_back(densityRate[s]), out.wallDistance.push_back(wallDistance[s]);
        if (!shift.empty())
            out.shiftVelocity.emplace_back(shift[s].x, shift[s].y, shift[s].z);
    }
    out.largestAcceleration = sph::asFloat(d.last.largestAcceleration);
    out.largestViscousRate = sph::asFloat(d.last.largestViscousRate);
    out.largestKinematicViscosity = sph::asFloat(d.last.largestKinematicViscosity);
    return out;
}

sim::sph::SphStepperFactory cudaSphStepperFactory()
{
    return [](const sim::sph::SphSolver& solver) { return std::make_unique<CudaSph>(solver); };
}

void CudaSph::timePhases(bool on)
{
    m_device->phases.enable(on);
}

std::vector<std::pair<std::string, double>> CudaSph::phaseSeconds() const
{
    return m_device->phases.totals();
}

std::size_t CudaSph::deviceBytes() const
{
    const Device& d = *m_device;
    return d.current.bytes() + d.other.bytes() + d.acceleration.bytes() + d.densityGradient.bytes() +
           d.derived.bytes() + d.shiftVelocity.bytes() + d.densityRate.bytes() + d.wallDistance.bytes() +
           d.guardedWallDistance.bytes() + d.velocityDivergence.bytes() + d.keys.bytes() + d.sortedKeys.bytes() + d.cellStart.bytes() +
           d.cellEnd.bytes() + d.cellFluid.bytes() + d.order.bytes() + d.sortedOrder.bytes() +
           d.fluidList.bytes() + d.bufferList.bytes() + d.wallList.bytes() + d.partitionScratch.bytes() + d.sortScratch.bytes();
}

} // namespace vsim::cuda
