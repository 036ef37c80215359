#include "vsim/sim/fem/QuasiStaticTearingSolver.h"

#include "vsim/core/Error.h"
#include "vsim/core/Localized.h"
#include "vsim/core/Parameters.h"
#include "vsim/core/StoredText.h"

#include <algorithm>
#include <cstdio>

namespace vsim::sim::fem {
namespace {

/// The modified Newton iteration's update budget, in multiples of the full one's.
constexpr int kModifiedNewtonUpdates = 5;

std::string megapascals(double pa)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.4g MPa", pa * 1e-6);
    return text;
}

} // namespace

QuasiStaticTearingSolver::QuasiStaticTearingSolver(QuasiStaticTearingSetup setup) : m_setup(std::move(setup))
{
    m_setup.wall = {};
}

QuasiStaticTearingSolver::~QuasiStaticTearingSolver() = default;

void QuasiStaticTearingSolver::initialize(const SimulationInput& input, const ParameterSet&)
{
    const QuasiStaticTearingSetup& s = m_setup;
    if (!(s.incrementPa > 0.0) || !(s.endPa > s.startPa) || s.startPa < 0.0 || !(s.tearStressPa > 0.0) ||
        !(s.onsetTolerance > 0.0 && s.onsetTolerance < 0.5))
        throw Error("quasi-static tearing needs a ramp start < end, a positive increment and tear strength, and an "
                    "onset tolerance in (0, 0.5)");
    BackwardEulerSettings unused; // no time steps: equilibria only
    m_wall = std::make_unique<WallSimulation>(input.get<TetMesh>("wall"), s.material, unused, s.loaded);
    m_wall->setTearStrength(s.tearStressPa);
    m_wall->setEquilibriumSolver(s.modifiedNewton, s.equilibriumElsewhere);
    m_lastGood = m_wall->frame(); // the rest state: the equilibrium without pressure
    m_lastGoodPressure = 0.0, m_onset = -1.0, m_bracket = 0.0, m_firstTorn = 0, m_solves = m_failed = 0;
    m_releasePending = false, m_startProblem.clear(), m_after.clear(), m_entropyCurve.clear();
    m_startStatus = RunStatus{};
    m_startStatus.forceTolerance = s.equilibriumTolerance;
    m_safe = s.startPa;
    if (!equilibrium(m_safe, m_startStatus, {}))
        m_startProblem = storedText(
            Pattern{"the equilibrium at the ramp's start %1 failed: %2", {megapascals(m_safe), m_failure}});
    else if (!m_wall->elementsOverTearStrength().empty())
        m_startProblem = storedText(Pattern{
            "elements are over the tear strength already at the ramp's start %1: start lower", {megapascals(m_safe)}});
    m_safeState = m_wall->model().positions();
    m_after.emplace_back(m_lastGoodPressure, m_solves);
}

bool QuasiStaticTearingSolver::equilibrium(double pressure, RunStatus& status, const Progress& progress)
{
    progress.throwIfCancelled();
    m_wall->setPressure(pressure);
    m_failure.clear();
    // The modified iteration converges linearly: 8-13 updates an equilibrium on the thinned tube against the full
    // one's 3 (tst_fem_tearing).
    const int maxUpdates = m_setup.equilibriumMaxUpdates * (m_setup.modifiedNewton ? kModifiedNewtonUpdates : 1);
    const StaticSolveReport report = m_wall->equilibrate(m_setup.equilibriumTolerance, maxUpdates, &m_failure);
    ++m_solves;
    // The run status records the equilibria the frames come from; a failed one leaves the state as it was.
    if (report.converged)
    {
        for (std::size_t u = 0; u < report.linearResiduals.size(); ++u)
            status.recordSolve(report.linearIterations[u], report.linearResiduals[u], 1e-8, 0);
        status.forceResidual = report.forceResidual;
        m_lastGood = m_wall->frame();
        m_lastGoodPressure = pressure;
        return true;
    }
    ++m_failed;
    if (m_failure.empty())
        m_failure = storedText(Pattern{"no equilibrium in %1 Newton updates (force residual %2)",
                                       {std::to_string(report.updates), numberText(report.forceResidual)}});
    return false;
}

StepOutcome QuasiStaticTearingSolver::record(StepOutcome outcome)
{
    m_after.emplace_back(m_lastGoodPressure, m_solves);
    return outcome;
}

