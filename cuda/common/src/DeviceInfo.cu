#include "vsim/cuda_common/DeviceInfo.h"

#include <cuda_runtime.h>

#include <cstdio>

namespace vsim::cuda {

std::string runtimeVersion()
{
    int version = 0;
    cudaRuntimeGetVersion(&version);
    return std::to_string(version / 1000) + "." + std::to_string((version % 1000) / 10);
}

std::vector<DeviceInfo> devices()
{
    int count = 0;
    if (cudaGetDeviceCount(&count) != cudaSuccess)
    {
        cudaGetLastError(); // clear the sticky "no driver" state
        return {};
    }
    std::vector<DeviceInfo> result;
    for (int index = 0; index < count; ++index)
    {
        cudaDeviceProp properties{};
        if (cudaGetDeviceProperties(&properties, index) != cudaSuccess)
            continue;
        result.push_back({index, properties.name, properties.major, properties.minor,
                          static_cast<double>(properties.totalGlobalMem) / (1024.0 * 1024.0 * 1024.0),
                          properties.multiProcessorCount});
    }
    return result;
}

std::string deviceSummary()
{
    const std::vector<DeviceInfo> found = devices();
    if (found.empty())
        return "no CUDA device";
    std::string summary;
    for (const DeviceInfo& device : found)
    {
        char line[256];
        std::snprintf(line, sizeof line, "%s%s (sm_%d%d, %.1f GiB, %d SMs)", summary.empty() ? "" : "; ",
                      device.name.c_str(), device.computeMajor, device.computeMinor, device.memoryGiB,
                      device.multiprocessors);
        summary += line;
    }
    return summary;
}

} // namespace vsim::cuda
