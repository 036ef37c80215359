#pragma once

// Vessel radii from the CT's partial-volume contrast rather than from a thresholded label. A scanner blurs a thin
// vessel, so the contour of any threshold shrinks with the vessel's size (a 1.5 mm artery at 0.7 mm voxels loses
// 10-20 % of its radius), and single cross-sections scatter by as much. The contrast over a tube around the
// centerline, (HU - tissue) / (blood - tissue) summed times the voxel volume, is the lumen volume when the blur is
// a convolution; a model of the blurred tube fitted to the voxels (a disc convolved with a Gaussian, whose integral
// is the disc's area for any blur; the analytic phantoms' edge profile Phi((r - d) / sigma) is not such a
// convolution: it adds about pi sigma^2 to the area) refines it. The drug network needs this: a flow
// split goes with the radius cubed or to the fourth power.

#include "vsim/core/ImageVolume.h"
#include "vsim/core/Progress.h"
#include "vsim/core/SkeletonGraph.h"

#include <vector>

namespace vsim::imaging {

struct PartialVolumeRadius
{
    bool measured = false;        ///< false: too short between its junction clearances (use another estimate)
    double startRadiusMm = 0.0;   ///< at the edge's `from` end, extrapolated from its two halves
    double endRadiusMm = 0.0;     ///< at its `to` end
    double meanRadiusMm = 0.0;    ///< equivalent radius of the mean lumen area
    double usedLengthMm = 0.0;    ///< length between the clearances that was integrated
};

/// One radius estimate per centerline edge. Each voxel within a tube around the centerlines belongs to the nearest
/// one; lengths within a clearance of a junction (3 radii of the widest vessel there + 1 mm) or a free end (1
/// radius + 1 mm) are left out; tissue is the dominant level of each tube's surrounding 1.5 mm shell within 2 mm
/// along it (a touching vein drops out), blood the median of the tube's own core where it is 1.8 mm wide or more,
/// else that of the nearest such tube along the tree (the contrast falls along the arteries). Two passes of the volume integral (the second with the tube
/// tightened to the lumen found), then blurred-tube fits to the voxels (the blur's sigma fitted on the widest
/// vessel): each tube's middle alone, then each nearly straight tube from its forks with its neighbours' fitted
/// tubes filling the merged lumens there. Throws vsim::Error for empty centerlines.
std::vector<PartialVolumeRadius> partialVolumeRadii(const CtVolume& ct, const SkeletonGraph& centerlines,
                                                    const Progress& progress = {});

} // namespace vsim::imaging