StepOutcome QuasiStaticTearingSolver::step(RunStatus& status, const Progress& progress)
{
    if (m_after.size() == 1) // the first step: the start's equilibrium is the run's first solve
    {
        if (status.solves == 0)
            status = m_startStatus;
        if (!m_startProblem.empty())
            return record(StepOutcome::guard(m_startProblem));
    }
    if (m_releasePending)
        return record(release(status, progress));
    progress.report(m_safe / m_setup.endPa, withArguments(localized("vsim::Progress", "quasi-static tearing at %1"), {megapascals(m_safe)})); // the axis's share
    m_over = std::min(m_setup.endPa, m_safe + m_setup.incrementPa);
    if (!equilibrium(m_over, status, progress))
        return record(equilibriumFailed());
    if (m_wall->elementsOverTearStrength().empty())
    {
        m_safe = m_over;
        m_safeState = m_wall->model().positions();
        return record({});
    }
    // Bisection of [safe, over] to the onset tolerance, each trial from the state at `safe`.
    double safe = m_safe;
    while (m_over - safe > m_setup.onsetTolerance * m_over)
    {
        const double middle = 0.5 * (safe + m_over);
        m_wall->restore(m_safeState);
        if (!equilibrium(middle, status, progress))
            break; // keep the bracket: the upper end's equilibrium is known
        if (m_wall->elementsOverTearStrength().empty())
            safe = middle, m_safeState = m_wall->model().positions();
        else
            m_over = middle;
    }
    m_wall->restore(m_safeState);
    if (!equilibrium(m_over, status, progress))
        return record(equilibriumFailed());
    if (m_onset < 0.0)
    {
        m_onset = m_over, m_bracket = m_over - safe;
        m_releasePending = true; // the onset's equilibrium is a frame before any release
        StepOutcome onset;
        onset.keyFrame = true;
        return record(onset);
    }
    return record(release(status, progress));
}

StepOutcome QuasiStaticTearingSolver::equilibriumFailed() const
{
    return StepOutcome::guard(
        storedText(Pattern{"the equilibrium at %1 failed: %2", {megapascals(m_over), m_failure}}));
}

StepOutcome QuasiStaticTearingSolver::release(RunStatus& status, const Progress& progress)
{
    m_releasePending = false;
    for (std::vector<std::size_t> over = m_wall->elementsOverTearStrength(); !over.empty();
         over = m_wall->elementsOverTearStrength())
    {
        if (m_wall->entropy().tornElements() == 0)
            m_firstTorn = m_wall->originalElement(over.front());
        m_wall->tearElements({over.front()});
        m_entropyCurve.emplace_back(m_over, m_wall->entropy().value());
        if (m_setup.entropyEnd > 0.0 && m_wall->entropy().value() > m_setup.entropyEnd)
            return {StepOutcome::Kind::EndCondition,
                    storedText(Pattern{"the fracture entropy passed %1 nats at %2",
                                       {numberText(m_setup.entropyEnd), megapascals(m_over)}})};
        if (int(m_wall->entropy().tornElements()) >= m_setup.maxTears)
            return {StepOutcome::Kind::EndCondition,
                    storedText(Pattern{"%1 elements torn at %2", {std::to_string(m_setup.maxTears), megapascals(m_over)}})};
        if (!equilibrium(m_over, status, progress))
            return {StepOutcome::Kind::EndCondition,
                    storedText(Pattern{"the torn wall holds no equilibrium at %1 (rupture): %2",
                                       {megapascals(m_over), m_failure}})};
    }
    m_safe = m_over;
    m_safeState = m_wall->model().positions();
    StepOutcome released;
    released.keyFrame = true;
    return released;
}

std::map<std::string, double> QuasiStaticTearingSolver::metrics() const
{
    return {{"final_pressure_kpa", m_lastGoodPressure * 1e-3},
            {"tear_onset_pressure_mpa", m_onset >= 0.0 ? m_onset * 1e-6 : -1.0},
            {"tear_onset_bracket_mpa", m_bracket * 1e-6},
            {"first_torn_element", m_onset >= 0.0 ? double(m_firstTorn) : -1.0},
            {"torn_elements", double(m_wall->entropy().tornElements())},
            {"fracture_entropy", m_wall->entropy().value()},
            {"equilibrium_solves", double(m_solves)},
            {"failed_equilibria", double(m_failed)}};
}

} // namespace vsim::sim::fem
