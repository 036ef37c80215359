#pragma once

// DICOM decimal strings (value representation DS, PS3.5 6.2: at most 16 characters a value) for the writers
// of the dicom module (internal).

#include <cstdio>
#include <initializer_list>
#include <string>

namespace vsim::dicom::detail {

/// `value` as a decimal string with as many significant digits (12 at most) as fit in 16 characters.
inline std::string decimalString(double value)
{
    char buffer[32];
    for (int precision = 12; precision > 1; --precision)
    {
        std::snprintf(buffer, sizeof buffer, "%.*g", precision, value);
        if (std::string(buffer).size() <= 16)
            return buffer;
    }
    return "0";
}

/// Several values as one multi-valued decimal string (backslash-separated).
inline std::string decimalStrings(std::initializer_list<double> values)
{
    std::string joined;
    for (double value : values)
    {
        if (!joined.empty())
            joined += '\\';
        joined += decimalString(value);
    }
    return joined;
}

} // namespace vsim::dicom::detail
