#include "vsim/app/VersionInfo.h"

#include "GpuPlugin.h"

#include "vsim/core/Version.h"

#include <Eigen/Core>
#include <QtGlobal>
#include <dcmtk/config/osconfig.h>
#include <itkVersion.h>
#include <vtkVersion.h>

namespace vsim::app {

std::vector<std::pair<std::string, std::string>> libraryVersions()
{
    std::vector<std::pair<std::string, std::string>> versions{
        {kApplicationName, kVersion},
        {"Qt", qVersion()},
        {"VTK", vtkVersion::GetVTKVersion()},
        {"ITK", itk::Version::GetITKVersion()},
        {"DCMTK", PACKAGE_VERSION},
        {"Eigen", std::to_string(EIGEN_WORLD_VERSION) + "." + std::to_string(EIGEN_MAJOR_VERSION) + "." +
                      std::to_string(EIGEN_MINOR_VERSION)},
    };
    versions.emplace_back("GPU plugin", gpuPluginStatus());
    if (const GpuPluginApi* plugin = gpuPlugin())
    {
        versions.emplace_back("CUDA runtime", plugin->runtimeVersion());
        versions.emplace_back("GPU", plugin->deviceSummary());
    }
    else
    {
        versions.emplace_back("CUDA runtime", "none (no GPU plugin)");
        versions.emplace_back("GPU", "not used: every solver runs on the CPU");
    }
    return versions;
}

} // namespace vsim::app
