#pragma once

// A report as a DICOM Encapsulated PDF instance (PS3.3 A.45.1), so that it can go to PACS with the patient's study:
// the study's Study Instance UID, a new series (modality DOC) and instance. DCMTK.

#include <QByteArray>

#include <filesystem>
#include <string>

namespace vsim::report {

/// Who and what the document belongs to (DICOM text values; empty ones are written empty, as type 2 allows).
struct DocumentIdentity
{
    std::string studyInstanceUid;  ///< the study's; a new one is made when empty (a study not from DICOM)
    std::string patientName, patientId, patientBirthDate, patientSex;
    std::string studyDate, studyTime, studyId, accessionNumber, studyDescription;
    std::string institution;
    std::string documentTitle = "VascuSim planning report";
    std::string softwareVersion;   ///< "0.2.0"
    /// Burned In Annotation: whether the PDF names the patient. When false, Patient Identity Removed is YES.
    bool identifiesPatient = true;
};

/// Writes `pdf` as an Encapsulated PDF Storage instance (explicit VR little endian, with file meta information).
/// Returns the new Series Instance UID. Throws vsim::Error when the file cannot be written.
std::string writeEncapsulatedPdf(const QByteArray& pdf, const DocumentIdentity& identity,
                                 const std::filesystem::path& file);

} // namespace vsim::report
