#pragma once

#include "vsim/core/Hounsfield.h"
#include "vsim/core/ImageVolume.h"
#include "vsim/core/Progress.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace vsim::study {

class Study;

/// A CT volume read from a single file, with what the conversion had to change.
struct ImportedVolume
{
    CtVolume image;                    ///< HU, int16, LPS patient frame
    std::string format;                ///< "NIfTI", "NRRD", "MetaImage"
    std::vector<std::string> warnings; ///< rounded or clamped values
};

/// Reads a 3D scalar volume from NIfTI (.nii, .nii.gz), NRRD (.nrrd, .nhdr) or MetaImage (.mha, .mhd), in the
/// LPS frame (ITK converts NIfTI's RAS). Non-integer values are rounded and values outside int16 are clamped,
/// each reported as a warning with its count. Throws vsim::Error for an unreadable or unsupported file, an image
/// that is not 3D or has more than one component, and vsim::Cancelled when cancelled.
ImportedVolume readVolumeFile(const std::filesystem::path& file, const Progress& progress = {});

/// Reads `file` and adds it to the study as an image artifact with provenance; returns the artifact id. The values
/// must read as CT in HU, after `rescale` when given (acceptAsHounsfield); otherwise vsim::Error names --rescale
/// and nothing is added.
std::string importVolumeFile(Study& study, const std::filesystem::path& file,
                             const std::optional<HounsfieldRescale>& rescale = std::nullopt, const Progress& progress = {});
/// The same for a volume read already (readVolumeFile); `file` names the source in the provenance.
std::string addImportedVolume(Study& study, ImportedVolume imported, const std::filesystem::path& file,
                              const std::optional<HounsfieldRescale>& rescale = std::nullopt);

} // namespace vsim::study
