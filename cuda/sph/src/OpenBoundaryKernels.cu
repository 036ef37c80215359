#include "SphDevice.cuh"

#include "vsim/cuda_common/CudaCheck.h"

namespace vsim::cuda::sph {
namespace {

__device__ float along(const OpenBoundaryParams& b, float4 x)
{
    return (x.x - b.centre[0]) * b.normal[0] + (x.y - b.centre[1]) * b.normal[1] + (x.z - b.centre[2]) * b.normal[2];
}

/// The squared distance (m^2) of x from the boundary's axis.
__device__ float offAxis2(const OpenBoundaryParams& b, float4 x)
{
    const float s = along(b, x);
    const float ox = x.x - b.centre[0] - s * b.normal[0], oy = x.y - b.centre[1] - s * b.normal[1],
                oz = x.z - b.centre[2] - s * b.normal[2];
    return ox * ox + oy * oy + oz * oz;
}

/// OpenBoundaries::exchange, one thread per particle.
__global__ void exchangeKernel(SphArrays a, OpenBoundaryArgs boundaries, int n, int firstId, OpenBoundaryTallies* t)
{
    const int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= n)
        return;
    float4 x = a.position[i];
    if (isWall(x))
        return;
    float4 v = a.velocity[i];
    const float mass = a.state[i].y;
    const int buffer = int(v.w);
    if (buffer > 0)
    {
        const int k = buffer - 1;
        const OpenBoundaryParams& b = boundaries.b[k];
        const float s = along(b, x);
        if (s >= 0.0f) // into the domain: fluid now, and the buffer refilled a depth behind it
        {
            v.w = 0.0f;
            a.velocity[i] = v;
            atomicAdd(&t->inflowKg[k], double(mass));
            const unsigned slot = atomicAdd(&t->created, 1u);
            const int j = n + int(slot);
            if (j >= boundaries.capacity)
            {
                t->overflow = 1u;
                return;
            }
            a.position[j] = make_float4(x.x - boundaries.depth * b.normal[0], x.y - boundaries.depth * b.normal[1],
                                        x.z - boundaries.depth * b.normal[2], kFluid);
            a.velocity[j] = make_float4(v.x, v.y, v.z, float(buffer));
            a.state[j] = a.state[i];
            a.id[j] = firstId + int(slot);
        }
        else if (s < -boundaries.depth) // out of the buffer's far end: it left when it entered the buffer
        {
            x.w = kRemoved;
            a.position[i] = x;
            atomicAdd(&t->removed, 1u);
        }
        return;
    }
    for (int k = 0; k < boundaries.count; ++k)
    {
        const OpenBoundaryParams& b = boundaries.b[k];
        if (along(b, x) < 0.0f && offAxis2(b, x) <= b.radius * b.radius)
        {
            if (b.joins)
            {
                v.w = float(k + 1);
                a.velocity[i] = v;
            }
            else
            {
                x.w = kRemoved;
                a.position[i] = x;
                atomicAdd(&t->removed, 1u);
            }
            atomicAdd(&t->outflowKg[k], double(mass));
            return;
        }
    }
}

/// The sum of a value over the lanes of a warp, in every lane.
__device__ float warpSum(float value)
{
    for (int offset = 16; offset > 0; offset /= 2)
        value += __shfl_xor_sync(0xffffffffu, value, offset);
    return value;
}

/// OpenBoundaries::impose for the listed buffer particles, a warp each: the values extrapolated from the fluid
/// at the mirror point across the plane (Shepard, max(W, 0) V; the neighbours dealt out over the lanes), the
/// prescribed ones imposed; their rates zero (G's w: their viscosity, which the fluid's viscous term reads).
__global__ void imposeKernel(SphParams p, SphArrays a, SphRatesArrays rates, OpenBoundaryArgs boundaries,
                             const unsigned* cellStart, const unsigned* cellEnd, const int* buffers, int count,
                             OpenBoundaryTallies* t)
{
    const int warp = (blockIdx.x * blockDim.x + threadIdx.x) / 32;
    const unsigned lane = threadIdx.x % 32u;
    if (warp >= count) // the whole warp: kThreads is a multiple of 32
        return;
    const int i = buffers[warp];
    const float4 x = a.position[i];
    float4 v = a.velocity[i];
    const int k = int(v.w) - 1;
    const OpenBoundaryParams& b = boundaries.b[k];
    const float s = along(b, x);
    const float4 mirror = make_float4(x.x - 2.0f * s * b.normal[0], x.y - 2.0f * s * b.normal[1],
                                      x.z - 2.0f * s * b.normal[2], kFluid);
    float weight = 0.0f, relative = 0.0f, vx = 0.0f, vy = 0.0f, vz = 0.0f;
    forEachNeighbourAround(
        p, a, cellStart, cellEnd, mirror, i,
        [&](int j, float4 xj, float, float, float, float r, float)
        {
            if (isWall(xj))
                return;
            const float4 vj = __ldg(&a.velocity[j]);
            if (vj.w != 0.0f) // another buffer particle
                return;
            const float4 sj = __ldg(&a.state[j]);
            const float w = fmaxf(kernelValue(p, r), 0.0f) * sj.y / sj.x;
            weight += w;
            relative += w * sj.x / mixtureDensity(p, sj.z);
            vx += w * vj.x, vy += w * vj.y, vz += w * vj.z;
        },
        nullptr, lane, 32u);
    weight = warpSum(weight), relative = warpSum(relative);
    vx = warpSum(vx), vy = warpSum(vy), vz = warpSum(vz);
    if (lane != 0)
        return;
    float4 state = a.state[i];
    rates.acceleration[i] = make_float4(0.0f, 0.0f, 0.0f, 0.0f);
    rates.densityRate[i] = 0.0f;
    rates.densityGradient[i] = make_float4(0.0f, 0.0f, 0.0f, mixtureViscosity(p, state.z));
    rates.wallDistance[i] = rates.guardedWallDistance[i] = INFINITY;
    const bool extrapolated = weight > 0.05f; // else the values stay (no fluid near the mirror point yet)
    if (b.velocityPrescribed)
    {
        const float shape = b.parabolic ? fmaxf(0.0f, 1.0f - offAxis2(b, x) / (b.equivalentRadius * b.equivalentRadius))
                                        : 1.0f;
        const float speed = b.speedScale * shape;
        v = make_float4(speed * b.normal[0], speed * b.normal[1], speed * b.normal[2], v.w);
        if (extrapolated)
            state.x = mixtureDensity(p, state.z) * relative / weight;
    }
    else
    {
        state.x = densityAt(p, b.pressure, state.z);
        if (extrapolated)
            v = make_float4(vx / weight, vy / weight, vz / weight, v.w);
    }
    a.velocity[i] = v;
    a.state[i] = state;
    const float normalSpeed = v.x * b.normal[0] + v.y * b.normal[1] + v.z * b.normal[2];
    atomicAdd(&t->flux[k], double(state.y / state.x * normalSpeed / boundaries.depth));
    atomicAdd(&t->pressureSum[k], double(pressureOf(p, state.x, state.z)));
    atomicAdd(&t->members[k], 1.0);
}

} // namespace

void launchExchange(const SphArrays& a, const OpenBoundaryArgs& boundaries, int n, int firstId,
                    OpenBoundaryTallies* tallies)
{
    exchangeKernel<<<blocks(n), kThreads>>>(a, boundaries, n, firstId, tallies);
    VSIM_CUDA_CHECK(cudaGetLastError());
}

void launchImpose(const SphParams& p, const SphArrays& a, const SphRatesArrays& rates,
                  const OpenBoundaryArgs& boundaries, const unsigned* cellStart, const unsigned* cellEnd,
                  const int* buffers, int count, OpenBoundaryTallies* tallies)
{
    if (count == 0)
        return;
    static_assert(kThreads % 32 == 0, "a warp per buffer particle");
    imposeKernel<<<blocks(32 * count), kThreads>>>(p, a, rates, boundaries, cellStart, cellEnd, buffers, count,
                                                   tallies);
    VSIM_CUDA_CHECK(cudaGetLastError());
}

} // namespace vsim::cuda::sph
