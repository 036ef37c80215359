#include "vsim/app/DamBreakValidationRun.h"

#include "BackendChoice.h"
#include "GpuPlugin.h"
#include "SphPipelineSupport.h"

#include "vsim/core/Error.h"
#include "vsim/core/StoredText.h"

#include <chrono>

namespace vsim::app {
namespace {

Pattern leftOut(const std::string& unavailable)
{
    return Pattern{"sph-dambreak needs a GPU at its million particles (about 20 hours on 2 CPU cores): %1; "
                   "validate sph-dambreak --backend cpu [--particles N] runs it on the CPU",
                   {unavailable}};
}

} // namespace

std::string whyDamBreakLeftOut(const std::string& backend)
{
    if (backend != "auto") // "cpu" runs it; "cuda" without a GPU, and an unknown name, are refused when it runs
        return {};
    const std::string unavailable = gpuUnavailableReason();
    if (unavailable.empty())
        return {};
    return storedText(leftOut(unavailable));
}

ValidationResult validateDamBreak(const std::string& backend, const sim::sph::DamBreakCheckOptions& options,
                                  const Progress& progress)
{
    std::string device;
    if (backend == "auto")
        if (const std::string unavailable = gpuUnavailableReason(); !unavailable.empty())
            throw Error(leftOut(unavailable));
    std::vector<std::string> warnings;
    const sim::sph::SphStepperFactory stepper = chooseSphStepper(backend, device, warnings);
    const auto start = std::chrono::steady_clock::now();
    ValidationResult result = sim::sph::damBreakValidation(sim::sph::runDamBreakCheck(options, stepper, progress));
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!device.empty())
        result.description += "; " + device;
    for (const std::string& warning : warnings)
        result.description += "; " + warning;
    return result;
}

} // namespace vsim::app
