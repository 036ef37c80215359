#include "vsim/sim/fem/QuasiStaticTearing.h"

#include "vsim/core/Error.h"
#include "vsim/sim/fem/WallSimulation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vsim::sim::fem {
namespace {

std::string megapascals(double pa)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.4g MPa", pa * 1e-6);
    return text;
}

} // namespace

FemRunResult runQuasiStaticTearing(const QuasiStaticTearingSetup& setup, const Progress& progress)
{
    if (!(setup.incrementPa > 0.0) || !(setup.endPa > setup.startPa) || setup.startPa < 0.0 ||
        !(setup.tearStressPa > 0.0) || !(setup.onsetTolerance > 0.0 && setup.onsetTolerance < 0.5))
        throw Error("quasi-static tearing needs a ramp start < end, a positive increment and tear strength, and an "
                    "onset tolerance in (0, 0.5)");
    BackwardEulerSettings unused; // no time steps: equilibria only
    WallSimulation wall(setup.wall, setup.material, unused, setup.loaded);
    wall.setTearStrength(setup.tearStressPa);

    FemRunResult result;
    RunStatus& status = result.status;
    status.forceTolerance = setup.equilibriumTolerance;
    status.reachedQuantity = "pressure";
    status.reachedUnit = "kPa";
    status.target = setup.endPa * 1e-3;
    int solves = 0, failed = 0;
    // The frames show converged equilibria only; the last one the run reached is kept for its end.
    TetMesh lastGood = wall.frame(); // the rest state: the equilibrium without pressure
    double lastGoodPressure = 0.0;
    const auto addFrame = [&](const TetMesh& frame, double pressure) {
        result.frames.push_back(frame);
        result.frameTimesS.push_back(double(solves)); // pseudo-time: the equilibria solved so far
        result.framePressuresPa.push_back(pressure);
    };
    // The equilibrium at `pressure` from the wall's current state; false when it fails (restored then).
    std::string failure;
    const auto equilibrium = [&](double pressure) {
        progress.throwIfCancelled();
        wall.setPressure(pressure);
        failure.clear();
        const StaticSolveReport report = wall.equilibrate(setup.equilibriumTolerance, setup.equilibriumMaxUpdates, &failure);
        ++solves;
        // The run status records the equilibria the frames come from; a failed one leaves the state as it was.
        if (report.converged)
        {
            for (std::size_t u = 0; u < report.linearResiduals.size(); ++u)
                status.recordSolve(report.linearIterations[u], report.linearResiduals[u], 1e-8, 0);
            status.forceResidual = report.forceResidual;
            lastGood = wall.frame();
            lastGoodPressure = pressure;
            return true;
        }
        ++failed;
        if (failure.empty())
            failure = "no equilibrium in " + std::to_string(report.updates) + " Newton updates (force residual " +
                      std::to_string(report.forceResidual) + ")";
        return false;
    };
    const auto stop = [&](RunStatus::StoppedBy by, const std::string& why) {
        status.stoppedBy = by;
        status.stopMessage = why;
        result.stopReason = why;
    };

    double safe = setup.startPa, onset = -1.0, bracket = 0.0;
    std::size_t firstTorn = 0;
    if (!equilibrium(safe))
        stop(RunStatus::StoppedBy::Guard, "the equilibrium at the ramp's start " + megapascals(safe) + " failed: " + failure);
    else if (!wall.elementsOverTearStrength().empty())
        stop(RunStatus::StoppedBy::Guard, "elements are over the tear strength already at the ramp's start " +
                                              megapascals(safe) + ": start lower");
    addFrame(lastGood, lastGoodPressure);
    Eigen::VectorXd safeState = wall.model().positions();
    while (status.stoppedBy == RunStatus::StoppedBy::End && safe < setup.endPa)
    {
        progress.report((safe - setup.startPa) / (setup.endPa - setup.startPa),
                        "quasi-static tearing at " + megapascals(safe));
        double over = std::min(setup.endPa, safe + setup.incrementPa);
        if (!equilibrium(over))
        {
            stop(RunStatus::StoppedBy::Guard, "the equilibrium at " + megapascals(over) + " failed: " + failure);
            break;
        }
        if (wall.elementsOverTearStrength().empty())
        {
            safe = over;
            safeState = wall.model().positions();
            continue;
        }
        // Bisection of [safe, over] to the onset tolerance, each trial from the state at `safe`.
        while (over - safe > setup.onsetTolerance * over)
        {
            const double middle = 0.5 * (safe + over);
            wall.restore(safeState);
            if (!equilibrium(middle))
                break; // keep the bracket: the upper end's equilibrium is known
            if (wall.elementsOverTearStrength().empty())
                safe = middle, safeState = wall.model().positions();
            else
                over = middle;
        }
        wall.restore(safeState);
        if (!equilibrium(over))
        {
            stop(RunStatus::StoppedBy::Guard, "the equilibrium at " + megapascals(over) + " failed: " + failure);
            break;
        }
        if (onset < 0.0)
        {
            onset = over, bracket = over - safe;
            addFrame(lastGood, over); // the onset's equilibrium, before any release
        }
        // Release the most stressed element and re-solve, one at a time, until none is over its strength.
        for (std::vector<std::size_t> overStrength = wall.elementsOverTearStrength(); !overStrength.empty();
             overStrength = wall.elementsOverTearStrength())
        {
            if (wall.entropy().tornElements() == 0)
                firstTorn = wall.originalElement(overStrength.front());
            wall.tearElements({overStrength.front()});
            result.entropyCurve.emplace_back(over, wall.entropy().value());
            if (setup.entropyEnd > 0.0 && wall.entropy().value() > setup.entropyEnd)
            {
                stop(RunStatus::StoppedBy::EndCondition, "the fracture entropy passed " + std::to_string(setup.entropyEnd) +
                                                             " nats at " + megapascals(over));
                break;
            }
            if (int(wall.entropy().tornElements()) >= setup.maxTears)
            {
                stop(RunStatus::StoppedBy::EndCondition,
                     std::to_string(setup.maxTears) + " elements torn at " + megapascals(over));
                break;
            }
            if (!equilibrium(over))
            {
                stop(RunStatus::StoppedBy::EndCondition, "the torn wall holds no equilibrium at " + megapascals(over) +
                                                             " (rupture): " + failure);
                break;
            }
        }
        if (status.stoppedBy != RunStatus::StoppedBy::End)
            break;
        safe = over;
        safeState = wall.model().positions();
        addFrame(lastGood, safe);
    }
    if (result.framePressuresPa.back() != lastGoodPressure || result.frames.back().tets.size() != lastGood.tets.size())
        addFrame(lastGood, lastGoodPressure);

    addPeakMetrics(result);
    result.metrics["final_pressure_kpa"] = lastGoodPressure * 1e-3;
    result.metrics["tear_onset_pressure_mpa"] = onset >= 0.0 ? onset * 1e-6 : -1.0;
    result.metrics["tear_onset_bracket_mpa"] = bracket * 1e-6;
    result.metrics["first_torn_element"] = onset >= 0.0 ? double(firstTorn) : -1.0;
    result.metrics["torn_elements"] = double(wall.entropy().tornElements());
    result.metrics["fracture_entropy"] = wall.entropy().value();
    result.metrics["equilibrium_solves"] = double(solves);
    result.metrics["failed_equilibria"] = double(failed);
    status.reached = lastGoodPressure * 1e-3;
    for (const auto& [key, value] : status.metrics())
        result.metrics[key] = value;
    return result;
}

} // namespace vsim::sim::fem
