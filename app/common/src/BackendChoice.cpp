#include "BackendChoice.h"

#include "GpuPlugin.h"

#include "vsim/app/BackendNames.h"

#include "vsim/core/Error.h"

namespace vsim::app {

bool isBackendName(const std::string& name)
{
    return name == "auto" || name == "cpu" || name == "cuda";
}

bool chooseCuda(const std::string& requested, std::string& device)
{
    return chooseCuda(requested, device, gpuUnavailableReason);
}

bool chooseCuda(const std::string& requested, std::string& device, const std::function<std::string()>& whyNot)
{
    if (!isBackendName(requested))
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
