// The Finite Particle Method's pass (launchFpm, SphKernels.cuh): the CPU's FPM systems of fluidNeighbourhood
// (SphRates.cpp, FiniteParticleMethod.h) in single precision, one thread per fluid particle.

#include "SphDevice.cuh"

#include "vsim/cuda_common/CudaCheck.h"

namespace vsim::cuda::sph {
namespace {

/// Solves the 4x4 system m x = rhs (row-major; `Columns` right-hand sides, row-major 4 x Columns) in place by
/// Gaussian elimination with partial pivoting, the solution left in rhs. False when the smallest pivot is under
/// 1e-5 of the largest (FpmFields::solve's test, at single precision's resolution).
template <int Columns>
__device__ bool solveFpmSystem(float m[16], float rhs[4 * Columns])
{
    float largest = 0.0f, smallest = INFINITY;
#pragma unroll
    for (int k = 0; k < 4; ++k)
    {
        int pivot = k;
#pragma unroll
        for (int r = k + 1; r < 4; ++r)
            if (fabsf(m[4 * r + k]) > fabsf(m[4 * pivot + k]))
                pivot = r;
#pragma unroll
        for (int r = k + 1; r < 4; ++r) // the swap with constant indices (the arrays stay in registers)
            if (r == pivot)
            {
#pragma unroll
                for (int c = 0; c < 4; ++c)
                {
                    const float t = m[4 * k + c];
                    m[4 * k + c] = m[4 * r + c], m[4 * r + c] = t;
                }
#pragma unroll
                for (int c = 0; c < Columns; ++c)
                {
                    const float t = rhs[Columns * k + c];
                    rhs[Columns * k + c] = rhs[Columns * r + c], rhs[Columns * r + c] = t;
                }
            }
        const float d = m[4 * k + k];
        largest = fmaxf(largest, fabsf(d)), smallest = fminf(smallest, fabsf(d));
        if (d == 0.0f)
            return false;
#pragma unroll
        for (int r = k + 1; r < 4; ++r)
        {
            const float f = m[4 * r + k] / d;
#pragma unroll
            for (int c = k; c < 4; ++c)
                m[4 * r + c] -= f * m[4 * k + c];
#pragma unroll
            for (int c = 0; c < Columns; ++c)
                rhs[Columns * r + c] -= f * rhs[Columns * k + c];
        }
    }
    if (!(largest > 0.0f) || smallest < 1e-5f * largest)
        return false;
#pragma unroll
    for (int k = 3; k >= 0; --k)
#pragma unroll
        for (int c = 0; c < Columns; ++c)
        {
            float v = rhs[Columns * k + c];
#pragma unroll
            for (int l = k + 1; l < 4; ++l)
                v -= m[4 * k + l] * rhs[Columns * l + c];
            rhs[Columns * k + c] = v / m[4 * k + k];
        }
    return true;
}

/// Adds one point to an FPM system: its test functions V (W, h grad W) against the offsets (1, (x_j - x_i) / h),
/// and its values.
template <int Columns>
__device__ void addToFpmSystem(float m[16], float sums[4 * Columns], const float test[4], const float offset[4],
                               const float values[Columns])
{
#pragma unroll
    for (int a = 0; a < 4; ++a)
    {
#pragma unroll
        for (int b = 0; b < 4; ++b)
            m[4 * a + b] += test[a] * offset[b];
#pragma unroll
        for (int c = 0; c < Columns; ++c)
            sums[Columns * a + c] += test[a] * values[c];
    }
}

__global__ void fpmKernel(SphParams p, SphArrays a, SphRatesArrays rates, const unsigned* cellStart,
                          const unsigned* cellEnd, const int* fluid, int count)
{
    const int t = blockIdx.x * blockDim.x + threadIdx.x;
    if (t >= count)
        return;
    const int i = fluid[t];
    const float4 vi = a.velocity[i], di = rates.derived[i]; // di = (V_i, ..., rho_i / rho0_i)
    float mv[16] = {}, sv[12] = {}, md[16] = {}, sd[4] = {};
    {
        // i itself: rij = 0, grad W = 0.
        const float test[4] = {di.x * kernelValue(p, 0.0f), 0.0f, 0.0f, 0.0f}, offset[4] = {1.0f, 0.0f, 0.0f, 0.0f};
        const float v[3] = {vi.x, vi.y, vi.z}, relative[1] = {di.w};
        addToFpmSystem<3>(mv, sv, test, offset, v);
        addToFpmSystem<1>(md, sd, test, offset, relative);
    }
    const bool gradients = p.diffusion > 0.0f;
    forEachNeighbour(p, a, cellStart, cellEnd, i,
                     [&](int j, float4 xj, float rx, float ry, float rz, float r, float)
                     {
                         const float4 dj = __ldg(&rates.derived[j]), vj = __ldg(&a.velocity[j]);
                         const float gh = dj.x * gradientFactor(p, r) * p.h; // V_j h dW/dr / r
                         const float test[4] = {dj.x * kernelValue(p, r), gh * rx, gh * ry, gh * rz};
                         const float offset[4] = {1.0f, -rx * p.invH, -ry * p.invH, -rz * p.invH};
                         const float v[3] = {vj.x, vj.y, vj.z}; // a wall particle stands still
                         addToFpmSystem<3>(mv, sv, test, offset, v);
                         if (gradients && !isWall(xj))
                         {
                             const float relative[1] = {dj.w};
                             addToFpmSystem<1>(md, sd, test, offset, relative);
                         }
                     });
    // Rows 1-3 of a solution are h times the gradients.
    rates.velocityDivergence[i] = solveFpmSystem<3>(mv, sv) ? (sv[3 * 1 + 0] + sv[3 * 2 + 1] + sv[3 * 3 + 2]) * p.invH : NAN;
    if (gradients && solveFpmSystem<1>(md, sd))
        rates.densityGradient[i] = make_float4(sd[1] * p.invH, sd[2] * p.invH, sd[3] * p.invH, rates.densityGradient[i].w);
}

} // namespace

void launchFpm(const SphParams& p, const SphArrays& a, const SphRatesArrays& rates, const unsigned* cellStart,
               const unsigned* cellEnd, const int* fluid, int count)
{
    if (count == 0)
        return;
    fpmKernel<<<blocks(count), kThreads>>>(p, a, rates, cellStart, cellEnd, fluid, count);
    VSIM_CUDA_CHECK(cudaGetLastError());
}

} // namespace vsim::cuda::sph
