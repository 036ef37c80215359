#pragma once

// The chemoembolization section's pictures (ReportNetwork.cpp): the tip's perfused territory and coverage over the
// CT, and the DSA-like view at the working C-arm angle. Both are drawn without a display.

#include "vsim/app/StudyReport.h"
#include "vsim/core/VesselNetwork.h"
#include "vsim/report/ReportModel.h"
#include "vsim/study/Study.h"

namespace vsim::app::detail {

/// The drug run's perfused territory (run again from its record: territories need the liver label, not kept in the
/// study) on the axial CT slice through the largest lesion's centre (the liver's centre without one), patient right
/// on the image's left, the CT in an abdominal window (W 400, L 40 HU). A note instead when the run had no liver
/// label or cannot be run again.
report::Block territoryPicture(const study::Study& study, const study::Artifact& run, int pixels);

/// The DSA-like projection (sim::network::dsaProjection) of the solved `network` at the run's working angle; a
/// note when the run has none.
report::Block workingViewPicture(const VesselNetwork& network, const study::Artifact& run, int pixels);

} // namespace vsim::app::detail
