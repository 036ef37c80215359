#include "SphDevice.cuh"

#include "vsim/cuda_common/CudaCheck.h"

#include <cub/device/device_partition.cuh>
#include <thrust/iterator/counting_iterator.h>

#include <cmath>

namespace vsim::cuda::sph {
namespace {

__global__ void cellKeysKernel(SphParams p, SphArrays a, int n, unsigned* keys, int* order,
                               unsigned* cellFluid, SphReductions* r)
{
    const int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= n)
        return;
    const float4 x = a.position[i];
    order[i] = i;
    if (x.w == kRemoved) // sorted past every cell, then dropped
    {
        keys[i] = p.removedKey;
        return;
    }
    if (!(x.x >= 0.0f && x.y >= 0.0f && x.z >= 0.0f && x.x <= p.boxHigh[0] && x.y <= p.boxHigh[1] &&
          x.z <= p.boxHigh[2]))
        if (atomicExch(&r->escaped, 1u) == 0u)
            r->escapedId = a.id[i];
    int c[3];
    cellOf(p, x, c);
    keys[i] = unsigned(c[0]) + unsigned(p.dims[0]) * rowOf(p, c[1], c[2]);
    if (!isWall(x))
        atomicAdd(&cellFluid[keys[i]], 1u);
}

__global__ void gatherKernel(SphArrays from, SphArrays to, const int* order, int n)
{
    const int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= n)
        return;
    const int s = order[i];
    to.position[i] = from.position[s], to.velocity[i] = from.velocity[s], to.state[i] = from.state[s];
    to.id[i] = from.id[s];
}

__global__ void cellRangesKernel(const unsigned* keys, int n, unsigned* cellStart, unsigned* cellEnd)
{
    const int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= n)
        return;
    const unsigned k = keys[i];
    if (i == 0 || keys[i - 1] != k)
        cellStart[k] = unsigned(i);
    if (i == n - 1 || keys[i + 1] != k)
        cellEnd[k] = unsigned(i + 1);
}

/// extrapolateWallPressure: a wall particle's density from the fluid's pressure around it (Shepard, W+).
__global__ void wallPressureKernel(SphParams p, SphArrays a, SphRatesArrays rates, const unsigned* cellStart,
                                   const unsigned* cellEnd, const unsigned* cellFluid, const int* walls,
                                   int count)
{
    const int t = blockIdx.x * blockDim.x + threadIdx.x;
    if (t >= count)
        return;
    const int i = walls[t];
    // A wall particle's rates are zero; its viscosity rides in G's w for the fluid's rates (SphKernels.cuh).
    rates.acceleration[i] = make_float4(0.0f, 0.0f, 0.0f, 0.0f);
    rates.densityRate[i] = 0.0f;
    rates.densityGradient[i] = make_float4(0.0f, 0.0f, 0.0f, mixtureViscosity(p, a.state[i].z));
    rates.wallDistance[i] = rates.guardedWallDistance[i] = INFINITY;
    float weight = 0.0f, pressure = 0.0f;
    forEachNeighbour(
        p, a, cellStart, cellEnd, i,
        [&](int j, float4 xj, float rx, float ry, float rz, float r, float)
        {
            if (isWall(xj))
                return;
            const float w = fmaxf(kernelValue(p, r), 0.0f);
            const float4 sj = a.state[j];
            weight += w;
            pressure += w * (pressureOf(p, sj.x, sj.z) +
                             sj.x * (p.gravity[0] * rx + p.gravity[1] * ry + p.gravity[2] * rz));
        },
        cellFluid);
    if (weight > 0.0f)
        a.state[i].x = densityAt(p, fmaxf(p.pressureFloor, pressure / weight), a.state[i].z);
}

/// summationDensity: a fluid particle's density m_i sum_j W_ij (itself included) times the lattice's scale.
__global__ void summationDensityKernel(SphParams p, SphArrays a, const unsigned* cellStart, const unsigned* cellEnd,
                                       const int* fluid, int count)
{
    const int t = blockIdx.x * blockDim.x + threadIdx.x;
    if (t >= count)
        return;
    const int i = fluid[t];
    float sum = kernelValue(p, 0.0f);
    forEachNeighbour(p, a, cellStart, cellEnd, i,
                     [&](int, float4, float, float, float, float r, float) { sum += kernelValue(p, r); });
    a.state[i].x = p.summationScale * a.state[i].y * sum;
}

