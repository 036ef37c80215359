#pragma once

// Labels from elsewhere for `import --as-label` and File > Import Label: a NIfTI / NRRD / MetaImage file, a DICOM
// SEG object, or a DICOM mask series, read onto its own grid (study::maskOnImageGrid then puts it on the CT's).

#include "vsim/core/ImageVolume.h"
#include "vsim/core/Progress.h"

#include <filesystem>
#include <string>
#include <vector>

namespace vsim::app {

/// True for the file names of volume files (.nii, .nii.gz, .nrrd, .nhdr, .mha, .mhd).
bool isVolumeFile(const std::filesystem::path& file);

struct MaskSource
{
    CtVolume mask;                          ///< label values on the source's own grid
    std::string kind;                       ///< "volume file", "DICOM SEG" or "DICOM mask series"
    std::vector<std::string> segmentLabels; ///< a SEG's segment labels by number - 1
    std::vector<std::string> warnings;
};

/// Reads `input`; for a DICOM folder `seriesKey` picks the series (else the one with most slices). Throws
/// vsim::Error with the reason.
MaskSource readMaskSource(const std::filesystem::path& input, const std::string& seriesKey, const Progress& progress = {});

} // namespace vsim::app
