#pragma once

// Measurements on the slice views: the tool the left button draws with, and a measurement as a view shows it.

#include "vsim/core/ViewMeasurement.h"

#include <string>

namespace vsim::viz {

/// What the left button does in a slice view when not Off: a ruler (press, drag, release), an angle (three clicks,
/// the vertex second) or an elliptical ROI (press at one corner of its box, drag, release). Escape drops the one
/// being drawn.
enum class MeasureTool
{
    Off,
    Ruler,
    Angle,
    Roi,
};

/// A measurement with the text drawn beside it ("Ruler 1: 45.2 mm").
struct ShownMeasurement
{
    ViewMeasurement measurement;
    std::string text;
};

} // namespace vsim::viz
