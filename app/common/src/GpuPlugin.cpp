#include "GpuPlugin.h"

#include "vsim/core/Version.h"

#include <dlfcn.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <system_error>

namespace vsim::app {
namespace {

namespace fs = std::filesystem;

struct LoadedPlugin
{
    const GpuPluginApi* api = nullptr;
    std::string status;
};

fs::path pluginFile()
{
    if (const char* chosen = std::getenv("VASCUSIM_GPU_PLUGIN"); chosen != nullptr && *chosen != '\0')
        return chosen;
    std::error_code error;
    const fs::path executable = fs::read_symlink("/proc/self/exe", error);
    if (error)
        return {};
    return executable.parent_path().parent_path() / VSIM_GPU_PLUGIN_DIR / "libvascusim-gpu.so";
}

LoadedPlugin load()
{
    const fs::path file = pluginFile();
    if (file.empty())
        return {nullptr, "not installed (the executable's folder is unknown)"};
    std::error_code error;
    if (!fs::exists(file, error))
        return {nullptr, "not installed (" + file.string() + " is absent)"};
    // Kept loaded for the life of the process: the backends it makes live as long as their runs.
    void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr)
    {
        const char* reason = dlerror();
        return {nullptr, "refused: " + file.string() + " does not load (" + (reason ? reason : "unknown") + ")"};
    }
    const auto entry = reinterpret_cast<GpuPluginEntry>(dlsym(handle, kGpuPluginEntry));
    const GpuPluginApi* api = entry != nullptr ? entry() : nullptr;
    if (api == nullptr)
        return {nullptr, "refused: " + file.string() + " is not a VascuSim GPU plugin"};
    if (api->interfaceVersion != kGpuPluginInterface || api->applicationVersion == nullptr ||
        std::strcmp(api->applicationVersion, kVersion) != 0)
        return {nullptr, "refused: " + file.string() + " was built for VascuSim " +
                             (api->applicationVersion ? api->applicationVersion : "?") + ", interface " +
                             std::to_string(api->interfaceVersion) + "; this is " + kVersion + ", interface " +
                             std::to_string(kGpuPluginInterface) + " (install the matching vascusim-gpu)"};
    return {api, "loaded from " + file.string()};
}

const LoadedPlugin& loaded()
{
    static const LoadedPlugin plugin = load();
    return plugin;
}

} // namespace

const GpuPluginApi* gpuPlugin()
{
    return loaded().api;
}

std::string gpuPluginStatus()
{
    return loaded().status;
}

std::string gpuUnavailableReason()
{
    const GpuPluginApi* plugin = gpuPlugin();
    if (plugin == nullptr)
        return "no CUDA backend: the GPU plugin is " + gpuPluginStatus();
    if (plugin->deviceCount() == 0)
        return "there is no CUDA device";
    return {};
}

} // namespace vsim::app
