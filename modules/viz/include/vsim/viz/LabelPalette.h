#pragma once

// The colours the MPR views draw label values 0-5 in, shared with the report's pictures so that both read alike.

#include <array>

namespace vsim::viz {

using LabelColour = std::array<double, 4>; ///< red, green, blue, opacity (0..1)

/// Tissue labels: 1 lumen red, 2-3 orange, 4 thrombus yellow, 5 wall blue; 0 clear.
inline constexpr std::array<LabelColour, 6> kTissuePalette{LabelColour{0, 0, 0, 0},          LabelColour{1.0, 0.2, 0.15, 0.45},
                                                           LabelColour{1.0, 0.6, 0.1, 0.45}, LabelColour{1.0, 0.6, 0.1, 0.45},
                                                           LabelColour{1.0, 0.9, 0.2, 0.45}, LabelColour{0.3, 0.5, 1.0, 0.45}};

/// A chemoembolization territory (sim::network::TerritoryLabelValue): 1 liver not perfused clear, 2 perfused liver
/// green, 3 perfused tumour blue, 4 tumour not perfused red, 5 margin not perfused yellow.
inline constexpr std::array<LabelColour, 6> kTerritoryPalette{LabelColour{0, 0, 0, 0},          LabelColour{0, 0, 0, 0},
                                                              LabelColour{0.2, 0.9, 0.3, 0.35}, LabelColour{0.3, 0.5, 1.0, 0.55},
                                                              LabelColour{1.0, 0.15, 0.1, 0.6}, LabelColour{1.0, 0.9, 0.2, 0.5}};

} // namespace vsim::viz
