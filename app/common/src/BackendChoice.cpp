#include "BackendChoice.h"

#include "vsim/core/Error.h"

#ifdef VSIM_HAVE_CUDA
#include "vsim/cuda_common/DeviceInfo.h"
#endif

namespace vsim::app {

bool chooseCuda(const std::string& requested, std::string& device)
{
    if (requested != "auto" && requested != "cpu" && requested != "cuda")
        throw Error("unknown backend '" + requested + "' (auto, cpu, cuda)");
    if (requested == "cpu")
        return false;
#ifdef VSIM_HAVE_CUDA
    if (!cuda::devices().empty())
    {
        device = cuda::deviceSummary();
        return true;
    }
    const std::string unavailable = "there is no CUDA device";
#else
    const std::string unavailable = "this build has no CUDA backend (nvcc was not found when it was configured)";
#endif
    if (requested == "cuda")
        throw Error(unavailable + ": use --backend cpu or auto");
    return false;
}

} // namespace vsim::app