__global__ void pressuresKernel(SphParams p, SphArrays a, SphRatesArrays rates, int n)
{
    const int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= n)
        return;
    float4 state = a.state[i];
    state.w = pressureOf(p, state.x, state.z);
    a.state[i] = state;
    rates.derived[i] = make_float4(state.y / state.x, state.y * state.w / (state.x * state.x), state.y,
                                   state.x / mixtureDensity(p, state.z));
}

/// The least r - guard depth over the walls whose depth particle i lies within (INFINITY if none).
__device__ float guardedWallDistance(const SphParams& p, const SphArrays& a, const unsigned* cellStart,
                                     const unsigned* cellEnd, int i)
{
    float distance = INFINITY;
    forEachNeighbour(p, a, cellStart, cellEnd, i,
                     [&](int j, float4 xj, float, float, float, float r, float)
                     {
                         if (!isWall(xj) || !(xj.w >= 0.0f) || !(r - xj.w < 0.0f))
                             return;
                         const float guardDepth = __ldg(&a.velocity[j]).w;
                         if (guardDepth >= 0.0f)
                             distance = fminf(distance, r - guardDepth);
                     });
    return distance;
}

/// fluidNeighbourhood: G_i = (M_i^T)^-1 sum_j V_j (rho_j / rho0_j - rho_i / rho0_i) grad W and the wall
/// distance.
__global__ void neighbourhoodKernel(SphParams p, SphArrays a, SphRatesArrays rates, const unsigned* cellStart,
                                    const unsigned* cellEnd, const int* fluid, int count)
{
    const int thread = blockIdx.x * blockDim.x + threadIdx.x;
    if (thread >= count)
        return;
    const int i = fluid[thread];
    const float muI = mixtureViscosity(p, a.state[i].z);
    rates.densityGradient[i] = make_float4(0.0f, 0.0f, 0.0f, muI);
    rates.wallDistance[i] = INFINITY;
    rates.guardedWallDistance[i] = INFINITY;
    const float relativeI = rates.derived[i].w;
    // The moment -sum V_j rij (x) grad W = -sum V_j g rij (x) rij (grad W = g rij) is symmetric: six sums.
    float m00 = 0, m01 = 0, m02 = 0, m11 = 0, m12 = 0, m22 = 0;
    float sum[3] = {0, 0, 0};
    float wallDistance = INFINITY;
    const bool gradients = p.diffusion > 0.0f && !p.fpm; // with FPM, G is launchFpm's
    forEachNeighbour(p, a, cellStart, cellEnd, i,
                     [&](int j, float4 xj, float rx, float ry, float rz, float r, float)
                     {
                         if (isWall(xj))
                         {
                             if (xj.w >= 0.0f)
                                 wallDistance = fminf(wallDistance, r - xj.w);
                             return;
                         }
                         if (!gradients)
                             return;
                         const float4 dj = __ldg(&rates.derived[j]);
                         const float vg = dj.x * gradientFactor(p, r); // V_j g
                         const float ax = vg * rx, ay = vg * ry, az = vg * rz;
                         m00 -= ax * rx, m01 -= ax * ry, m02 -= ax * rz;
                         m11 -= ay * ry, m12 -= ay * rz, m22 -= az * rz;
                         const float difference = dj.w - relativeI;
                         sum[0] += difference * ax, sum[1] += difference * ay, sum[2] += difference * az;
                     });
    rates.wallDistance[i] = wallDistance;
    // The guard's distance, against each wall's guard depth (<= its wall depth, riding on the velocity
    // record): only a particle within some wall's depth can have one, so it has a loop of its own, which the
    // rest skip (in the loop above it cost 8 registers a thread: occupancy 62.5 % instead of 75 %).
    if (wallDistance < 0.0f)
        rates.guardedWallDistance[i] = guardedWallDistance(p, a, cellStart, cellEnd, i);
    if (!gradients)
        return;
    // G = (M^T)^-1 sum by the adjugate (M is symmetric), where |det| > 1e-3 (SphRates.cpp).
    const float t[9] = {m00, m01, m02, m01, m11, m12, m02, m12, m22};
    const float c0 = t[4] * t[8] - t[5] * t[7], c1 = t[5] * t[6] - t[3] * t[8],
                c2 = t[3] * t[7] - t[4] * t[6];
    const float det = t[0] * c0 + t[1] * c1 + t[2] * c2;
    if (!(fabsf(det) > 1e-3f))
        return;
    const float inv[9] = {c0, t[2] * t[7] - t[1] * t[8], t[1] * t[5] - t[2] * t[4],
                          c1, t[0] * t[8] - t[2] * t[6], t[2] * t[3] - t[0] * t[5],
                          c2, t[1] * t[6] - t[0] * t[7], t[0] * t[4] - t[1] * t[3]};
    float G[3];
    for (int row = 0; row < 3; ++row)
        G[row] = (inv[3 * row] * sum[0] + inv[3 * row + 1] * sum[1] + inv[3 * row + 2] * sum[2]) / det;
    rates.densityGradient[i] = make_float4(G[0], G[1], G[2], muI);
}

