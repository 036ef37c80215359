#pragma once

#include <string>

namespace vsim {

/// The current time as ISO 8601 UTC, e.g. "2026-11-22T09:30:00Z": provenance of artifacts and runs, lock files.
std::string utcTimestamp();

} // namespace vsim
