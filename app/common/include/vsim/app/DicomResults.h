#pragma once

// A study's results as DICOM objects for a PACS (issue 22), shared by `vascusim-cli export-label` and the
// workstation's File > Send to PACS: a label as a Segmentation (SEG) in the CT's study and frame of reference, and a
// report kept in the study as an Encapsulated PDF, de-identified when the report was made so.

#include "vsim/study/Study.h"

#include <filesystem>
#include <string>

namespace vsim::app {

/// Writes the label `labelId` as a DICOM SEG at `out`: the study's patient and Study Instance UID, the newest CT's
/// frame of reference, each frame naming the CT image it was derived from where the import recorded them; segments
/// 1 vessel lumen, 4 thrombus, 5 aortic wall. Throws vsim::Error when it cannot be written.
void writeLabelSegmentation(const study::Study& study, const std::string& labelId, const std::filesystem::path& out);

/// Writes the report artifact `reportId` (its PDF as kept in the study) as a DICOM Encapsulated PDF at `out`, in
/// the patient's study, or as a new de-identified study when the report was made anonymized. Returns whether it was.
bool writeReportEncapsulatedPdf(const study::Study& study, const std::string& reportId, const std::filesystem::path& out);

} // namespace vsim::app
