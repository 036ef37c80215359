#include "vsim/sim/heat/HeatValidation.h"

#include "vsim/core/Error.h"
#include "vsim/core/StoredText.h"
#include "vsim/sim/common/RunDriver.h"
#include "vsim/sim/heat/HeatDiffusion.h"

#include <chrono>
#include <cmath>
#include <numbers>

namespace vsim::sim::heat {
namespace {

/// The relative L2 error after one decay time on `cells` cells, run on the driver.
double decayError(int cells, const Progress& progress)
{
    ParameterSet parameters(heatParameters());
    parameters.set("cells", cells);
    const double box = parameters.get("box_mm"), diffusivity = parameters.get("diffusivity_mm2_s");
    parameters.set("end_time_s", box * box / (3.0 * std::numbers::pi * std::numbers::pi * diffusivity));
    HeatDiffusionSolver solver;
    RunControl control;
    control.keepFramesInMemory = false;
    const SolverRun run = runSolver(solver, {}, parameters, control, progress);
    if (!run.status.complete())
        throw Error(Pattern{"heat-decay: the run at %1 cells stopped: %2",
                            {std::to_string(cells), run.status.stopText()}});
    return run.metrics.at("relative_l2_error");
}

} // namespace

std::vector<std::string> heatValidationCases()
{
    return {"heat-decay"};
}

ValidationResult runHeatValidation(const std::string& name, const Progress& progress)
{
    if (name != "heat-decay")
        throw Error(Pattern{"unknown validation case '%1' (known: heat-decay)", {name}});
    const auto start = std::chrono::steady_clock::now();
    ValidationResult result;
    result.name = name;
    result.description = storedText("the slowest mode of a 20 mm cube of tissue (D 0.14 mm^2/s) after one decay time, "
                                    "on the run driver: relative L2 error against the exact solution, and its order "
                                    "of convergence");
    const double coarse = decayError(16, progress.subRange(0.0, 0.1));
    const double middle = decayError(32, progress.subRange(0.1, 0.3));
    const double fine = decayError(64, progress.subRange(0.3, 1.0));
    result.figures.push_back({"relative L2 error at 32 cells", middle, 0.0, 0.005, "relative"});
    result.figures.push_back({"order of convergence 16 -> 32 cells", std::log2(coarse / middle), 2.0, 0.3, ""});
    result.figures.push_back({"order of convergence 32 -> 64 cells", std::log2(middle / fine), 2.0, 0.3, ""});
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

} // namespace vsim::sim::heat
