#pragma once

// When a time average takes its next sample (issue 18: the sections' flow, the wall loads): every N-th step from a
// start time on, each sample weighted by the time since the last one taken, so that sampling every N-th step
// averages the same window as sampling every step.

#include <algorithm>

namespace vsim::sim::sph {

class SampleSchedule
{
public:
    SampleSchedule() = default;
    SampleSchedule(double fromTimeS, int everySteps) : m_from(fromTimeS), m_every(std::max(1, everySteps)) {}

    /// Called once a step at time t (s) that held for `stepS`: the weight (s) of the sample due now, 0 when none is.
    double due(double timeS, double stepS)
    {
        if (timeS < m_from || !(stepS > 0.0))
            return 0.0;
        m_pending += stepS;
        if (m_calls++ % m_every != 0)
            return 0.0;
        const double weight = m_pending;
        m_pending = 0.0;
        return weight;
    }
    void reset() { m_pending = 0.0, m_calls = 0; }
    /// Every call takes its sample from now on (a caller that already samples at its own cadence: SphSolver with
    /// another stepper).
    void everyCall() { m_every = 1; }
    /// Where it stands (SphCheckpoint.h): the time since the last sample taken (s) and the calls so far.
    struct State
    {
        double pendingS = 0.0;
        long calls = 0;
    };
    State state() const { return {m_pending, m_calls}; }
    void restore(State state) { m_pending = state.pendingS, m_calls = state.calls; }

private:
    double m_from = 0.0, m_pending = 0.0; ///< s; m_pending: since the last sample taken
    int m_every = 1;
    long m_calls = 0;
};

} // namespace vsim::sim::sph
