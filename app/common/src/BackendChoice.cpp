#include "BackendChoice.h"

#include "GpuPlugin.h"

#include "vsim/core/Error.h"

namespace vsim::app {

bool chooseCuda(const std::string& requested, std::string& device)
{
    return chooseCuda(requested, device, gpuUnavailableReason);
}

bool chooseCuda(const std::string& requested, std::string& device, const std::function<std::string()>& whyNot)
{
    if (requested != "auto" && requested != "cpu" && requested != "cuda")
        throw Error(Pattern{"unknown backend '%1' (auto, cpu, cuda)", {requested}});
    if (requested == "cpu")
        return false;
    const std::string unavailable = whyNot();
    if (unavailable.empty())
    {
        device = gpuPlugin()->deviceSummary();
        return true;
    }
    if (requested == "cuda")
        throw Error(Pattern{"%1: use --backend cpu or auto", {unavailable}});
    return false;
}

} // namespace vsim::app
