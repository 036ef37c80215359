#pragma once

// A device array freed with its owner (move-only), for the GPU backends' host code.

#include "vsim/cuda_common/CudaCheck.h"

#include <cuda_runtime.h>

#include <algorithm>
#include <stdexcept>
#include <utility>
#include <vector>

namespace vsim::cuda {

template <typename T>
struct Buffer
{
    T* data = nullptr;
    std::size_t count = 0;

    Buffer() = default;
    explicit Buffer(std::size_t n) { allocate(n); }
    Buffer(const Buffer&) = delete;
    Buffer& operator=(const Buffer&) = delete;
    Buffer(Buffer&& other) noexcept : data(std::exchange(other.data, nullptr)), count(std::exchange(other.count, 0)) {}
    Buffer& operator=(Buffer&& other) noexcept
    {
        std::swap(data, other.data);
        std::swap(count, other.count);
        return *this;
    }
    ~Buffer() { cudaFree(data); }

    void allocate(std::size_t n)
    {
        cudaFree(data);
        data = nullptr;
        count = n;
        VSIM_CUDA_CHECK(cudaMalloc(&data, std::max<std::size_t>(1, n) * sizeof(T)));
    }
    void upload(const T* host, std::size_t n)
    {
        allocate(n);
        if (n > 0)
            VSIM_CUDA_CHECK(cudaMemcpy(data, host, n * sizeof(T), cudaMemcpyHostToDevice));
    }
    void upload(const std::vector<T>& host) { upload(host.data(), host.size()); }
    void zero(std::size_t n)
    {
        allocate(n);
        VSIM_CUDA_CHECK(cudaMemset(data, 0, std::max<std::size_t>(1, n) * sizeof(T)));
    }
    /// Writes `host` into the first host.size() values; the allocation stays as it is (it must hold them).
    void write(const std::vector<T>& host)
    {
        if (host.size() > count)
            throw std::length_error("a device buffer was given more values than it holds");
        if (!host.empty())
            VSIM_CUDA_CHECK(cudaMemcpy(data, host.data(), host.size() * sizeof(T), cudaMemcpyHostToDevice));
    }
    /// The first `n` values (all of them by default).
    std::vector<T> read(std::size_t n = std::size_t(-1)) const
    {
        std::vector<T> host(std::min(n, count));
        if (!host.empty())
            VSIM_CUDA_CHECK(cudaMemcpy(host.data(), data, host.size() * sizeof(T), cudaMemcpyDeviceToHost));
        return host;
    }
    std::size_t bytes() const { return count * sizeof(T); }
};

} // namespace vsim::cuda
