#pragma once

// A DSA-like view (sim::network::dsaProjection) as a grey picture, for the report and the workstation's dock.

#include "vsim/sim/network/WorkingAngle.h"

#include <QImage>

namespace vsim::app {

/// One grey pixel per projection pixel (transmission 0 black .. 1 white), the head up.
QImage projectionPicture(const sim::network::ProjectionImage& image);

} // namespace vsim::app
