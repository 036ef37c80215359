#include "vsim/core/Validation.h"

#include <cmath>

namespace vsim {

bool ValidationFigure::passed() const { return std::abs(measured - expected) <= tolerance; }

bool ValidationResult::passed() const
{
    for (const ValidationFigure& figure : figures)
        if (!figure.passed())
            return false;
    return !figures.empty();
}

} // namespace vsim
