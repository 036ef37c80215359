#pragma once

// Block-wide reductions for the smoke kernels (blocks of kBlock threads): warp shuffles, then one value per warp in
// shared memory. Include only from .cu files.

#include "SmokeDevice.cuh"

namespace vsim::cuda::smoke {

/// The block's reduction of `value` by `combine` (associative, with `identity`), by warp shuffles and shared
/// memory; valid in the block's first thread (threadInBlock() 0). Every thread of the block must reach it.
template <class Combine>
__device__ inline double blockReduce(double value, double identity, Combine combine)
{
    __shared__ double warps[kBlock / 32];
    const unsigned t = threadInBlock();
    for (int offset = 16; offset > 0; offset /= 2)
        value = combine(value, __shfl_down_sync(0xffffffffu, value, offset));
    if (t % 32 == 0)
        warps[t / 32] = value;
    __syncthreads();
    value = t < kBlock / 32 ? warps[t] : identity;
    if (t < 32)
        for (int offset = 16; offset > 0; offset /= 2)
            value = combine(value, __shfl_down_sync(0xffffffffu, value, offset));
    return value;
}

/// The block's place in its grid (x fastest): where it writes its partial sum.
__device__ inline unsigned blockInGrid()
{
    return blockIdx.x + gridDim.x * (blockIdx.y + gridDim.y * blockIdx.z);
}

__device__ inline double blockSum(double value)
{
    return blockReduce(value, 0.0, [](double a, double b) { return a + b; });
}

/// The block's largest of non-negative values.
__device__ inline double blockMax(double value)
{
    return blockReduce(value, 0.0, [](double a, double b) { return fmax(a, b); });
}

/// The largest of non-negative doubles, by their bits (ordered as unsigned integers).
__device__ inline void atomicMaxNonNegative(double* target, double value)
{
    atomicMax(reinterpret_cast<unsigned long long*>(target), static_cast<unsigned long long>(__double_as_longlong(value)));
}

} // namespace vsim::cuda::smoke
