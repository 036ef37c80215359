#pragma once

// Numbers shown on screen in the reader's locale (issue 20, item 7): QLocale's default follows the workstation's
// language (gui Languages.cpp), so a German reader sees 3,5 mm. Texts that are parsed back (coordinates typed
// into a field) keep the '.' and do not use this.

#include <QString>

namespace vsim::viz {

/// `value` with `decimals` digits after the locale's decimal mark, without group separators ("12345,6"); a value
/// that rounds to zero has no minus sign.
QString decimalText(double value, int decimals);

/// `value` with `digits` significant digits in the locale's decimal mark ("0,0031", "1,2e+05"), as 'g' prints.
QString significantText(double value, int digits);

} // namespace vsim::viz
