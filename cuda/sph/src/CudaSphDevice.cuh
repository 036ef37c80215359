#pragma once

// The host side of CudaSph (CudaSph.cu): its device arrays and the steps it launches (the neighbour sort, the
// open boundaries' exchange, the rates of SphSolver::updateRates, the stable time step), read by CudaSph's step,
// download and accessors. Single precision on the device; positions from the domain box's low corner.

#include "SphKernels.cuh"
#include "StepPhases.cuh"
#include "vsim/core/Error.h"
#include "vsim/core/Parameters.h"
#include "vsim/core/StoredText.h"
#include "vsim/cuda_common/CudaCheck.h"
#include "vsim/cuda_common/DeviceBuffer.cuh"
#include "vsim/cuda_sph/CudaSph.h"

#include <cub/device/device_radix_sort.cuh>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <unordered_map>
#include <vector>

namespace vsim::cuda {

namespace sph {

/// The particle arrays, twice: the sorted order is gathered from one set into the other.
struct ParticleArrays
{
    Buffer<float4> position, velocity, state;
    Buffer<int> id;

    explicit ParticleArrays(std::size_t n) : position(n), velocity(n), state(n), id(n) {}
    sph::SphArrays pointers() const { return {position.data, velocity.data, state.data, id.data}; }
    std::size_t bytes() const { return position.bytes() + velocity.bytes() + state.bytes() + id.bytes(); }
};

inline unsigned bitsFor(std::size_t count)
{
    unsigned bits = 1;
    while ((std::size_t(1) << bits) < count)
        ++bits;
    return bits;
}

inline float asFloat(unsigned bits)
{
    float value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
}

inline unsigned bitsOf(float value)
{
    unsigned bits;
    std::memcpy(&bits, &value, sizeof bits);
    return bits;
}

inline float4 asFloat4(const Eigen::Vector3d& v)
{
    return make_float4(float(v.x()), float(v.y()), float(v.z()), 0.0f);
}


/// What a guard's message tells of one particle, read back from the device.
struct ParticleAt
{
    int id = -1;
    Eigen::Vector3d positionM = Eigen::Vector3d::Zero();
    double wallDistanceM = INFINITY, guardedWallDistanceM = INFINITY;
    double densityKgM3 = 0.0, voidFraction = 0.0;
};

} // namespace sph

struct CudaSph::Device
{
    int n = 0;        ///< particles now
    int capacity = 0; ///< particles the arrays hold (open boundaries create and remove particles)
    sph::SphParams params{};
    sim::sph::FluidModel fluid;
    sim::sph::SphStepSettings settings;
    sim::sph::OpenBoundaries boundaries;  ///< the CPU solver's, initialized: profiles and prescribed values
    sph::OpenBoundaryArgs boundaryArgs{}; ///< what the kernels see of them
    sim::sph::MassLedger ledger;
    std::vector<double> flowRate, pressure; ///< per boundary, the last imposition's (m^3/s into the domain, Pa)
    int nextId = 0;
    sph::ParticleArrays current, other;
    Buffer<float4> acceleration, densityGradient, derived, shiftVelocity;
    Buffer<float> densityRate, wallDistance, guardedWallDistance;
    Buffer<float> velocityDivergence; ///< with FPM only (launchFpm)
    Buffer<unsigned> keys, sortedKeys, cellStart, cellEnd, cellFluid;
    Buffer<int> order, sortedOrder;
    Buffer<int> fluidList, bufferList, wallList, kindCounts; // the indices by kind (launchPartition)
    Buffer<std::uint8_t> partitionScratch;
    int fluidCount = 0, bufferCount = 0; ///< the lists' lengths; the walls are the rest of the n particles
    Buffer<std::uint8_t> sortScratch;
    std::size_t sortScratchBytes = 0;
    unsigned keyBits = 1;
    std::size_t cells = 0;
    Buffer<sph::SphReductions> reductions;
    Buffer<sph::OpenBoundaryTallies> tallies;
    sph::SphReductions last{};
    sph::OpenBoundaryTallies lastTallies{};
    double time = 0.0, stepS = 0.0;
    sph::StepPhases phases; ///< off unless asked for (CudaSph::timePhases)

