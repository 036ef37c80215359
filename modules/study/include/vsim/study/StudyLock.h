#pragma once

// One writer per study: a kernel-held lock on `<bundle>/study.lock` (an open-file-description fcntl lock, which the
// kernel releases when its holder exits or is killed, even by SIGKILL). The holder's process, host, program and time
// are written into the file for the messages only; they never decide who holds the lock.

#include <filesystem>
#include <memory>
#include <string>

namespace vsim::study {

/// Who holds (or last held) a study's lock, as its holder wrote it.
struct LockHolder
{
    long pid = 0;
    std::string host;
    std::string program; ///< e.g. "vascusim-cli segment", "vascusim"
    std::string since;   ///< ISO 8601 UTC

    /// "vascusim-cli segment (process 1234 on host ws-7, since 2026-11-24T10:00:00Z)"
    std::string describe() const;
    /// True when the holder wrote another host's name (a study on a network share).
    bool isOtherHost() const;
};

/// The name programs give themselves in lock files ("vascusim-cli segment"); set once at start-up.
void setLockProgramName(const std::string& name);

class StudyLock
{
public:
    /// Takes the write lock of `bundle` (an existing folder), waiting up to `waitSeconds` for another holder.
    /// Throws vsim::Error naming the holder (context "holder", "host") when it is still held after the wait, or when
    /// the lock file cannot be opened.
    static StudyLock acquire(const std::filesystem::path& bundle, double waitSeconds = 0.0);
    /// Breaks a lock the user confirmed as stale (a holder on another host that died): the old lock file is moved
    /// aside and a new one taken. Never called without the user's confirmation. Throws vsim::Error like acquire().
    static StudyLock breakAndAcquire(const std::filesystem::path& bundle);
    /// The holder written in the lock file, when its lock is held now; empty (pid 0) when nobody holds it.
    static LockHolder currentHolder(const std::filesystem::path& bundle);

    StudyLock(StudyLock&&) noexcept;
    StudyLock& operator=(StudyLock&&) noexcept;
    ~StudyLock(); ///< releases the lock

private:
    struct Handle;
    explicit StudyLock(std::unique_ptr<Handle> handle);
    std::unique_ptr<Handle> m_handle;
};

/// The lock file's name inside a bundle.
inline constexpr const char* kStudyLockFile = "study.lock";

} // namespace vsim::study
