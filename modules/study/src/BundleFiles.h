#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace vsim::study {

/// CRC-32 (zlib) of a file's bytes; throws vsim::Error when it cannot be read.
std::uint32_t fileChecksum(const std::filesystem::path& file);
/// Flushes a file's data to the device (fsync); throws vsim::Error on failure.
void syncFile(const std::filesystem::path& file);
/// Flushes a folder's entries (so that a rename inside it survives a crash).
void syncDirectory(const std::filesystem::path& folder);
/// Writes `text` to `target` atomically: a temporary file beside it, fsync, rename over the target, folder fsync.
void writeFileAtomically(const std::filesystem::path& target, const std::string& text);
/// Reads a whole text file; throws vsim::Error when it cannot be read.
std::string readTextFile(const std::filesystem::path& file);

} // namespace vsim::study
