#include "vsim/core/Progress.h"

#include "vsim/core/Error.h"

#include <algorithm>

namespace vsim {

void Progress::throwIfCancelled() const
{
    if (m_token.isCancelled())
        throw Cancelled();
}

void Progress::report(double fraction, const std::string& stage) const
{
    throwIfCancelled();
    if (m_sink)
        m_sink(m_begin + (m_end - m_begin) * std::clamp(fraction, 0.0, 1.0), stage);
}

Progress Progress::subRange(double begin, double end) const
{
    Progress child = *this;
    child.m_begin = m_begin + (m_end - m_begin) * begin;
    child.m_end = m_begin + (m_end - m_begin) * end;
    return child;
}

} // namespace vsim
