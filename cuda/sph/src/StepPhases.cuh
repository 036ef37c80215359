#pragma once

// Wall-clock seconds per phase of CudaSph's step, for a profile where no profiler runs (the device tool's
// machine: bench_sph_cuda_stenosis --phases). Each lap waits for the device first, so a phase's time is its
// kernels' run plus their launch and any transfer: the phases add up to the step, latencies included (what a
// small run is bound by). Off by default: its waits serialise the host and the device.

#include "vsim/cuda_common/CudaCheck.h"

#include <cuda_runtime.h>

#include <chrono>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

namespace vsim::cuda::sph {

class StepPhases
{
public:
    void enable(bool on)
    {
        m_on = on;
        m_mark = Clock::now();
    }
    bool enabled() const { return m_on; }

    /// The time since the last lap, waited for the device, added to `phase`.
    void lap(const char* phase)
    {
        if (!m_on)
            return;
        VSIM_CUDA_CHECK(cudaDeviceSynchronize());
        const Clock::time_point now = Clock::now();
        const double seconds = std::chrono::duration<double>(now - m_mark).count();
        m_mark = now;
        for (auto& [name, total] : m_totals)
            if (std::strcmp(name, phase) == 0)
            {
                total += seconds;
                return;
            }
        m_totals.emplace_back(phase, seconds);
    }

    /// Seconds per phase in the order the phases first ran.
    std::vector<std::pair<std::string, double>> totals() const
    {
        return {m_totals.begin(), m_totals.end()};
    }

private:
    using Clock = std::chrono::steady_clock;
    bool m_on = false;
    Clock::time_point m_mark = Clock::now();
    std::vector<std::pair<const char*, double>> m_totals; ///< names are literals
};

} // namespace vsim::cuda::sph
