#include "BackendChoice.h"

#include "GpuPlugin.h"

#include "vsim/core/Error.h"

namespace vsim::app {

bool chooseCuda(const std::string& requested, std::string& device)
{
    if (requested != "auto" && requested != "cpu" && requested != "cuda")
        throw Error("unknown backend '" + requested + "' (auto, cpu, cuda)");
    if (requested == "cpu")
        return false;
    const std::string unavailable = gpuUnavailableReason();
    if (unavailable.empty())
    {
        device = gpuPlugin()->deviceSummary();
        return true;
    }
    if (requested == "cuda")
        throw Error(unavailable + ": use --backend cpu or auto");
    return false;
}

} // namespace vsim::app
