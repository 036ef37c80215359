#pragma once

#include <string>
#include <vector>

namespace vsim::cuda {

/// One CUDA device as the runtime reports it.
struct DeviceInfo
{
    int index = 0;
    std::string name;
    int computeMajor = 0;
    int computeMinor = 0;
    double memoryGiB = 0.0;
    int multiprocessors = 0;
};

/// The CUDA runtime version this build links, e.g. "13.0".
std::string runtimeVersion();
/// The devices present; empty when there is no driver or no device (never throws).
std::vector<DeviceInfo> devices();
/// One line for people, e.g. "NVIDIA H100 80GB HBM3 (sm_90, 79.1 GiB, 132 SMs)" or "no CUDA device".
std::string deviceSummary();

} // namespace vsim::cuda
