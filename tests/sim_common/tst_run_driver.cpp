// The run driver (sim/common/RunDriver.h) on the template solver and on a solver that breaks on purpose: frames by
// steps and by the axis, every Nth kept, the end reached; a cancel, a guard, a frame that is not finite and the step
// limit each ending the run with its status and the last good state as the last frame; bad input refused before
// anything runs.

#include "vsim/core/Error.h"
#include "vsim/sim/common/RunDriver.h"
#include "vsim/sim/heat/HeatDiffusion.h"

#include <QtTest>

#include <cmath>

using namespace vsim;
using namespace vsim::sim;

namespace {

ParameterSet heatParameters(double endTimeS = 60.0, double stepFraction = 0.9, int cells = 16)
{
    ParameterSet parameters(heat::heatParameters());
    parameters.set("end_time_s", endTimeS);
    parameters.set("time_step_fraction", stepFraction);
    parameters.set("cells", cells);
    return parameters;
}

double peakOf(const RunFrame& frame)
{
    const RealVolume& rise = std::get<GridFields>(frame.data).fields.at("temperature_rise_k");
    return *std::max_element(rise.data(), rise.data() + rise.size());
}

/// A one-number solver whose value turns NaN at step `breakAt` without noticing (the driver's frame guard must).
class BreakingSolver : public Solver
{
public:
    explicit BreakingSolver(int breakAt, int keyFrameAt = -1) : m_breakAt(breakAt), m_keyFrameAt(keyFrameAt) {}
    std::string name() const override { return "breaking"; }
    std::vector<ParameterSpec> parameters() const override { return {}; }
    void initialize(const SimulationInput&, const ParameterSet&) override { m_step = 0; }
    RunAxis axis() const override { return {"time", "s", 10.0}; }
    double position() const override { return m_step; }
    StepOutcome step(RunStatus& status, const Progress&) override
    {
        ++m_step;
        status.recordSolve(3, 1e-9, 1e-8, 100);
        StepOutcome outcome;
        outcome.keyFrame = m_step == m_keyFrameAt;
        return outcome;
    }
    SimulationData snapshot() const override
    {
        VesselNetwork network;
        network.nodes = {{Eigen::Vector3d::Zero(), ""}, {Eigen::Vector3d(1, 0, 0), ""}};
        network.segments.push_back({0, 1, 1.0, 1.0, 1.0, 0.0, {}});
        network.segmentFields["value"] = {m_step >= m_breakAt ? std::nan("") : double(m_step)};
        return network;
    }
    std::map<std::string, double> metrics() const override { return {{"steps_taken", double(m_step)}}; }

private:
    int m_breakAt = 0, m_keyFrameAt = -1;
    int m_step = 0;
};

} // namespace

class RunDriver : public QObject
{
    Q_OBJECT
private slots:
    /// The guard's finder names the first value that is not finite in every kind of frame (particles included).
    void firstNonFiniteNamesTheValue()
    {
        ParticleSet particles;
        particles.positionsMm = {{0, 0, 0}, {1, 0, 0}};
        particles.fields["speed_m_s"] = {0.5, 0.25};
        QVERIFY(!firstNonFinite(particles));
        particles.fields["speed_m_s"][1] = std::nan("");
        QCOMPARE(*firstNonFinite(particles), std::string("particle field speed_m_s at particle 1"));
        particles.positionsMm[0].y() = INFINITY;
        QCOMPARE(*firstNonFinite(particles), std::string("particle 0's position"));
        particles.fields["pressure_pa"] = {1.0};
        QVERIFY_THROWS_EXCEPTION(Error, particles.validate());
        QCOMPARE(dataKindName(particles), std::string("particle set"));
    }

    void framesEveryStepsKeepEveryNth()
    {
        heat::HeatDiffusionSolver solver;
        RunControl control;
        control.frameEverySteps = 10, control.keepEvery = 3;
        const SolverRun run = runSolver(solver, {}, heatParameters(), control);
        QCOMPARE(run.status.stoppedBy, RunStatus::StoppedBy::End);
        QVERIFY(run.status.converged() && run.status.complete());
        QCOMPARE(run.status.reached, 60.0);
        QCOMPARE(run.status.reachedUnit, std::string("s"));
        const long expectedTaken = 1 + run.steps / 10 + (run.steps % 10 ? 1 : 0);
        QCOMPARE(long(run.framesTaken), expectedTaken);
        QCOMPARE(run.frames.size(), run.keptFrameNumbers.size());
        for (std::size_t f = 0; f + 1 < run.frames.size(); ++f)
        {
            QCOMPARE(run.frames[f].number % 3, 0);
            QCOMPARE(run.frames[f].step, long(run.frames[f].number) * 10);
        }
        QCOMPARE(run.frames.back().step, run.steps);
        QCOMPARE(run.frames.back().number, run.framesTaken - 1);
        QCOMPARE(run.frames.back().position, 60.0);
        QCOMPARE(run.metrics.at("run_steps"), double(run.steps));
        QCOMPARE(run.metrics.at("run_frames_kept"), double(run.frames.size()));
        QCOMPARE(run.provenance.solver, std::string("heat"));
        QCOMPARE(run.provenance.parameters.at("keep_every"), std::string("3"));
        QCOMPARE(run.provenance.parameters.at("end_time_s"), std::string("60"));
        // The field decays: each kept frame's peak below the one before.
        for (std::size_t f = 1; f < run.frames.size(); ++f)
            QVERIFY(peakOf(run.frames[f]) < peakOf(run.frames[f - 1]));
    }