    Device(std::size_t count, std::size_t capacityCount, std::size_t cellCount, bool shifting, bool fpm)
        : n(int(count)), capacity(int(capacityCount)), current(capacityCount), other(capacityCount),
          acceleration(capacityCount), densityGradient(capacityCount), derived(capacityCount),
          shiftVelocity(shifting ? capacityCount : 0),
          densityRate(capacityCount), wallDistance(capacityCount), guardedWallDistance(capacityCount),
          velocityDivergence(fpm ? capacityCount : 0),
          keys(capacityCount), sortedKeys(capacityCount), cellStart(cellCount), cellEnd(cellCount),
          cellFluid(cellCount), order(capacityCount), sortedOrder(capacityCount), fluidList(capacityCount),
          bufferList(capacityCount), wallList(capacityCount), kindCounts(2), keyBits(sph::bitsFor(cellCount + 1)),
          cells(cellCount), reductions(1), tallies(1)
    {
        VSIM_CUDA_CHECK(cub::DeviceRadixSort::SortPairs(nullptr, sortScratchBytes, keys.data,
                                                        sortedKeys.data, order.data, sortedOrder.data,
                                                        capacity, 0, int(keyBits)));
        sortScratch = Buffer<std::uint8_t>(sortScratchBytes);
        partitionScratch = Buffer<std::uint8_t>(sph::partitionScratchBytes(capacity));
    }

    sph::SphRatesArrays rates() const
    {
        return {acceleration.data, densityGradient.data, derived.data, densityRate.data, wallDistance.data,
                shiftVelocity.data, guardedWallDistance.data, velocityDivergence.data};
    }
    bool open() const { return boundaryArgs.count > 0; }

    /// Cell keys (removed particles past every cell), the radix sort of `total` particles, the gather into the
    /// sorted order, each cell's run over the `kept` ones, and the indices by kind. A closed domain's fluid
    /// count is fixed; with open boundaries it is read back.
    void sort(int total, int kept)
    {
        VSIM_CUDA_CHECK(cudaMemset(cellFluid.data, 0, cellFluid.bytes()));
        sph::launchCellKeys(params, current.pointers(), total, keys.data, order.data, cellFluid.data,
                            reductions.data);
        phases.lap("cell keys");
        VSIM_CUDA_CHECK(cub::DeviceRadixSort::SortPairs(sortScratch.data, sortScratchBytes, keys.data,
                                                        sortedKeys.data, order.data, sortedOrder.data,
                                                        total, 0, int(keyBits)));
        phases.lap("radix sort");
        sph::launchGather(current.pointers(), other.pointers(), sortedOrder.data, total);
        std::swap(current, other);
        n = kept;
        phases.lap("gather");
        VSIM_CUDA_CHECK(cudaMemset(cellStart.data, 0, cellStart.bytes()));
        VSIM_CUDA_CHECK(cudaMemset(cellEnd.data, 0, cellEnd.bytes()));
        sph::launchCellRanges(sortedKeys.data, n, cellStart.data, cellEnd.data);
        phases.lap("cell ranges");
        sph::launchPartition(current.pointers(), n, fluidList.data, bufferList.data, wallList.data, kindCounts.data,
                             partitionScratch.data, partitionScratch.bytes());
        if (open())
        {
            int counts[2];
            VSIM_CUDA_CHECK(cudaMemcpy(counts, kindCounts.data, sizeof counts, cudaMemcpyDeviceToHost));
            fluidCount = counts[0], bufferCount = counts[1];
        }
        phases.lap("partition by kind");
    }

