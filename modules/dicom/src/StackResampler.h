#pragma once

#include "vsim/core/ImageVolume.h"
#include "vsim/core/Progress.h"
#include "vsim/dicom/SliceStack.h"

#include <vector>

namespace vsim::dicom {

/// HU given to grid voxels that no source slice covers.
inline constexpr std::int16_t kPaddingHu = -1024;

/// Fills `grid` from parallel source slices (pixels[k] lies on plane stack.positions[k]; `offsets` are the
/// planes' distances along the normal, ascending): each voxel is interpolated bilinearly in the two planes that
/// bracket it and linearly between them. Handles tilted, unevenly spaced and gapped stacks alike.
CtVolume resampleStack(const CtVolume& pixels, const SliceStack& stack, const std::vector<double>& offsets,
                       const VolumeGeometry& grid, const Progress& progress = {});

} // namespace vsim::dicom
