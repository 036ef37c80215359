#include "BlockReduce.cuh"
#include "SmokeKernels.cuh"

#include "vsim/cuda_common/CudaCheck.h"

namespace vsim::cuda::smoke {
namespace {

constexpr int kReduceBlocks = 1024;

__global__ void dotKernel(const float* a, const float* b, std::size_t n, double* out)
{
    double sum = 0.0;
    for (std::size_t c = blockIdx.x * std::size_t(blockDim.x) + threadIdx.x; c < n; c += std::size_t(gridDim.x) * blockDim.x)
        sum += double(a[c]) * double(b[c]);
    sum = blockSum(sum);
    if (threadInBlock() == 0)
        atomicAdd(out, sum);
}

__global__ void sumOnFluidKernel(const float* x, const std::uint8_t* fluid, std::size_t n, double* out)
{
    double sum = 0.0, count = 0.0;
    for (std::size_t c = blockIdx.x * std::size_t(blockDim.x) + threadIdx.x; c < n; c += std::size_t(gridDim.x) * blockDim.x)
        if (fluid[c])
            sum += x[c], count += 1.0;
    sum = blockSum(sum);
    __syncthreads();
    count = blockSum(count);
    if (threadInBlock() == 0)
        atomicAdd(out, sum), atomicAdd(out + 1, count);
}

__device__ double absOrInfinity(float value)
{
    return isnan(value) ? double(INFINITY) : fabs(double(value));
}

/// Up to five arrays in one launch (a launch each costs its ramp and its tail).
struct Arrays
{
    const float* data[5];
    std::size_t size[5];
    int count;
};

/// out[a] = the largest |value| of array a (NaN as +infinity), each array's in one pass.
__global__ void maxAbsEachKernel(Arrays arrays, double* out)
{
    const std::size_t stride = std::size_t(gridDim.x) * blockDim.x, first = blockIdx.x * std::size_t(blockDim.x) + threadIdx.x;
    for (int a = 0; a < arrays.count; ++a)
    {
        double largest = 0.0;
        for (std::size_t n = first; n < arrays.size[a]; n += stride)
            largest = fmax(largest, absOrInfinity(arrays.data[a][n]));
        largest = blockMax(largest);
        if (threadInBlock() == 0)
            atomicMaxNonNegative(out + a, largest);
        __syncthreads(); // blockMax's shared memory again
    }
}

__global__ void notFiniteKernel(Arrays arrays, double* out)
{
    double count = 0.0;
    const std::size_t stride = std::size_t(gridDim.x) * blockDim.x, first = blockIdx.x * std::size_t(blockDim.x) + threadIdx.x;
    for (int a = 0; a < arrays.count; ++a)
        for (std::size_t n = first; n < arrays.size[a]; n += stride)
            count += isfinite(arrays.data[a][n]) ? 0.0 : 1.0;
    count = blockSum(count);
    if (threadInBlock() == 0 && count > 0.0)
        atomicAdd(out, count);
}

/// out[0] += the sum of the blocks' partial sums (out[0] zeroed before).
__global__ void sumPartialsKernel(const double* partials, unsigned count, double* out)
{
    double sum = 0.0;
    for (unsigned n = blockIdx.x * blockDim.x + threadIdx.x; n < count; n += gridDim.x * blockDim.x)
        sum += partials[n];
    sum = blockSum(sum);
    if (threadInBlock() == 0)
        atomicAdd(out, sum);
}

} // namespace

unsigned reduceBlocks(std::size_t n)
{
    return std::max(1u, std::min(unsigned(kReduceBlocks), blocksFor(n)));
}

double sumPartials(const double* partials, unsigned count, double* scratch)
{
    VSIM_CUDA_CHECK(cudaMemsetAsync(scratch, 0, sizeof(double)));
    sumPartialsKernel<<<reduceBlocks(count), kBlock>>>(partials, count, scratch);
    return fetchScalar(scratch);
}

double fetchScalar(const double* scratch)
{
    double value = 0.0;
    VSIM_CUDA_CHECK(cudaMemcpy(&value, scratch, sizeof(double), cudaMemcpyDeviceToHost));
    return value;
}

double dot(const float* a, const float* b, std::size_t n, double* scratch)
{
    VSIM_CUDA_CHECK(cudaMemsetAsync(scratch, 0, 2 * sizeof(double)));
    dotKernel<<<reduceBlocks(n), kBlock>>>(a, b, n, scratch);
    return fetchScalar(scratch);
}

void sumOnFluid(const float* x, const std::uint8_t* fluid, std::size_t n, double* scratch, double& sum, double& count)
{
    VSIM_CUDA_CHECK(cudaMemsetAsync(scratch, 0, 2 * sizeof(double)));
    sumOnFluidKernel<<<reduceBlocks(n), kBlock>>>(x, fluid, n, scratch);
    double values[2];
    VSIM_CUDA_CHECK(cudaMemcpy(values, scratch, 2 * sizeof(double), cudaMemcpyDeviceToHost));
    sum = values[0], count = values[1];
}

void faceSpeeds(const GridView& g, double* scratch, double largest[3])
{
    VSIM_CUDA_CHECK(cudaMemsetAsync(scratch, 0, 3 * sizeof(double)));
    const Arrays faces{{g.u, g.v, g.w}, {nodes(latticeOf(g, 0)), nodes(latticeOf(g, 1)), nodes(latticeOf(g, 2))}, 3};
    maxAbsEachKernel<<<reduceBlocks(faces.size[0]), kBlock>>>(faces, scratch);
    VSIM_CUDA_CHECK(cudaMemcpy(largest, scratch, 3 * sizeof(double), cudaMemcpyDeviceToHost));
}

double countNotFinite(const GridView& g, double* scratch)
{
    VSIM_CUDA_CHECK(cudaMemsetAsync(scratch, 0, sizeof(double)));
    const std::size_t cells = g.cells();
    const Arrays fields{{g.u, g.v, g.w, g.density, g.temperature},
                        {nodes(latticeOf(g, 0)), nodes(latticeOf(g, 1)), nodes(latticeOf(g, 2)), cells, cells}, 5};
    notFiniteKernel<<<reduceBlocks(cells), kBlock>>>(fields, scratch);
    return fetchScalar(scratch);
}

} // namespace vsim::cuda::smoke
