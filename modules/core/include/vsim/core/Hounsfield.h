#pragma once

// Is a volume CT in Hounsfield units? Every step after the import reads HU (segmentation thresholds, the phantoms'
// contrast, the partial-volume radii), so the import decides, once, with a test that a crop without air passes:
// CT in HU always holds voxels below 0 HU (air, fat, fluid, or the noise around soft tissue at 20-60 HU) and its
// median is that of the body or air (-1000..500 HU). Stored values without their rescale (0..4095, soft tissue near
// 1,050) and MR (no value below 0) fail it; the user then gives the rescale (--rescale SLOPE,INTERCEPT).

#include "vsim/core/ImageVolume.h"

#include <optional>
#include <string>
#include <vector>

namespace vsim {

/// value_HU = slope * stored + intercept (DICOM Rescale Slope / Intercept).
struct HounsfieldRescale
{
    double slope = 1.0;
    double intercept = 0.0;
};

/// Why `ct` does not read as CT in HU ("" when it does): no voxel below 0, or a median above 500 (HU).
std::string whyNotHounsfield(const CtVolume& ct);

/// Makes an imported volume CT in HU or refuses it: applies `rescale` when given (rounded, clamped to int16; a
/// warning names it and the clamped voxels), then throws vsim::Error naming --rescale when the values still do not
/// read as HU. `rescale` not given: nothing changes unless the check fails.
void acceptAsHounsfield(CtVolume& ct, const std::optional<HounsfieldRescale>& rescale, std::vector<std::string>& warnings);

} // namespace vsim