    /// The exchange after the drift (open boundaries only), then the sort; returns a guard's message, or "".
    std::string exchangeAndSort()
    {
        if (!open())
        {
            sort(n, n);
            return {};
        }
        sph::launchExchange(current.pointers(), boundaryArgs, n, nextId, tallies.data);
        VSIM_CUDA_CHECK(cudaMemcpy(&lastTallies, tallies.data, sizeof lastTallies, cudaMemcpyDeviceToHost));
        phases.lap("open boundaries' exchange");
        if (lastTallies.overflow)
            return storedText(Pattern{"the open boundaries let in more particles than the GPU's arrays hold (%1)",
                                      {std::to_string(capacity)}});
        const int total = n + int(lastTallies.created);
        nextId += int(lastTallies.created);
        for (int k = 0; k < boundaryArgs.count; ++k)
            ledger.inflowKg[std::size_t(k)] += lastTallies.inflowKg[k],
                ledger.outflowKg[std::size_t(k)] += lastTallies.outflowKg[k];
        sort(total, total - int(lastTallies.removed));
        return {};
    }

    /// SphSolver::updateRates: the buffers' values, the walls' pressure, every pressure, G and the wall
    /// distances, the rates.
    void updateRates(double timeS)
    {
        const Eigen::Vector3d external = fluid.externalAcceleration(timeS);
        const float e[3] = {float(external.x()), float(external.y()), float(external.z())};
        const int wallCount = n - fluidCount - bufferCount;
        if (params.summation)
        {
            sph::launchSummationDensity(params, current.pointers(), cellStart.data, cellEnd.data, fluidList.data,
                                        fluidCount);
            phases.lap("density by summation");
        }
        if (open())
        {
            for (int k = 0; k < boundaryArgs.count; ++k)
            {
                const std::size_t b = std::size_t(k);
                sph::OpenBoundaryParams& args = boundaryArgs.b[k];
                args.speedScale = args.velocityPrescribed
                                      ? float(boundaries.prescribedFlowRate(b, timeS) / boundaries.calibration(b))
                                      : 0.0f;
                args.pressure = float(boundaries.prescribedPressure(b, timeS, flowRate[b]));
            }
            sph::launchImpose(params, current.pointers(), rates(), boundaryArgs, cellStart.data, cellEnd.data,
                              bufferList.data, bufferCount, tallies.data);
            phases.lap("open boundaries' values");
        }
        sph::launchWallPressure(params, current.pointers(), rates(), cellStart.data, cellEnd.data,
                                cellFluid.data, wallList.data, wallCount);
        phases.lap("wall pressure");
        sph::launchPressures(params, current.pointers(), rates(), n);
        phases.lap("pressures");
        sph::launchNeighbourhood(params, current.pointers(), rates(), cellStart.data, cellEnd.data,
                                 fluidList.data, fluidCount);
        phases.lap("neighbourhood (G, wall distance)");
        if (params.fpm)
        {
            sph::launchFpm(params, current.pointers(), rates(), cellStart.data, cellEnd.data, fluidList.data,
                           fluidCount);
            phases.lap("FPM systems");
        }
        sph::launchRates(params, current.pointers(), rates(), cellStart.data, cellEnd.data, e, fluidList.data,
                         fluidCount, reductions.data);
        phases.lap("rates");
    }

    void resetReductions()
    {
        VSIM_CUDA_CHECK(cudaMemset(reductions.data, 0, sizeof(sph::SphReductions)));
        if (open())
            VSIM_CUDA_CHECK(cudaMemset(tallies.data, 0, sizeof(sph::OpenBoundaryTallies)));
    }
    void fetchReductions()
    {
        VSIM_CUDA_CHECK(cudaMemcpy(&last, reductions.data, sizeof last, cudaMemcpyDeviceToHost));
        if (!open())
            return;
        VSIM_CUDA_CHECK(cudaMemcpy(&lastTallies, tallies.data, sizeof lastTallies, cudaMemcpyDeviceToHost));
        for (int k = 0; k < boundaryArgs.count; ++k)
        {
            const std::size_t b = std::size_t(k);
            flowRate[b] = lastTallies.flux[k];
            pressure[b] = lastTallies.members[k] > 0.0 ? lastTallies.pressureSum[k] / lastTallies.members[k]
                                                       : double(boundaryArgs.b[k].pressure);
        }
    }

