#pragma once

// The median the modules share (import's slice gaps, segmentation's tissue levels, radii, section areas): one
// definition instead of a copy per file.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace vsim {

/// The median of `values`, in their unit: the element at n / 2 in sorted order (the upper of the two middle ones
/// for an even count); `whenEmpty` for none.
template <class T> double median(std::vector<T> values, double whenEmpty = std::nan(""))
{
    if (values.empty())
        return whenEmpty;
    const auto middle = values.begin() + std::ptrdiff_t(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return double(*middle);
}

} // namespace vsim
