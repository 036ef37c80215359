#pragma once

// Where arterial blood enters the tree (issue 19, item 1). A tree built from imaging is rooted at its largest
// end, which on a patient's label is often the aorta or an iliac artery, not the celiac trunk or the common
// hepatic artery where a chemoembolization model begins. An inlet segment cuts the tree there: blood enters
// through that segment, and the model keeps it and everything beyond it (away from the old root). At the
// celiac trunk the splenic and left gastric arteries then drain through their own outlet resistances beside
// the hepatic tree.

#include "vsim/core/VesselNetwork.h"

#include <string>
#include <vector>

namespace vsim::sim::network
{

/// The tree blood entering through `segment` reaches: that segment and every segment beyond it, seen from the
/// network's root (the largest end when unset). Nodes are renumbered in their old order; `nodeMap`, when
/// given, gets old node -> new node (-1: left out). The segment's end towards the old root is the new root.
/// Outlet conditions and segment fields of what is kept stay. Throws vsim::Error for a segment out of range.
VesselNetwork treeBeyond(const VesselNetwork& network, int segment, std::vector<int>* nodeMap = nullptr);

/// An inlet point farther than this from every centerline is refused.
inline constexpr double kInletReachMm = 10.0;

/// The inlet segment `text` names: a segment number, a point on it "x,y,z" (mm: the nearest segment, within
/// kInletReachMm), or an anatomical name ("common hepatic artery", any case; of several segments of that name, the
/// one nearest the root). Throws vsim::Error listing the names the tree has.
int inletSegment(const VesselNetwork& network, const std::string& text);

} // namespace vsim::sim::network
