#include "vsim/cuda_common/VectorKernels.h"

#include "vsim/cuda_common/CudaCheck.h"

namespace vsim::cuda {
namespace {

__global__ void scaledSumKernel(double a, const double* x, double* y, std::size_t count)
{
    const std::size_t i = blockIdx.x * static_cast<std::size_t>(blockDim.x) + threadIdx.x;
    if (i < count)
        y[i] = fma(a, x[i], y[i]);
}

} // namespace

std::vector<double> scaledSum(double a, const std::vector<double>& x, const std::vector<double>& y)
{
    if (x.size() != y.size())
        throw Error("scaledSum: x and y differ in length");
    const std::size_t bytes = x.size() * sizeof(double);
    double* deviceX = nullptr;
    double* deviceY = nullptr;
    std::vector<double> result(y.size());
    try
    {
        VSIM_CUDA_CHECK(cudaMalloc(&deviceX, bytes));
        VSIM_CUDA_CHECK(cudaMalloc(&deviceY, bytes));
        VSIM_CUDA_CHECK(cudaMemcpy(deviceX, x.data(), bytes, cudaMemcpyHostToDevice));
        VSIM_CUDA_CHECK(cudaMemcpy(deviceY, y.data(), bytes, cudaMemcpyHostToDevice));
        constexpr int kThreads = 256;
        const int blocks = static_cast<int>((x.size() + kThreads - 1) / kThreads);
        scaledSumKernel<<<blocks, kThreads>>>(a, deviceX, deviceY, x.size());
        VSIM_CUDA_CHECK(cudaGetLastError());
        VSIM_CUDA_CHECK(cudaMemcpy(result.data(), deviceY, bytes, cudaMemcpyDeviceToHost));
    }
    catch (...)
    {
        cudaFree(deviceX);
        cudaFree(deviceY);
        throw;
    }
    cudaFree(deviceX);
    cudaFree(deviceY);
    return result;
}

} // namespace vsim::cuda
