#pragma once

// The projection's first guess: psi (= dt p / rho) extrapolated from the last two steps' projections, linear in
// time for the pressure p (a second-order start where the last projection alone is a first-order one). Over steps
// dt_{n-1}, dt_n and the coming dt, with s = dt / dt_n and s' = dt_n / dt_{n-1}:
//   p_guess = p_n + s (p_n - p_{n-1})  =>  psi_guess = s (1 + s) psi_n - s^2 s' psi_{n-1}.
// Only a starting point: the solve still runs to its tolerance, so a poor guess costs iterations, not accuracy.
// Steps whose lengths differ by more than a factor 2 (the run's last, shortened step; a projection outside a
// step) fall back to psi_n as it is, the warm start the projection had before.

namespace vsim::sim::smoke {

class PressureWarmStart
{
public:
    /// psi_guess = current psi_n + previous psi_{n-1}.
    struct Weights
    {
        float current = 1.0f;
        float previous = 0.0f;
    };

    /// The weights for a projection ending a step of `stepS` seconds (<= 0: a projection outside a step).
    Weights weights(double stepS) const;
    /// Records the projection just made (`stepS` as given to weights(); <= 0 forgets the history).
    void record(double stepS);

private:
    double m_lastS = 0.0;     ///< dt_n (0: no projection of a step yet)
    double m_previousS = 0.0; ///< dt_{n-1} (0: none)
};

} // namespace vsim::sim::smoke
