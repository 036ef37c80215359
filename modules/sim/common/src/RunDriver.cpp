#include "vsim/sim/common/RunDriver.h"

#include "vsim/core/Error.h"
#include "vsim/core/StoredText.h"
#include "vsim/core/UtcTime.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace vsim::sim {
namespace {

/// True when `position` has reached `target` (to a relative 1e-9, so that sums of time steps land on it).
bool reached(double position, double target)
{
    return position >= target - 1e-9 * std::max(1.0, std::abs(target));
}

/// The frames of one run: when to take one, which to keep, where they go.
class FrameSchedule
{
public:
    FrameSchedule(const RunControl& control, SolverRun& run) : m_control(control), m_run(run)
    {
        if (control.frameEverySteps < 0 || control.frameEvery < 0.0 || control.keepEvery < 1 || control.maxSteps < 1)
            throw Error("run control: frame intervals must be >= 0, keep_every and max_steps >= 1");
        m_nextPosition = control.frameEvery;
    }

    /// True when the step just taken (at `position`) is due a frame.
    bool due(long step, double position)
    {
        bool take = m_control.frameEverySteps > 0 && step % m_control.frameEverySteps == 0;
        if (m_control.frameEvery > 0.0 && reached(position, m_nextPosition))
        {
            take = true;
            while (reached(position, m_nextPosition))
                m_nextPosition += m_control.frameEvery;
        }
        return take;
    }

    /// Takes `data` as the frame of `step`; `last` frames are always kept. Returns false when the frame holds a value
    /// that is not finite (it is not taken; `why` says where).
    bool take(SimulationData data, long step, double position, bool last, std::string& why)
    {
        if (const auto where = firstNonFinite(data))
        {
            why = storedText(Pattern{"a value that is not finite: %1", {*where}});
            return false;
        }
        RunFrame frame{m_run.framesTaken++, step, position, std::move(data)};
        m_lastStep = step;
        if (last || frame.number % m_control.keepEvery == 0)
            keep(std::move(frame));
        else
            m_pending = std::move(frame), m_hasPending = true;
        return true;
    }

    /// At the end: the last frame taken is kept even when keep_every passed it over.
    void finish()
    {
        if (m_hasPending)
            keep(std::move(m_pending));
    }

    long lastStep() const { return m_lastStep; }

private:
    void keep(RunFrame frame)
    {
        m_hasPending = false;
        m_run.keptFrameNumbers.push_back(frame.number);
        if (m_control.frameSink)
            m_control.frameSink(frame);
        if (m_control.keepFramesInMemory)
            m_run.frames.push_back(std::move(frame));
    }

    const RunControl& m_control;
    SolverRun& m_run;
    double m_nextPosition = 0.0;
    long m_lastStep = -1;
    RunFrame m_pending;
    bool m_hasPending = false;
};

void stop(RunStatus& status, RunStatus::StoppedBy by, std::string message)
{
    status.stoppedBy = by;
    status.stopMessage = std::move(message);
}

} // namespace

std::vector<ParameterSpec> runControlParameters()
{
    using K = ParameterSpec::Kind;
    return {
        {"frame_every_steps", "Frame every N steps", "", 0, 0, 1e9, "Run",
         "a frame after every N steps (0: not by steps; with both intervals 0, only the first and the last frame)", K::Integer},
        {"frame_every", "Frame every", "axis unit", 0, 0, 1e12, "Run",
         "a frame each time the run's axis (simulated time in s, or pressure in kPa) passes a multiple of this (0: not "
         "by the axis)", K::Real},
        {"keep_every", "Keep every Nth frame", "", 1, 1, 1e6, "Run",
         "keep every Nth frame taken (large runs); the first and the last are always kept, and the run lists which", K::Integer},
        {"max_steps", "Step limit", "", 1000000, 1, 1e12, "Run",
         "a run that has not reached its end after this many steps stops with a message (a collapsing time step)", K::Integer},
    };
}

RunControl runControlFrom(const ParameterSet& parameters)
{
    RunControl control;
    control.frameEverySteps = int(parameters.get("frame_every_steps"));
    control.frameEvery = parameters.get("frame_every");
    control.keepEvery = int(parameters.get("keep_every"));
    control.maxSteps = long(parameters.get("max_steps"));
    return control;
}

