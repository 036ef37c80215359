#include "vsim/sim/sph/SphValidation.h"

#include "SphCases.h"

#include "vsim/core/Error.h"

#include <chrono>

namespace vsim::sim::sph {

std::vector<std::string> sphValidationCases()
{
    return {"sph-kernel", "sph-fpm", "sph-hydrostatic", "sph-poiseuille", "sph-womersley", "sph-mass", "sph-stenosis"};
}

ValidationResult runSphValidation(const std::string& name, const Progress& progress)
{
    const auto start = std::chrono::steady_clock::now();
    ValidationResult result;
    if (name == "sph-kernel")
        result = detail::kernelCase();
    else if (name == "sph-fpm")
        result = detail::fpmCase(progress);
    else if (name == "sph-hydrostatic")
        result = detail::hydrostaticCase(progress);
    else if (name == "sph-poiseuille")
        result = detail::poiseuilleCase(progress);
    else if (name == "sph-womersley")
        result = detail::womersleyCase(progress);
    else if (name == "sph-mass")
        result = detail::massCase(progress);
    else if (name == "sph-stenosis")
        result = detail::stenosisCase(progress);
    else
        throw Error(Pattern{"unknown validation case '%1' (known: sph-kernel, sph-fpm, sph-hydrostatic, "
                            "sph-poiseuille, sph-womersley, sph-mass, sph-stenosis)",
                            {name}});
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

} // namespace vsim::sim::sph
