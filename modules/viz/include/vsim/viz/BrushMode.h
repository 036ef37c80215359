#pragma once

namespace vsim::viz {

/// What the left button does on a slice view's label overlay: move the cursor (Off), paint 1 or erase to 0.
enum class BrushMode { Off, Paint, Erase };

} // namespace vsim::viz