    /// Takes the saved rates of the next kick (SphSolver::savedStartRates, in the order of `ids`; the solver has
    /// checked that they fit its particles and its particle shifting) in place of updateRates: each sorted
    /// particle's by its number, and the largest values the time step reads.
    void uploadRates(const sim::sph::SphRates& saved, const std::vector<int>& ids)
    {
        const std::size_t count = std::size_t(n);
        if (ids.size() != count || saved.acceleration.size() != count || saved.densityRate.size() != count ||
            saved.wallDistance.size() != count || (shiftVelocity.bytes() > 0 && saved.shiftVelocity.size() != count))
            throw Error("the saved rates do not fit the particles: the checkpoint is damaged");
        std::unordered_map<int, std::size_t> given;
        for (std::size_t i = 0; i < count; ++i)
            given.emplace(ids[i], i);
        const std::vector<int> sorted = current.id.read(count);
        std::vector<float4> a(count), shift(shiftVelocity.bytes() > 0 ? count : 0);
        std::vector<float> rate(count), distance(count);
        for (std::size_t s = 0; s < count; ++s)
        {
            const std::size_t i = given.at(sorted[s]);
            a[s] = sph::asFloat4(saved.acceleration[i]);
            rate[s] = float(saved.densityRate[i]), distance[s] = float(saved.wallDistance[i]);
            if (!shift.empty())
                shift[s] = sph::asFloat4(saved.shiftVelocity[i]);
        }
        acceleration.write(a), densityRate.write(rate), wallDistance.write(distance);
        if (!shift.empty())
            shiftVelocity.write(shift);
        last = {};
        last.largestAcceleration = sph::bitsOf(float(saved.largestAcceleration));
        last.largestViscousRate = sph::bitsOf(float(saved.largestViscousRate));
        last.largestKinematicViscosity = sph::bitsOf(float(saved.largestKinematicViscosity));
    }

    /// Particle `index` of the sorted order now (a guard's particle).
    sph::ParticleAt particleAt(int index) const
    {
        sph::ParticleAt at;
        float4 x, state;
        float distance[2];
        VSIM_CUDA_CHECK(cudaMemcpy(&x, current.position.data + index, sizeof x, cudaMemcpyDeviceToHost));
        VSIM_CUDA_CHECK(cudaMemcpy(&state, current.state.data + index, sizeof state, cudaMemcpyDeviceToHost));
        VSIM_CUDA_CHECK(cudaMemcpy(&at.id, current.id.data + index, sizeof at.id, cudaMemcpyDeviceToHost));
        VSIM_CUDA_CHECK(cudaMemcpy(&distance[0], wallDistance.data + index, sizeof(float), cudaMemcpyDeviceToHost));
        VSIM_CUDA_CHECK(
            cudaMemcpy(&distance[1], guardedWallDistance.data + index, sizeof(float), cudaMemcpyDeviceToHost));
        at.positionM = settings.boxLowM + Eigen::Vector3d(x.x, x.y, x.z);
        at.wallDistanceM = distance[0], at.guardedWallDistanceM = distance[1];
        at.densityKgM3 = state.x, at.voidFraction = state.z;
        return at;
    }

    /// stableTimeStep (SphRates.cpp) from the last rates' maxima.
    double stableStep() const
    {
        const double h = params.h;
        double step = h / (fluid.soundSpeed + sph::asFloat(last.largestViscousRate));
        if (sph::asFloat(last.largestAcceleration) > 0.0f)
            step = std::min(step, std::sqrt(h / sph::asFloat(last.largestAcceleration)));
        step *= settings.cfl;
        if (sph::asFloat(last.largestKinematicViscosity) > 0.0f)
            step = std::min(step, 0.125 * h * h / sph::asFloat(last.largestKinematicViscosity));
        return step;
    }
};

} // namespace vsim::cuda
