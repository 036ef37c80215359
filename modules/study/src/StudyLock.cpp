#include "vsim/study/StudyLock.h"

#include "vsim/core/Error.h"
#include "vsim/study/Study.h"

#include <cerrno>
#include <chrono>
#include <cstring>
#include <csignal>
#include <fcntl.h>
#include <sstream>
#include <thread>
#include <unistd.h>

namespace vsim::study {
namespace fs = std::filesystem;

namespace {

std::string g_programName = "vascusim";

std::string hostName()
{
    char name[256] = {};
    if (gethostname(name, sizeof name - 1) != 0)
        return "unknown";
    return name;
}

/// Tries to take (F_WRLCK) or to test (F_GETLK) the whole-file OFD lock; returns 0, or errno.
int tryLock(int descriptor)
{
    struct flock lock{};
    lock.l_type = F_WRLCK;
    lock.l_whence = SEEK_SET;
    return fcntl(descriptor, F_OFD_SETLK, &lock) == 0 ? 0 : errno;
}

bool isLockedByOther(int descriptor)
{
    struct flock lock{};
    lock.l_type = F_WRLCK;
    lock.l_whence = SEEK_SET;
    return fcntl(descriptor, F_OFD_GETLK, &lock) == 0 && lock.l_type != F_UNLCK;
}

LockHolder parseHolder(const std::string& text)
{
    LockHolder holder;
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line))
    {
        const auto equals = line.find('=');
        if (equals == std::string::npos)
            continue;
        const std::string key = line.substr(0, equals), value = line.substr(equals + 1);
        // The first of each key counts: a holder that is rewriting a longer description leaves old lines behind.
        if (key == "pid" && holder.pid == 0)
            holder.pid = std::atol(value.c_str());
        else if (key == "host" && holder.host.empty())
            holder.host = value;
        else if (key == "program" && holder.program.empty())
            holder.program = value;
        else if (key == "since" && holder.since.empty())
            holder.since = value;
    }
    return holder;
}

std::string readAll(int descriptor)
{
    std::string text;
    char buffer[512];
    ssize_t got = 0;
    off_t offset = 0;
    while ((got = pread(descriptor, buffer, sizeof buffer, offset)) > 0)
    {
        text.append(buffer, std::size_t(got));
        offset += got;
    }
    return text;
}

/// The holder of a lock that another open file description holds now. A new holder writes its description just
/// after taking the lock: until then the file names the previous (dead) holder, so read again for a moment.
LockHolder readLiveHolder(int descriptor)
{
    LockHolder holder;
    for (int attempt = 0; attempt < 40; ++attempt)
    {
        holder = parseHolder(readAll(descriptor));
        const bool alive = holder.pid > 0 && (kill(pid_t(holder.pid), 0) == 0 || errno == EPERM);
        if (alive || holder.isOtherHost())
            break;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return holder;
}

int openLockFile(const fs::path& bundle)
{
    const fs::path file = bundle / kStudyLockFile;
    const int descriptor = open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (descriptor < 0)
        throw Error(Pattern{"cannot open the study's lock file: %1", {std::strerror(errno)}},
                    {{"file", file.string()}});
    return descriptor;
}

} // namespace

std::string LockHolder::describe() const
{
    std::ostringstream text;
    text << (program.empty() ? std::string("another program") : program) << " (process " << pid << " on host "
         << (host.empty() ? std::string("unknown") : host) << (since.empty() ? "" : ", since " + since) << ")";
    return text.str();
}

bool LockHolder::isOtherHost() const { return !host.empty() && host != hostName(); }

void setLockProgramName(const std::string& name) { g_programName = name; }

struct StudyLock::Handle
{
    int descriptor = -1;
    ~Handle()
    {
        if (descriptor >= 0)
            close(descriptor); // closing the open file description releases its lock
    }
};

StudyLock::StudyLock(std::unique_ptr<Handle> handle) : m_handle(std::move(handle)) {}
StudyLock::StudyLock(StudyLock&&) noexcept = default;
StudyLock& StudyLock::operator=(StudyLock&&) noexcept = default;
StudyLock::~StudyLock() = default;

StudyLock StudyLock::acquire(const fs::path& bundle, double waitSeconds)
{
    auto handle = std::make_unique<Handle>();
    handle->descriptor = openLockFile(bundle);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(waitSeconds);
    for (;;)
    {
        const int failure = tryLock(handle->descriptor);
        if (failure == 0)
            break;
        if (failure != EAGAIN && failure != EACCES)
            throw Error(Pattern{"cannot lock the study: %1", {std::strerror(failure)}}, {{"folder", bundle.string()}});
        if (std::chrono::steady_clock::now() >= deadline)
        {
            const LockHolder holder = readLiveHolder(handle->descriptor);
            throw Error(Pattern{"the study is being written by %1; wait for it (--wait SECONDS) or open the study "
                                "read-only",
                                {holder.describe()}},
                        {{"folder", bundle.string()}, {"holder", holder.describe()}, {"host", holder.host}});
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    std::ostringstream owner;
    owner << "pid=" << getpid() << "\nhost=" << hostName() << "\nprogram=" << g_programName
          << "\nsince=" << utcTimestamp() << "\n";
    const std::string text = owner.str();
    // Informational only: a failed write leaves the lock held and an older description. Written over the old one,
    // then cut to length, so that a reader never finds the file empty.
    if (pwrite(handle->descriptor, text.data(), text.size(), 0) == ssize_t(text.size()))
        (void)!ftruncate(handle->descriptor, off_t(text.size()));
    return StudyLock(std::move(handle));
}

StudyLock StudyLock::breakAndAcquire(const fs::path& bundle)
{
    const fs::path file = bundle / kStudyLockFile;
    const fs::path aside = bundle / (std::string(kStudyLockFile) + ".broken-" + std::to_string(getpid()));
    std::error_code error;
    fs::rename(file, aside, error);
    if (error)
        throw Error(Pattern{"cannot move the stale lock aside: %1", {error.message()}}, {{"file", file.string()}});
    return acquire(bundle, 0.0);
}

LockHolder StudyLock::currentHolder(const fs::path& bundle)
{
    const int descriptor = open((bundle / kStudyLockFile).c_str(), O_RDONLY | O_CLOEXEC);
    if (descriptor < 0)
        return {};
    LockHolder holder;
    if (isLockedByOther(descriptor))
        holder = readLiveHolder(descriptor);
    close(descriptor);
    return holder;
}

} // namespace vsim::study
