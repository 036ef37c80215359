#pragma once

// The device functions the SPH kernels share (SphKernels.cu, OpenBoundaryKernels.cu): the fluid model, the
// quartic kernel, the neighbour loop over the sorted cells, the warp maxima. CUDA only.

#include "SphKernels.cuh"

namespace vsim::cuda::sph {

constexpr int kThreads = 128; // 2-3 % faster than 256 on the H100 (RESULTS.md, 2026-11-27)
inline int blocks(int n)
{
    return (n + kThreads - 1) / kThreads;
}

__device__ inline float mixtureDensity(const SphParams& p, float s)
{
    return p.restDensity * (1.0f - s) + p.gasDensity * s;
}
__device__ inline float mixtureViscosity(const SphParams& p, float s)
{
    return p.viscosity * (1.0f - s) + p.gasViscosity * s;
}
__device__ inline float stiffness(const SphParams& p, float s)
{
    return p.soundSpeed * p.soundSpeed * mixtureDensity(p, s) / p.gamma;
}
/// Tait (FluidModel::pressure).
__device__ inline float pressureOf(const SphParams& p, float rho, float s)
{
    const float tait = stiffness(p, s) * (powf(rho / mixtureDensity(p, s), p.gamma) - 1.0f);
    return p.tension ? tait : fmaxf(tait, 0.0f);
}
/// FluidModel::densityFloor: a particle's density after a kick.
__device__ inline float flooredDensity(const SphParams& p, float rho, float s)
{
    return p.tension ? rho : fmaxf(rho, mixtureDensity(p, s));
}
/// FluidModel::densityAt.
__device__ inline float densityAt(const SphParams& p, float pressurePa, float s)
{
    return mixtureDensity(p, s) * powf(1.0f + pressurePa / stiffness(p, s), 1.0f / p.gamma);
}
/// The quartic kernel's W(r) (QuarticKernel::value), in its factored form norm (2 - q)^2 (1/6 + q/6 - 5/32
/// q^2), as on the CPU: near q = 2, where W is slightly negative, the expanded polynomial cancels to a
/// rounding error of either sign, and a wall particle exactly 2h from the fluid took the fluid's pressure or
/// kept its own by that sign, differently on the two sides.
__device__ inline float kernelValue(const SphParams& p, float r)
{
    const float q = r * p.invH;
    if (q >= 2.0f)
        return 0.0f;
    const float a = 2.0f - q;
    return p.wNorm * a * a * (1.0f / 6.0f + q / 6.0f - 5.0f / 32.0f * q * q);
}
/// dW/dr / r: grad_i W = this times rij (QuarticKernel::gradient); -9/4 + 19/8 q - 5/8 q^2 factored as
/// 5/8 (2 - q) (q - 1.8), exactly 0 at the support's edge.
__device__ inline float gradientFactor(const SphParams& p, float r)
{
    const float q = r * p.invH;
    if (r <= 0.0f || q >= 2.0f)
        return 0.0f;
    return p.gradNorm * 0.625f * (2.0f - q) * (q - 1.8f);
}

/// FluidModel::wallRepulsionFactor: D ((r0 / r')^12 - (r0 / r')^4) / (r' r) within r0, r' = max(r, 0.8 r0)
/// (1/s^2).
__device__ inline float wallRepulsionFactor(const SphParams& p, float r)
{
    if (!(r < p.repulsionRange) || !(r > 0.0f) || p.repulsion <= 0.0f)
        return 0.0f;
    const float plateau = fmaxf(r, p.repulsionPlateau * p.repulsionRange);
    const float q2 = p.repulsionRange * p.repulsionRange / (plateau * plateau), q4 = q2 * q2;
    return p.repulsion * (q4 * q4 * q4 - q4) / (plateau * r);
}

/// The neighbour loops tell walls from fluid by the position record they load anyway (SphKernels.cuh).
__device__ inline bool isWall(float4 position)
{
    return position.w != kFluid;
}

__device__ inline void cellOf(const SphParams& p, float4 x, int c[3])
{
    const float xs[3] = {x.x, x.y, x.z};
    for (int a = 0; a < 3; ++a)
        c[a] = min(max(int(floorf(xs[a] / p.cell)), 0), p.dims[a] - 1);
}

/// f(j, xj, rx, ry, rz, r, r2) for every particle j != self within the support of the point xi (m from the
/// box's corner; xj the position record, rij = xi - x_j, m; r = |rij|, r2 = r^2). With `cellFluid` (fluid
/// particles per cell) only the cells that hold fluid are scanned: the wall particles' pass, whose sums run
/// over the fluid alone (most walls see none). With `first` and `stride` each row's run is dealt out: a warp's
/// lane `first` of `stride` visits the candidates first, first + stride, ... (the caller sums over the lanes).
template <class F>
__device__ void forEachNeighbourAround(const SphParams& p, const SphArrays& a, const unsigned* cellStart,
                                       const unsigned* cellEnd, float4 xi, int self, F&& f,
                                       const unsigned* cellFluid = nullptr, unsigned first = 0,
                                       unsigned stride = 1)
{
    int c[3];
    cellOf(p, xi, c);
    for (int dz = -2; dz <= 2; ++dz)
    {
        const int z = c[2] + dz;
        if (z < 0 || z >= p.dims[2])
            continue;
        // How far the point lies from this layer of cells, and then from each row: the run along x is cut
        // to the support's chord there (the rows in the corners of the 5 x 5 block are skipped or short).
        const float gz = fmaxf(0.0f, fmaxf(z * p.cell - xi.z, xi.z - (z + 1) * p.cell));
        for (int dy = -2; dy <= 2; ++dy)
        {
            const int y = c[1] + dy;
            if (y < 0 || y >= p.dims[1])
                continue;
            const float gy = fmaxf(0.0f, fmaxf(y * p.cell - xi.y, xi.y - (y + 1) * p.cell));
            const float chord2 = p.support2 - gy * gy - gz * gz;
            if (chord2 <= 0.0f)
                continue;
            const float chord = sqrtf(chord2);
            // The cells along x within the chord are consecutive in the sorted order: one run.
            const int x0 = max(int(floorf((xi.x - chord) / p.cell)), 0);
            const int x1 = min(int(floorf((xi.x + chord) / p.cell)), p.dims[0] - 1);
            const unsigned row = unsigned(p.dims[0]) * rowOf(p, y, z);
            unsigned begin = 0xffffffffu, end = 0;
            for (int x = x0; x <= x1; ++x)
            {
                if (cellFluid && __ldg(&cellFluid[row + unsigned(x)]) == 0u)
                    continue;
                const unsigned s = __ldg(&cellStart[row + unsigned(x)]),
                               e = __ldg(&cellEnd[row + unsigned(x)]);
                if (e > s)
                    begin = min(begin, s), end = max(end, e);
            }
            for (unsigned j = begin + first; j < end; j += stride)
            {
                if (int(j) == self)
                    continue;
                const float4 xj = __ldg(&a.position[j]);
                const float rx = xi.x - xj.x, ry = xi.y - xj.y, rz = xi.z - xj.z;
                const float r2 = rx * rx + ry * ry + rz * rz;
                if (r2 < p.support2 && r2 > 0.0f)
                    f(int(j), xj, rx, ry, rz, sqrtf(r2), r2);
            }
        }
    }
}

/// The same around particle i (itself left out).
template <class F>
__device__ void forEachNeighbour(const SphParams& p, const SphArrays& a, const unsigned* cellStart,
                                 const unsigned* cellEnd, int i, F&& f, const unsigned* cellFluid = nullptr)
{
    forEachNeighbourAround(p, a, cellStart, cellEnd, a.position[i], i, static_cast<F&&>(f), cellFluid);
}

/// The largest value over a warp, then one atomicMax per warp (non-negative floats as unsigned bit patterns).
__device__ inline void warpMax(unsigned* target, float value)
{
    unsigned bits = __float_as_uint(fmaxf(value, 0.0f));
    for (int offset = 16; offset > 0; offset /= 2)
        bits = max(bits, __shfl_down_sync(0xffffffffu, bits, offset));
    if ((threadIdx.x & 31) == 0 && bits > 0)
        atomicMax(target, bits);
}

} // namespace vsim::cuda::sph
