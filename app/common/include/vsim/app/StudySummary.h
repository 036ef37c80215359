#pragma once

#include <string>

namespace vsim::study {
class Study;
}

namespace vsim::app {

/// The study as JSON for `vascusim-cli info`: name, bundle, metadata, open warnings, and every artifact with
/// its kind, file, provenance, warnings, damage flag and, for images and labels, dims / spacing (mm) / origin (mm).
std::string studySummaryJson(const study::Study& study);

} // namespace vsim::app