/// computeRates for the fluid particles (walls get no rates; a wall-fluid pair's viscous rate is the fluid
/// one's). The options a run may leave off (particle shifting, the walls' backstop) are template switches, so
/// that a run without them carries neither their per-neighbour tests nor their registers (launchRates).
template <bool Shifting, bool Backstop>
__global__ void ratesKernel(SphParams p, SphArrays a, SphRatesArrays rates, const unsigned* cellStart,
                            const unsigned* cellEnd, float ex, float ey, float ez, const int* fluid,
                            int count, SphReductions* r)
{
    const int t = blockIdx.x * blockDim.x + threadIdx.x;
    float acceleration = 0.0f, viscousRate = 0.0f, kinematic = 0.0f;
    if (t < count) // every thread of the warp goes on to the maxima
    {
        const int i = fluid[t];
        const float4 vi = a.velocity[i], si = a.state[i], di = rates.derived[i];
        const float rhoI = si.x, inverseRhoI = 1.0f / rhoI, pressureI = di.y / di.z; // p_i / rho_i^2
        const float restI = mixtureDensity(p, si.z), relativeI = di.w;
        const float4 gi = rates.densityGradient[i];
        const float muI = gi.w, wallDistanceI = rates.wallDistance[i];
        // The per-neighbour work with the factors common to all neighbours taken out of the sums, and the
        // dot products with grad W = g rij as g times the dot product with rij (the same sums, reordered).
        float continuity = 0.0f, diffusion = 0.0f, fx = 0.0f, fy = 0.0f, fz = 0.0f;
        float weights = kernelValue(p, 0.0f); // sum_j W_ij, i included (the relaxation towards summation)
        float viscousX = 0.0f, viscousY = 0.0f, viscousZ = 0.0f;
        float crowdX = 0.0f, crowdY = 0.0f, crowdZ = 0.0f; // grad C_i (particle shifting)
        float gradV[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};     // d v_k / d x_l at 3 k + l (the shift's correction)
        // Per neighbour, from its records: dj = (V_j, m_j p_j / rho_j^2, m_j, rho_j / rho0_j), gj = (G_j,
        // mu_j).
        forEachNeighbour(p, a, cellStart, cellEnd, i,
                         [&](int j, float4 xj, float rx, float ry, float rz, float rr, float r2)
                         {
                             const float4 vj = __ldg(&a.velocity[j]), dj = __ldg(&rates.derived[j]),
                                          gj = __ldg(&rates.densityGradient[j]);
                             const bool wallJ = isWall(xj);
                             const float g = gradientFactor(p, rr);
                             const float vx = vi.x - vj.x, vy = vi.y - vj.y, vz = vi.z - vj.z;
                             const float vr = vx * rx + vy * ry + vz * rz;
                             const float vg = dj.x * g; // V_j g
                             continuity += vg * vr;     // V_j vij . grad W
                             // delta-SPH: psi . grad W with psi = -2 (rho_j / rho0_j - rho_i / rho0_i)
                             // rij / r^2 - (G_i + G_j), so psi . rij = -2 (...) - (G_i + G_j) . rij.
                             if (!wallJ && vj.w == 0.0f && p.diffusion > 0.0f) // fluid j only
                                 diffusion +=
                                     vg * (-2.0f * (dj.w - relativeI) -
                                           ((gi.x + gj.x) * rx + (gi.y + gj.y) * ry + (gi.z + gj.z) * rz));
                             if (p.relaxationRate > 0.0f)
                                 weights += kernelValue(p, rr);
                             const float pressureTerm = (dj.z * pressureI + dj.y) * g;
                             fx -= pressureTerm * rx, fy -= pressureTerm * ry, fz -= pressureTerm * rz;
                             float wx = vx, wy = vy, wz = vz;
                             if (wallJ && xj.w >= 0.0f)
                             {
                                 const float beta =
                                     fminf(p.betaMax, 1.0f + xj.w / fmaxf(wallDistanceI, 1e-3f * p.h));
                                 wx = beta * vi.x, wy = beta * vi.y, wz = beta * vi.z;
                             }
                             if (Backstop && wallJ && vj.w >= 0.0f) // a wall with the backstop
                             {
                                 const float push = wallRepulsionFactor(p, rr);
                                 fx += push * rx, fy += push * ry, fz += push * rz;
                             }
                             if (Shifting) // grad C_i with the anti-clumping term (SphRates.h)
                             {
                                 const float ratio = kernelValue(p, rr) * p.shiftingReciprocalWeight;
                                 const float ratio2 = ratio * ratio;
                                 const float crowd = vg * (1.0f + p.antiClumping * ratio2 * ratio2);
                                 crowdX += crowd * rx, crowdY += crowd * ry, crowdZ += crowd * rz;
                                 if (p.shiftCorrection) // sum V_j (v_j - v_i) (x) grad W, grad W = g rij
                                 {
                                     const float v[3] = {vx, vy, vz}, rij[3] = {rx, ry, rz};
                                     for (int k = 0; k < 3; ++k)
                                         for (int l = 0; l < 3; ++l)
                                             gradV[3 * k + l] -= vg * v[k] * rij[l];
                                 }
                             }
                             const float damped = 1.0f / (r2 + p.eta2);
                             const float viscous = vg * (muI + gj.w) * r2 * damped; // rij . grad W = g r^2
                             viscousX += viscous * wx, viscousY += viscous * wy, viscousZ += viscous * wz;
                             viscousRate = fmaxf(viscousRate, fabsf(p.h * vr * damped));
                         });
        // With FPM the continuity equation's divergence is the FPM one where its system was regular (SphRates.h).
        const float fpmDivergence = p.fpm ? rates.velocityDivergence[i] : NAN;
        rates.densityRate[i] =
            p.summation ? 0.0f
                        : (isfinite(fpmDivergence) ? -rhoI * fpmDivergence : rhoI * continuity) +
                              p.diffusion * restI * diffusion;
        if (p.relaxationRate > 0.0f)
            rates.densityRate[i] += p.relaxationRate * (p.summationScale * si.y * weights - rhoI);
        fx += inverseRhoI * viscousX + ex;
        fy += inverseRhoI * viscousY + ey;
        fz += inverseRhoI * viscousZ + ez;
        if (Shifting)
        {
            const float coefficient =
                -p.shifting * fmaxf(sqrtf(vi.x * vi.x + vi.y * vi.y + vi.z * vi.z), p.shiftingSpeed);
            const float shift[3] = {coefficient * crowdX, coefficient * crowdY, coefficient * crowdZ};
            rates.shiftVelocity[i] = make_float4(shift[0], shift[1], shift[2], 0.0f);
            if (p.shiftCorrection) // (s_i . grad) v_i
            {
                fx += gradV[0] * shift[0] + gradV[1] * shift[1] + gradV[2] * shift[2];
                fy += gradV[3] * shift[0] + gradV[4] * shift[1] + gradV[5] * shift[2];
                fz += gradV[6] * shift[0] + gradV[7] * shift[1] + gradV[8] * shift[2];
            }
        }
        rates.acceleration[i] = make_float4(fx, fy, fz, 0.0f);
        acceleration = sqrtf(fx * fx + fy * fy + fz * fz);
        kinematic = muI / restI;
    }
    warpMax(&r->largestAcceleration, acceleration);
    warpMax(&r->largestViscousRate, viscousRate);
    warpMax(&r->largestKinematicViscosity, kinematic);
}