    void framesEveryAxisInterval()
    {
        heat::HeatDiffusionSolver solver;
        RunControl control;
        control.frameEvery = 10.0;
        std::vector<double> streamed;
        control.keepFramesInMemory = false;
        control.frameSink = [&](const RunFrame& frame) { streamed.push_back(frame.position); };
        const SolverRun run = runSolver(solver, {}, heatParameters(), control);
        QVERIFY(run.frames.empty());
        QCOMPARE(streamed.size(), std::size_t(7)); // 0, then past 10, 20, ..., 60 s
        const double dt = run.metrics.at("time_step_s");
        for (std::size_t f = 1; f < streamed.size(); ++f)
        {
            QVERIFY(streamed[f] >= 10.0 * double(f) - 1e-9);
            QVERIFY(streamed[f] < 10.0 * double(f) + dt);
        }
        QCOMPARE(streamed.back(), 60.0);
    }

    void cancelKeepsTheLastGoodState()
    {
        heat::HeatDiffusionSolver solver;
        CancellationToken token;
        RunControl control;
        control.frameEverySteps = 5;
        control.frameSink = [&](const RunFrame& frame) {
            if (frame.number == 2)
                token.cancel();
        };
        const SolverRun run = runSolver(solver, {}, heatParameters(), control, Progress({}, token));
        QCOMPARE(run.status.stoppedBy, RunStatus::StoppedBy::Cancel);
        QVERIFY(!run.status.complete());
        QCOMPARE(run.steps, 10L);
        QCOMPARE(run.frames.back().step, 10L); // the state the run stopped at (its frame was already taken)
        QVERIFY(run.status.reached < run.status.target);
        QCOMPARE(run.metrics.at("run_complete"), 0.0);
        QVERIFY(run.status.stopText().find("cancel") != std::string::npos);
    }

    void guardKeepsTheLastGoodState()
    {
        heat::HeatDiffusionSolver solver;
        RunControl control;
        control.frameEverySteps = 50; // the guard comes between frames: the driver adds the last good state
        const SolverRun run = runSolver(solver, {}, heatParameters(600.0, 1.9), control);
        QCOMPARE(run.status.stoppedBy, RunStatus::StoppedBy::Guard);
        QVERIFY2(run.status.stopMessage.find("unstable") != std::string::npos, run.status.stopMessage.c_str());
        qInfo("guard: %s", run.status.stopText().c_str());
        QVERIFY(run.steps > 0 && run.steps % 50 != 0);
        QCOMPARE(run.frames.back().step, run.steps);
        QVERIFY(peakOf(run.frames.back()) <= 10.0);
        QVERIFY(run.status.reached < 600.0);
    }

    void frameThatIsNotFiniteIsAGuard()
    {
        BreakingSolver solver(4);
        RunControl control;
        control.frameEverySteps = 1;
        const SolverRun run = runSolver(solver, {}, ParameterSet(std::vector<ParameterSpec>{}), control);
        QCOMPARE(run.status.stoppedBy, RunStatus::StoppedBy::Guard);
        QVERIFY2(run.status.stopMessage.find("segment field value at segment 0") != std::string::npos,
                 run.status.stopMessage.c_str());
        QCOMPARE(run.frames.back().step, 3L); // the frame before the broken one
        QCOMPARE(run.status.solves, 4L);
        QVERIFY(run.status.converged());
    }

    void keyFramesBetweenTheSchedule()
    {
        BreakingSolver solver(100, 4); // never breaks; asks for a frame after step 4
        const SolverRun run = runSolver(solver, {}, ParameterSet(std::vector<ParameterSpec>{}), RunControl{});
        QCOMPARE(run.status.stoppedBy, RunStatus::StoppedBy::End);
        QCOMPARE(run.frames.size(), std::size_t(3)); // the first, the key frame, the last
        QCOMPARE(run.frames[1].step, 4L);
        QCOMPARE(run.frames[2].step, 10L);
    }

    void stepLimitStopsTheRun()
    {
        heat::HeatDiffusionSolver solver;
        RunControl control;
        control.maxSteps = 5;
        const SolverRun run = runSolver(solver, {}, heatParameters(), control);
        QCOMPARE(run.status.stoppedBy, RunStatus::StoppedBy::Guard);
        QVERIFY(run.status.stopMessage.find("step limit of 5") != std::string::npos);
        QCOMPARE(run.frames.back().step, 5L);
        QCOMPARE(run.frames.size(), std::size_t(2));
    }

    void runControlFromParameters()
    {
        ParameterSet parameters(runControlParameters());
        parameters.setFromText("frame_every_steps=20");
        parameters.setFromText("keep_every=4");
        const RunControl control = runControlFrom(parameters);
        QCOMPARE(control.frameEverySteps, 20);
        QCOMPARE(control.keepEvery, 4);
        QCOMPARE(control.frameEvery, 0.0);
        QVERIFY_THROWS_EXCEPTION(Error, parameters.setFromText("keep_every=0"));
    }

    void badInputIsRefusedBeforeRunning()
    {
        heat::HeatDiffusionSolver solver;
        SimulationInput input;
        input.data.emplace("wall", TetMesh{});
        bool framed = false;
        RunControl control;
        control.frameSink = [&](const RunFrame&) { framed = true; };
        QVERIFY_THROWS_EXCEPTION(Error, runSolver(solver, input, heatParameters(), control));
        QVERIFY(!framed);
        try
        {
            input.get<VesselNetwork>("wall");
            QFAIL("no error");
        }
        catch (const Error& error)
        {
            QCOMPARE(std::string(error.what()), std::string("the solver's input 'wall' must be a vessel network, not a tet mesh"));
        }
        QVERIFY_THROWS_EXCEPTION(Error, input.get<TetMesh>("network"));
    }
};

QTEST_GUILESS_MAIN(RunDriver)
#include "tst_run_driver.moc"
