#pragma once

// Include only from .cu files: it brings in the CUDA runtime header.

#include "vsim/core/Error.h"

#include <cuda_runtime.h>

#include <string>

namespace vsim::cuda {

/// Throws vsim::Error naming the call and CUDA's message when `status` is not cudaSuccess.
inline void check(cudaError_t status, const char* call)
{
    if (status != cudaSuccess)
        throw Error(Pattern{"CUDA call failed: %1: %2", {call, cudaGetErrorString(status)}});
}

} // namespace vsim::cuda

#define VSIM_CUDA_CHECK(call) ::vsim::cuda::check((call), #call)
