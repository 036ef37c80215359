#pragma once

#include "vsim/core/Hounsfield.h"
#include "vsim/core/Progress.h"
#include "vsim/dicom/DicomImport.h"
#include "vsim/dicom/DicomScan.h"

#include <filesystem>
#include <optional>
#include <string>

namespace vsim::study {
class Study;
}

namespace vsim::app {

/// Adds a decoded series to the study as an image with provenance (the series key, the source), the DICOM
/// attributes and the import warnings; fills the study's patient and study metadata when empty. Returns the id.
/// Throws vsim::Error when the series belongs to another patient than the study's, or when its values do not read
/// as CT in HU after `rescale` (when given; the message names --rescale); nothing is added then.
std::string addDicomVolumeToStudy(study::Study& study, dicom::DicomVolume volume, const std::filesystem::path& source,
                                  const std::optional<HounsfieldRescale>& rescale = std::nullopt);

/// Decodes a scanned series and adds it to the study as an image with provenance (the series key, the source),
/// the DICOM attributes and the import warnings; fills the study's patient and study metadata when empty.
/// Throws vsim::Error when the series belongs to another patient than the study's, cannot be imported, or does not
/// read as CT in HU after `rescale` (addDicomVolumeToStudy).
std::string importDicomSeriesIntoStudy(study::Study& study, const dicom::DicomSeries& series,
                                       const std::filesystem::path& source,
                                       const dicom::DicomImportOptions& options = {}, const Progress& progress = {},
                                       const std::optional<HounsfieldRescale>& rescale = std::nullopt);

/// Picks the series to import: `keyOrUid` when given, else the CT series with most slices. Throws vsim::Error
/// with a one-line reason when there is none (e.g. a folder without DICOM images) or the key is unknown.
const dicom::DicomSeries& chooseSeries(const dicom::DicomScanResult& scan, const std::string& keyOrUid);

/// The scan as JSON for `vascusim-cli import --list`: files counted by outcome, warnings, and every series with
/// patient, study, description, modality, slice count, image size, pixel spacing, geometry plan and warnings.
std::string dicomScanJson(const dicom::DicomScanResult& scan);

} // namespace vsim::app
