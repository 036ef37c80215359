#pragma once

// When a smoothed-aggregation hierarchy (AggregationMultigrid.h) is set up again: its coarse levels keep the
// matrix they were set up from while the co-rotational matrix turns with the wall, so the PCG's iterations grow;
// once a solve takes more than `factor` times the iterations of the first solve with the hierarchy, plus 5, the
// next solve sets it up again from its own matrix. One rule for every PCG with the multigrid: the implicit step
// (BackwardEuler, the CUDA stepper) and the static solve's conjugate gradients (TangentSolver, the CUDA static wall).

namespace vsim::sim::fem {

class MultigridSetUpRule
{
public:
    /// `factor`: BackwardEulerSettings::multigridSetUpAgainFactor (0: every second solve).
    explicit MultigridSetUpRule(double factor) : m_factor(factor) {}
    /// A hierarchy was just set up: the next solve is the measure.
    void setUp() { m_first = -1; }
    /// After a solve with the hierarchy that took `iterations`: whether the next solve sets it up again.
    bool setUpAgainAfter(int iterations)
    {
        if (m_first < 0)
        {
            m_first = iterations;
            return false;
        }
        return iterations > m_factor * m_first + 5;
    }

private:
    double m_factor;
    int m_first = -1; ///< iterations of the first solve with the current hierarchy (-1: none yet)
};

} // namespace vsim::sim::fem
