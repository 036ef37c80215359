#include "vsim/app/VersionInfo.h"

#include "vsim/core/Version.h"

#include <Eigen/Core>
#include <QtGlobal>
#include <dcmtk/config/osconfig.h>
#include <itkVersion.h>
#include <vtkVersion.h>

#ifdef VSIM_HAVE_CUDA
#include "vsim/cuda_common/DeviceInfo.h"
#endif

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
#ifdef VSIM_HAVE_CUDA
    versions.emplace_back("CUDA runtime", cuda::runtimeVersion());
    versions.emplace_back("GPU", cuda::deviceSummary());
#else
    versions.emplace_back("CUDA runtime", "not built (no nvcc at configure time)");
    versions.emplace_back("GPU", "not used");
#endif
    return versions;
}

} // namespace vsim::app
