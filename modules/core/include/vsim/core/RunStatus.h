#pragma once

// How far a simulation run got and how well its solves converged: one record shared by every solver (wall FEM,
// drug network, and the blood-flow and smoke solvers to come). Every figure a run prints is read against it: a run
// whose solves ended above their tolerance is "not converged", a run stopped by a guard or a cancel states what it
// reached (a pressure or a time) against its target.

#include <map>
#include <string>

namespace vsim {

struct RunStatus
{
    enum class StoppedBy
    {
        End,          ///< ran to its end (the pressure curve or the simulated time)
        EndCondition, ///< a physical end condition of the protocol (e.g. the fracture entropy)
        Guard,        ///< a guard (NaN, inverted elements, solver breakdown): the last good state is kept
        Cancel        ///< the user cancelled
    };

    long solves = 0;             ///< linear (or nonlinear) solves recorded
    long unconvergedSolves = 0;  ///< solves that ended above their tolerance
    long solvesAtCap = 0;        ///< of those, the ones that took the whole iteration cap (the others stopped early:
                                 ///< a breakdown or a stall)
    long iterations = 0;         ///< iterations of all solves together (0 for direct solvers)
    int iterationCap = 0;        ///< the largest number of iterations a solve may take (0: direct)
    double tolerance = 0.0;      ///< relative residual a solve must reach
    double finalResidual = 0.0;  ///< relative residual of the last solve
    double worstResidual = 0.0;  ///< largest relative residual of any solve
    /// Nonlinear solvers whose figures come from an equilibrium: ||f_int - f_ext|| / ||f_ext|| of the final state
    /// against forceTolerance; -1 when the run computes none.
    double forceResidual = -1.0;
    double forceTolerance = 0.0;
    StoppedBy stoppedBy = StoppedBy::End;
    std::string stopMessage;     ///< why it stopped early (guard, end condition), for people
    std::string reachedQuantity; ///< "pressure" or "time"
    std::string reachedUnit;     ///< the unit of reached/target as printed ("kPa", "s")
    double reached = 0.0;        ///< what the run reached, in reachedUnit
    double target = 0.0;         ///< what it was to reach, in reachedUnit

    /// Records one solve: its iterations and its final relative residual against `tolerance` (cap 0: direct).
    void recordSolve(int solveIterations, double residual, double solveTolerance, int cap);
    /// True when every solve reached its tolerance, and the force residual its own (where there is one).
    bool converged() const { return unconvergedSolves == 0 && (forceResidual < 0.0 || forceResidual <= forceTolerance); }
    /// True when the run reached its target (ran to its end or a physical end condition).
    bool complete() const { return stoppedBy == StoppedBy::End || stoppedBy == StoppedBy::EndCondition; }
    /// "converged" or "not converged: 200 of 200 solves ended above their tolerance at the 100-iteration cap, worst
    /// relative residual 3.1e-03 (tolerance 1e-06)"; the cap is named only for the solves that reached it ("3 of
    /// 200 ..., 1 of them at the ..." when the others stopped before it). `forPeople`: in the reader's language (localized(), for reports);
    /// else English, as the study and metrics.json keep it.
    std::string convergenceText(bool forPeople = false) const;
    /// "" when the run ran to its end; else e.g. "stopped by a guard at pressure 9.1 of 16.0 kPa: <message>" (the
    /// solver's message, a stored text: storedTextForPeople() when `forPeople`).
    std::string stopText(bool forPeople = false) const;
    /// What a reader must know before reading the figures: "" when the solves converged and the run reached its
    /// target; else "NOT CONVERGED (...)" and / or "STOPPED EARLY (...)", joined by "; ".
    std::string warningText(bool forPeople = false) const;

    /// The record as run metrics (run_converged 0/1, run_solves, run_unconverged_solves, run_solves_at_cap, run_mean_iterations,
    /// run_iteration_cap, run_tolerance, run_final_residual, run_worst_residual, run_complete 0/1, with a force
    /// residual run_force_residual and run_force_tolerance,
    /// run_reached_<quantity>_<unit>, run_target_<quantity>_<unit>), for the study's attributes and metrics.json.
    std::map<std::string, double> metrics() const;
    /// The record as text attributes (run_stopped_by, run_stop_message, run_convergence).
    std::map<std::string, std::string> attributes() const;
    /// Reads back what metrics() and attributes() wrote (a study's run artifact); missing keys leave defaults.
    static RunStatus fromRecords(const std::map<std::string, double>& metrics,
                                 const std::map<std::string, std::string>& attributes);
};

/// "end", "end condition", "guard", "cancel".
std::string stoppedByName(RunStatus::StoppedBy stoppedBy);

} // namespace vsim
