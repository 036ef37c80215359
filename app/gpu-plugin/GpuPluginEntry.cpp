// The GPU plugin's entry point: the table of GpuPluginApi.h over the cuda_* modules.

#include "vsim/app/GpuPluginApi.h"
#include "vsim/core/Version.h"
#include "vsim/cuda_common/DeviceInfo.h"
#include "vsim/cuda_fem/CudaBackwardEuler.h"
#include "vsim/cuda_fem/CudaStaticWall.h"
#include "vsim/cuda_smoke/CudaSmokeBackend.h"
#include "vsim/cuda_sph/CudaSph.h"

namespace {

vsim::app::GpuPluginApi makeTable()
{
    vsim::app::GpuPluginApi table;
    table.applicationVersion = vsim::kVersion;
    table.runtimeVersion = [] { return vsim::cuda::runtimeVersion(); };
    table.deviceCount = [] { return int(vsim::cuda::devices().size()); };
    table.deviceSummary = [] { return vsim::cuda::deviceSummary(); };
    table.wallStepperFactory = [] { return vsim::cuda::cudaStepperFactory(); };
    table.wallStaticModelFactory = [] { return vsim::cuda::cudaStaticWallFactory(); };
    table.sphStepperFactory = [] { return vsim::cuda::cudaSphStepperFactory(); };
    table.smokeBackendFactory = [] { return vsim::cuda::cudaSmokeBackendFactory(); };
    return table;
}

} // namespace

extern "C" __attribute__((visibility("default"))) const vsim::app::GpuPluginApi* vascusimGpuPlugin()
{
    static const vsim::app::GpuPluginApi table = makeTable();
    return &table;
}