__global__ void kickDriftKernel(SphParams p, SphArrays a, SphRatesArrays rates, float dt, int n)
{
    const int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= n)
        return;
    a.state[i].x += 0.5f * dt * rates.densityRate[i];
    float4 x = a.position[i];
    if (isWall(x))
        return;
    a.state[i].x = flooredDensity(p, a.state[i].x, a.state[i].z);
    float4 v = a.velocity[i];
    if (v.w == 0.0f) // not a buffer particle: those drift with their imposed velocity
    {
        const float4 acc = rates.acceleration[i];
        v.x += 0.5f * dt * acc.x, v.y += 0.5f * dt * acc.y, v.z += 0.5f * dt * acc.z;
        a.velocity[i] = v;
        if (p.shifting > 0.0f)
        {
            const float4 s = rates.shiftVelocity[i];
            x.x += dt * s.x, x.y += dt * s.y, x.z += dt * s.z;
        }
    }
    x.x += dt * v.x, x.y += dt * v.y, x.z += dt * v.z;
    a.position[i] = x;
}

__global__ void kickKernel(SphParams p, SphArrays a, SphRatesArrays rates, float dt, float throughWallM,
                           int n, SphReductions* r)
{
    const int i = blockIdx.x * blockDim.x + threadIdx.x;
    float variation = 0.0f;
    if (i < n)
    {
        float4 state = a.state[i];
        state.x += 0.5f * dt * rates.densityRate[i];
        const float4 x = a.position[i];
        if (!isWall(x))
            state.x = flooredDensity(p, state.x, state.z);
        a.state[i] = state;
        float4 v = a.velocity[i];
        const bool fluid = !isWall(x) && v.w == 0.0f; // neither a wall nor in a buffer
        if (fluid)
        {
            const float4 acc = rates.acceleration[i];
            v.x += 0.5f * dt * acc.x, v.y += 0.5f * dt * acc.y, v.z += 0.5f * dt * acc.z;
            a.velocity[i] = v;
        }
        const float departure = state.x / mixtureDensity(p, state.z) - 1.0f; // FluidModel::densityVariation
        const float change = p.tension ? fabsf(departure) : fmaxf(departure, 0.0f);
        if (!isfinite(change) || !isfinite(x.x + x.y + x.z) || !isfinite(v.x + v.y + v.z))
        {
            if (atomicExch(&r->notFinite, 1u) == 0u)
                r->notFiniteId = a.id[i];
        }
        else if (fluid)
            variation = change;
        if (fluid && rates.guardedWallDistance[i] < -throughWallM && atomicExch(&r->throughWall, 1u) == 0u)
            r->throughWallId = a.id[i], r->throughWallIndex = i;
    }
    // The largest variation and its particle: one atomicMax per warp on (bits << 32 | index).
    unsigned long long key = (static_cast<unsigned long long>(__float_as_uint(variation)) << 32) | unsigned(i);
    for (int offset = 16; offset > 0; offset /= 2)
    {
        const unsigned long long other = __shfl_down_sync(0xffffffffu, key, offset);
        key = other > key ? other : key;
    }
    if ((threadIdx.x & 31) == 0)
        atomicMax(&r->largestDensityVariation, key);
}

} // namespace

