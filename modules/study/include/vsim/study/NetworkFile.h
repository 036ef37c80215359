#pragma once

// The vessel-network file (JSON), for networks users write by hand (what imaging cannot see) and for the study's
// network artifacts. Lengths in mm, pressures in mmHg, resistances in mmHg min/ml (1 mmHg min/ml = 8.0e9 Pa s/m^3):
//
//   {"format": "vascusim-network", "version": 1, "root": 0,
//    "nodes":    [{"position_mm": [x, y, z], "name": "A"}, ...],            (index = node id; name optional)
//    "segments": [{"from": 0, "to": 1, "start_radius_mm": 3.0, "end_radius_mm": 2.7, "length_mm": 38.0,
//                  "resistance_mmhg_min_per_ml": 0.5,                        (optional: replaces the conical law)
//                  "path_mm": [[x, y, z], ...]}, ...],                       (optional, for display)
//    "outlets":  [{"node": 4, "pressure_mmhg": 10.0},                       (a pressure at the node), or
//                 {"node": 5, "resistance_mmhg_min_per_ml": 12.0, "pressure_mmhg": 10.0}, ...],
//    "segment_fields": {"flow_ml_min": [...], ...}}                          (results, one value per segment)

#include "vsim/core/VesselNetwork.h"

#include <filesystem>
#include <string>

namespace vsim::study {

/// Pa s / m^3 per mmHg min / ml.
inline constexpr double kPaSPerM3PerMmHgMinPerMl = 133.322387415 * 60.0 / 1e-6;

std::string networkToJsonText(const VesselNetwork& network);
/// Parses and validates; throws vsim::Error naming what is missing or wrong (segment, node, key).
VesselNetwork networkFromJsonText(const std::string& text);

/// Reads a network file; throws vsim::Error for an unreadable file or a bad network.
VesselNetwork readNetworkFile(const std::filesystem::path& file);
/// Writes a network file; throws vsim::Error when it cannot be written.
void writeNetworkFile(const VesselNetwork& network, const std::filesystem::path& file);

} // namespace vsim::study
