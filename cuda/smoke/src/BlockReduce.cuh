#pragma once

// Block-wide reductions for the smoke kernels (blocks of kBlock threads): warp shuffles, then one value per warp in
// shared memory. Include only from .cu files.

#include "SmokeDevice.cuh"

namespace vsim::cuda::smoke {

/// The block's reduction of `value` by `combine` (associative, with `identity`), by warp shuffles and shared
/// memory; valid in thread 0. Every thread of the block must reach it.
template <class Combine>
__device__ inline double blockReduce(double value, double identity, Combine combine)
{
    __shared__ double warps[kBlock / 32];
    for (int offset = 16; offset > 0; offset /= 2)
        value = combine(value, __shfl_down_sync(0xffffffffu, value, offset));
    if (threadIdx.x % 32 == 0)
        warps[threadIdx.x / 32] = value;
    __syncthreads();
    value = threadIdx.x < kBlock / 32 ? warps[threadIdx.x] : identity;
    if (threadIdx.x < 32)
        for (int offset = 16; offset > 0; offset /= 2)
            value = combine(value, __shfl_down_sync(0xffffffffu, value, offset));
    return value;
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
