#pragma once

// The part of a vessel tree the injected drug reaches: everything downstream of the catheter tip. The segment from
// the tip towards the tree's root and all beyond it are left out (the thesis's "the tree upstream of the tip is
// excluded"), as are parts not connected to the tip.

#include "vsim/core/VesselNetwork.h"

#include <vector>

namespace vsim::sim::network {

struct TipOrientation
{
    int tip = -1;
    std::vector<int> order;           ///< nodes downstream of the tip, the tip first, parents before children
    std::vector<int> parentSegment;   ///< per node: its segment towards the tip (-1 for the tip and left-out nodes)
    std::vector<int> upstreamNode;    ///< per segment: its end nearer the tip (-1 when left out)
    std::vector<int> outlets;         ///< end nodes downstream of the tip (not the tip itself)
    bool active(int segment) const { return upstreamNode[std::size_t(segment)] >= 0; }
};

/// Orients `network` (a validated tree) from `tip`. Throws vsim::Error when the tip does not exist, is not
/// connected to the root, or has nothing downstream (an end of the tree other than the root).
TipOrientation orientFromTip(const VesselNetwork& network, int tip);

/// The end node of the largest radius: the inlet of a tree built from imaging. -1 for an empty network.
int largestEnd(const VesselNetwork& network);

} // namespace vsim::sim::network
