#pragma once

// A line plot drawn with a QPainter into a rectangle (device units): axes with rounded ticks, the series as
// polylines, dashed reference lines with their labels, a legend. Vectors on a PDF device.

#include "vsim/report/ReportModel.h"

#include <QPainter>
#include <QRectF>

namespace vsim::report::detail {

void paintPlot(QPainter& painter, const QRectF& area, const Plot& plot);

} // namespace vsim::report::detail
