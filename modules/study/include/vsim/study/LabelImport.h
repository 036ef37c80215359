#pragma once

// Labels from elsewhere (reference masks, another program's segmentation) onto a study's image grid, voxel for
// voxel: never resampled by interpolation. A mask on the image's own grid is taken as it is; a mask on a larger or
// smaller grid of the same spacing and axes, offset by a whole number of voxels (a crop of the same scan), is cut
// or padded onto the image's grid, provided none of its labelled voxels falls outside; its axes may be the image's
// in another order or direction (a DICOM SEG's stack runs along the row x column normal, a NIfTI mask may be
// stored flipped): the voxels are reordered, never interpolated. Anything else is refused with both grids in the
// message.

#include "vsim/core/ImageVolume.h"

#include <optional>
#include <string>
#include <vector>

namespace vsim::study {

/// The mask's nonzero voxels on `image`'s grid (0 elsewhere): as `value` when given, else with their own values (a
/// multi-label mask keeps its labels; they must be 1..255), a mask of one value as label 1 (with a warning).
/// `warnings` gains a line when the mask was cut or padded.
/// Throws vsim::Error naming both grids when they do not match as the header says, when the mask has no labelled
/// voxel, and for own values outside 1..255.
LabelVolume maskOnImageGrid(const CtVolume& mask, const VolumeGeometry& image, std::optional<std::uint8_t> value,
                            std::vector<std::string>& warnings);

} // namespace vsim::study
