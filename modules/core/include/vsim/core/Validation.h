#pragma once

// The result of an analytic validation case (`vascusim-cli validate <case>`): figures compared with their
// expected values within a stated tolerance. Every solver's cases report in this form.

#include <string>
#include <vector>

namespace vsim {

struct ValidationFigure
{
    std::string name;
    double measured = 0.0;
    double expected = 0.0;
    double tolerance = 0.0; ///< allowed |measured - expected| (absolute, in the figure's unit)
    std::string unit;
    bool passed() const;
};

struct ValidationResult
{
    std::string name;
    std::string description; ///< what is compared with what
    std::vector<ValidationFigure> figures;
    double seconds = 0.0;
    /// True when there are figures and every one is within its tolerance.
    bool passed() const;
};

/// The solver settings a solver's validation cases run with, to set beside a reported run's.
struct ValidationConfiguration
{
    std::string backend = "cpu";
    int iterationCap = 0;          ///< largest iterations per linear solve (0: direct solves)
    double loosestTolerance = 0.0; ///< the loosest relative residual any case solves to (0: direct)
    std::string text;              ///< the same for people
};

} // namespace vsim
