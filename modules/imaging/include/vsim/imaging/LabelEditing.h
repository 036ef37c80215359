#pragma once

// Manual correction of a label map: a round brush in the plane of an MPR view (or a sphere) paints or erases voxels, and every
// change is recorded so that it can be undone and redone exactly (GUI brush, thesis ch. 4.1 "interactive
// correction" of the automatic extraction).

#include "vsim/core/ImageVolume.h"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace vsim::imaging {

/// The voxels one brush stroke changed: their linear indices, their values before and the value written.
struct LabelEdit
{
    std::vector<std::size_t> voxels;
    std::vector<std::uint8_t> before;
    std::uint8_t after = 0;

    bool empty() const { return voxels.empty(); }
    /// Adds what `later` changed (same value written); voxels already in this edit keep their first value.
    void merge(const LabelEdit& later);
};

/// Writes `value` into every voxel of `label` whose centre lies within `radiusMm` of `centreMm` in the plane
/// through `centreMm` with normal `planeNormal` (patient frame, mm), at most half a voxel off the plane (one
/// slice of a 2D brush). Returns the voxels that changed.
LabelEdit paintDisc(LabelVolume& label, const Eigen::Vector3d& centreMm, const Eigen::Vector3d& planeNormal,
                    double radiusMm, std::uint8_t value);

/// The 3D sphere brush: writes `value` into every voxel whose centre lies within `radiusMm` of `centreMm`
/// (patient frame, mm), through the slices as well as in them.
LabelEdit paintBall(LabelVolume& label, const Eigen::Vector3d& centreMm, double radiusMm, std::uint8_t value);

/// "Remove island": clears the 26-connected piece of nonzero voxels at `pointMm` (the nonzero voxel nearest to it
/// within `searchMm`, or half a voxel's diagonal if that is more), e.g. a vein or bone fragment the segmentation
/// kept beside the vessel.
/// Returns the voxels that changed (empty when no labelled voxel is that near).
LabelEdit removeIsland(LabelVolume& label, const Eigen::Vector3d& pointMm, double searchMm = 3.0);

/// Writes the edit's values again (redo).
void reapply(LabelVolume& label, const LabelEdit& edit);
/// Restores the values before the edit (undo).
void revert(LabelVolume& label, const LabelEdit& edit);

} // namespace vsim::imaging
