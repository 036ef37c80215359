#include "BundleFiles.h"

#include "vsim/core/Error.h"

#include <fcntl.h>
#include <unistd.h>
#include <zlib.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <future>
#include <sstream>
#include <vector>

namespace vsim::study {
namespace {

Error ioError(const std::string& what, const std::filesystem::path& file)
{
    return Error(Pattern{"%1: %2", {what, std::strerror(errno)}}, {{"file", file.string()}});
}

void syncPath(const std::filesystem::path& path, int flags)
{
    const int descriptor = ::open(path.c_str(), flags);
    if (descriptor < 0)
        throw ioError("cannot open for sync", path);
    const int status = ::fsync(descriptor);
    ::close(descriptor);
    if (status != 0)
        throw ioError("fsync failed", path);
}

} // namespace

namespace {

/// CRC-32 of `length` bytes of a file from `offset`.
uLong rangeChecksum(const std::filesystem::path& file, std::uint64_t offset, std::uint64_t length)
{
    std::ifstream stream(file, std::ios::binary);
    if (!stream || !stream.seekg(static_cast<std::streamoff>(offset)))
        throw ioError("cannot read", file);
    std::vector<char> chunk(1 << 20);
    uLong crc = crc32(0L, Z_NULL, 0);
    while (length > 0)
    {
        const auto wanted = static_cast<std::streamsize>(std::min<std::uint64_t>(chunk.size(), length));
        if (!stream.read(chunk.data(), wanted))
            throw ioError("file changed while it was read", file);
        crc = crc32(crc, reinterpret_cast<const Bytef*>(chunk.data()), static_cast<uInt>(wanted));
        length -= static_cast<std::uint64_t>(wanted);
    }
    return crc;
}

} // namespace

std::uint32_t fileChecksum(const std::filesystem::path& file)
{
    std::error_code error;
    const std::uint64_t size = std::filesystem::file_size(file, error);
    if (error)
        throw ioError("cannot read", file);
    // Two halves on two threads, joined with crc32_combine: volumes are hundreds of MB.
    constexpr std::uint64_t kSplitAbove = 16u << 20;
    if (size < kSplitAbove)
        return static_cast<std::uint32_t>(rangeChecksum(file, 0, size));
    const std::uint64_t half = size / 2;
    auto second = std::async(std::launch::async, [&] { return rangeChecksum(file, half, size - half); });
    const uLong first = rangeChecksum(file, 0, half);
    return static_cast<std::uint32_t>(crc32_combine(first, second.get(), static_cast<z_off_t>(size - half)));
}

void syncFile(const std::filesystem::path& file)
{
    syncPath(file, O_RDONLY);
}

void syncDirectory(const std::filesystem::path& folder)
{
    syncPath(folder, O_RDONLY | O_DIRECTORY);
}

void writeFileAtomically(const std::filesystem::path& target, const std::string& text)
{
    std::filesystem::path temporary = target;
    temporary += ".tmp";
    {
        std::ofstream stream(temporary, std::ios::binary | std::ios::trunc);
        stream.write(text.data(), static_cast<std::streamsize>(text.size()));
        stream.flush();
        if (!stream)
            throw ioError("cannot write", temporary);
    }
    syncFile(temporary);
    std::error_code error;
    std::filesystem::rename(temporary, target, error);
    if (error)
        throw Error(Pattern{"cannot replace file: %1", {error.message()}}, {{"file", target.string()}});
    syncDirectory(target.parent_path());
}

std::string readTextFile(const std::filesystem::path& file)
{
    std::ifstream stream(file, std::ios::binary);
    if (!stream)
        throw ioError("cannot read", file);
    std::ostringstream text;
    text << stream.rdbuf();
    return text.str();
}

} // namespace vsim::study
