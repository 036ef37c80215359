#include "BundleFiles.h"

#include "vsim/core/Error.h"

#include <fcntl.h>
#include <unistd.h>
#include <zlib.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

namespace vsim::study {
namespace {

Error ioError(const std::string& what, const std::filesystem::path& file)
{
    return Error(what + ": " + std::strerror(errno), {{"file", file.string()}});
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

std::uint32_t fileChecksum(const std::filesystem::path& file)
{
    std::ifstream stream(file, std::ios::binary);
    if (!stream)
        throw ioError("cannot read", file);
    std::vector<char> chunk(1 << 20);
    uLong crc = crc32(0L, Z_NULL, 0);
    while (stream)
    {
        stream.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
        const auto count = stream.gcount();
        if (count > 0)
            crc = crc32(crc, reinterpret_cast<const Bytef*>(chunk.data()), static_cast<uInt>(count));
    }
    return static_cast<std::uint32_t>(crc);
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
        throw Error("cannot replace file: " + error.message(), {{"file", target.string()}});
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