void launchCellKeys(const SphParams& p, const SphArrays& a, int n, unsigned* keys, int* order,
                    unsigned* cellFluid, SphReductions* r)
{
    cellKeysKernel<<<blocks(n), kThreads>>>(p, a, n, keys, order, cellFluid, r);
    VSIM_CUDA_CHECK(cudaGetLastError());
}

void launchGather(const SphArrays& from, const SphArrays& to, const int* order, int n)
{
    gatherKernel<<<blocks(n), kThreads>>>(from, to, order, n);
    VSIM_CUDA_CHECK(cudaGetLastError());
}

void launchCellRanges(const unsigned* sortedKeys, int n, unsigned* cellStart, unsigned* cellEnd)
{
    cellRangesKernel<<<blocks(n), kThreads>>>(sortedKeys, n, cellStart, cellEnd);
    VSIM_CUDA_CHECK(cudaGetLastError());
}

void launchWallPressure(const SphParams& p, const SphArrays& a, const SphRatesArrays& rates,
                        const unsigned* cellStart, const unsigned* cellEnd, const unsigned* cellFluid,
                        const int* walls, int count)
{
    if (count == 0)
        return;
    wallPressureKernel<<<blocks(count), kThreads>>>(p, a, rates, cellStart, cellEnd, cellFluid, walls, count);
    VSIM_CUDA_CHECK(cudaGetLastError());
}