SolverRun runSolver(Solver& solver, const SimulationInput& input, const ParameterSet& parameters,
                    const RunControl& control, const Progress& progress)
{
    const auto started = std::chrono::steady_clock::now();
    SolverRun run;
    run.provenance = {solver.name(), parameters.valuesAsText(), input.sources, utcTimestamp(), 0.0};
    run.provenance.parameters["frame_every_steps"] = std::to_string(control.frameEverySteps);
    run.provenance.parameters["frame_every"] = numberText(control.frameEvery);
    run.provenance.parameters["keep_every"] = std::to_string(control.keepEvery);
    run.provenance.parameters["max_steps"] = std::to_string(control.maxSteps);
    FrameSchedule frames(control, run);
    solver.initialize(input, parameters);
    run.axis = solver.axis();
    RunStatus& status = run.status;

    std::string why;
    bool stateBroken = false; // a frame showed values that are not finite: no later snapshot is good
    if (!frames.take(solver.snapshot(), 0, solver.position(), false, why))
        throw Error(Pattern{"%1: the initial state holds %2", {solver.name(), why}});
    try
    {
        while (true)
        {
            progress.throwIfCancelled();
            if (reached(solver.position(), run.axis.target))
                break;
            if (run.steps >= control.maxSteps)
            {
                stop(status, RunStatus::StoppedBy::Guard,
                     storedText(Pattern{"the run did not reach its end within the step limit of %1 steps (a "
                                        "collapsing time step?)",
                                        {std::to_string(control.maxSteps)}}));
                break;
            }
            const double before = solver.position();
            const StepOutcome outcome = solver.step(status, progress);
            if (outcome.kind == StepOutcome::Kind::Guard)
            {
                // A guard after the step itself went through (the wall's equilibrium after its last path step)
                // leaves the state of that step: it counts.
                if (solver.position() != before)
                    ++run.steps;
                stop(status, RunStatus::StoppedBy::Guard, outcome.message);
                break;
            }
            ++run.steps;
            if (outcome.kind == StepOutcome::Kind::EndCondition)
                stop(status, RunStatus::StoppedBy::EndCondition, outcome.message);
            const bool ends = outcome.kind != StepOutcome::Kind::Continue || reached(solver.position(), run.axis.target);
            if (frames.due(run.steps, solver.position()) || ends || outcome.keyFrame)
                if (!frames.take(solver.snapshot(), run.steps, solver.position(), ends, why))
                {
                    // The state is broken and the solver did not see it: the frame before stays the last.
                    stateBroken = true;
                    stop(status, RunStatus::StoppedBy::Guard,
                         storedText(Pattern{"step %1 left %2", {std::to_string(run.steps), why}}));
                    break;
                }
            if (ends)
                break;
            const double fraction = run.axis.target > 0.0 ? std::clamp(solver.position() / run.axis.target, 0.0, 1.0) : 1.0;
            progress.report(fraction * solver.axisProgressShare(), solver.name());
        }
    }
    catch (const Cancelled&)
    {
        stop(status, RunStatus::StoppedBy::Cancel, storedText("cancelled by the user"));
    }
    // A guard or a cancel: the solver is at its last good state; keep it as the last frame.
    if (status.stoppedBy == RunStatus::StoppedBy::Guard || status.stoppedBy == RunStatus::StoppedBy::Cancel)
        if (!stateBroken && frames.lastStep() != run.steps)
            frames.take(solver.snapshot(), run.steps, solver.position(), true, why);
    frames.finish();
    // After the loop: a solver may have replaced the status by its final solve's (the wall's equilibrium).
    status.reachedQuantity = run.axis.quantity, status.reachedUnit = run.axis.unit;
    status.reached = solver.position(), status.target = run.axis.target;

    run.metrics = solver.metrics();
    for (const auto& [key, value] : status.metrics())
        run.metrics[key] = value;
    run.provenance.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    run.metrics["run_steps"] = double(run.steps);
    run.metrics["run_frames_taken"] = double(run.framesTaken);
    run.metrics["run_frames_kept"] = double(run.keptFrameNumbers.size());
    run.metrics["run_wall_seconds"] = run.provenance.wallSeconds;
    return run;
}

} // namespace vsim::sim
