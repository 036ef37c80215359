#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <string>

namespace vsim {

/// Shared cancel flag: the GUI's Cancel button (or SIGINT in the CLI) sets it, the worker polls it.
class CancellationToken
{
public:
    CancellationToken() : m_flag(std::make_shared<std::atomic<bool>>(false)) {}
    void cancel() { m_flag->store(true); }
    bool isCancelled() const { return m_flag->load(); }

private:
    std::shared_ptr<std::atomic<bool>> m_flag;
};

/// Progress of one task: reports a fraction in [0, 1] with a stage name, and is the one place long loops
/// check for cancellation. Sub-ranges let a pipeline hand a slice of its bar to each step.
class Progress
{
public:
    using Sink = std::function<void(double fraction, const std::string& stage)>;

    Progress() = default;
    Progress(Sink sink, CancellationToken token) : m_sink(std::move(sink)), m_token(std::move(token)) {}

    /// Reports `fraction` (0..1) of this task's range; throws vsim::Cancelled when cancellation was requested.
    void report(double fraction, const std::string& stage = {}) const;
    /// Throws vsim::Cancelled when cancellation was requested.
    void throwIfCancelled() const;
    /// Returns a Progress that maps its 0..1 onto [begin, end] of this one.
    Progress subRange(double begin, double end) const;
    const CancellationToken& token() const { return m_token; }

private:
    Sink m_sink;
    CancellationToken m_token;
    double m_begin = 0.0;
    double m_end = 1.0;
};

} // namespace vsim