void launchSummationDensity(const SphParams& p, const SphArrays& a, const unsigned* cellStart,
                            const unsigned* cellEnd, const int* fluid, int count)
{
    if (count == 0)
        return;
    summationDensityKernel<<<blocks(count), kThreads>>>(p, a, cellStart, cellEnd, fluid, count);
    VSIM_CUDA_CHECK(cudaGetLastError());
}

void launchPressures(const SphParams& p, const SphArrays& a, const SphRatesArrays& rates, int n)
{
    pressuresKernel<<<blocks(n), kThreads>>>(p, a, rates, n);
    VSIM_CUDA_CHECK(cudaGetLastError());
}

void launchNeighbourhood(const SphParams& p, const SphArrays& a, const SphRatesArrays& rates,
                         const unsigned* cellStart, const unsigned* cellEnd, const int* fluid, int count)
{
    if (count == 0)
        return;
    neighbourhoodKernel<<<blocks(count), kThreads>>>(p, a, rates, cellStart, cellEnd, fluid, count);
    VSIM_CUDA_CHECK(cudaGetLastError());
}

void launchRates(const SphParams& p, const SphArrays& a, const SphRatesArrays& rates,
                 const unsigned* cellStart, const unsigned* cellEnd, const float external[3],
                 const int* fluid, int count, SphReductions* r)
{
    if (count == 0)
        return;
    const bool shifting = p.shifting > 0.0f, backstop = p.repulsion > 0.0f;
    auto kernel = shifting ? (backstop ? ratesKernel<true, true> : ratesKernel<true, false>)
                           : (backstop ? ratesKernel<false, true> : ratesKernel<false, false>);
    kernel<<<blocks(count), kThreads>>>(p, a, rates, cellStart, cellEnd, external[0], external[1],
                                        external[2], fluid, count, r);
    VSIM_CUDA_CHECK(cudaGetLastError());
}

namespace {
struct IsFluidParticle
{
    const float4* position;
    const float4* velocity;
    __device__ bool operator()(int i) const { return position[i].w == kFluid && velocity[i].w == 0.0f; }
};
struct IsBufferParticle
{
    const float4* position;
    const float4* velocity;
    __device__ bool operator()(int i) const { return position[i].w == kFluid && velocity[i].w != 0.0f; }
};
} // namespace

std::size_t partitionScratchBytes(int n)
{
    std::size_t bytes = 0;
    VSIM_CUDA_CHECK(cub::DevicePartition::If(nullptr, bytes, thrust::counting_iterator<int>(0), (int*)nullptr,
                                             (int*)nullptr, (int*)nullptr, (int*)nullptr, n,
                                             IsFluidParticle{nullptr, nullptr}, IsBufferParticle{nullptr, nullptr}));
    return bytes;
}

void launchPartition(const SphArrays& a, int n, int* fluid, int* buffers, int* walls, int* counts, void* scratch,
                     std::size_t scratchBytes)
{
    VSIM_CUDA_CHECK(cub::DevicePartition::If(scratch, scratchBytes, thrust::counting_iterator<int>(0), fluid,
                                             buffers, walls, counts, n, IsFluidParticle{a.position, a.velocity},
                                             IsBufferParticle{a.position, a.velocity}));
}

void launchKickDrift(const SphParams& p, const SphArrays& a, const SphRatesArrays& rates, float dt, int n)
{
    kickDriftKernel<<<blocks(n), kThreads>>>(p, a, rates, dt, n);
    VSIM_CUDA_CHECK(cudaGetLastError());
}

void launchKick(const SphParams& p, const SphArrays& a, const SphRatesArrays& rates, float dt,
                float throughWallM, int n, SphReductions* r)
{
    kickKernel<<<blocks(n), kThreads>>>(p, a, rates, dt, throughWallM, n, r);
    VSIM_CUDA_CHECK(cudaGetLastError());
}

} // namespace vsim::cuda::sph
