#pragma once

// The drawing order of a slice view's layers, as z in the slice's own coordinates (mm; the camera looks down
// -z from z = 1000, so a larger z is drawn in front; the CT slice is at 0). One place for all of them, so that a
// new layer finds its slot.

namespace vsim::viz::slice_depth {

constexpr double kLabels = 0.5;       ///< the label overlay
constexpr double kField = 0.75;       ///< a field's or the network's cut
constexpr double kMarkers = 1.0;      ///< marker rings and their names
constexpr double kMeasurements = 1.2; ///< rulers and their figures
constexpr double kOverlay = 1.5;      ///< crosshair lines and the scale bar

} // namespace vsim::viz::slice_depth
