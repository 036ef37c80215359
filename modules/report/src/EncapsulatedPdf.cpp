#include "vsim/report/EncapsulatedPdf.h"

#include "vsim/core/DicomUid.h"
#include "vsim/core/Error.h"

#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcuid.h>

#include <ctime>
#include <vector>

namespace vsim::report {
namespace {

void put(DcmDataset& data, const DcmTagKey& tag, const std::string& value)
{
    const OFCondition status = data.putAndInsertString(tag, value.c_str());
    if (status.bad())
        throw Error(Pattern{"cannot set a DICOM attribute of the report: %1", {status.text()}});
}

} // namespace

std::string writeEncapsulatedPdf(const QByteArray& pdf, const DocumentIdentity& identity,
                                 const std::filesystem::path& file)
{
    if (pdf.isEmpty())
        throw Error("no PDF to encapsulate");
    DcmFileFormat format;
    DcmDataset& data = *format.getDataset();
    const std::time_t now = std::time(nullptr);
    std::tm utc{};
    gmtime_r(&now, &utc);
    char date[16], time[16];
    std::strftime(date, sizeof date, "%Y%m%d", &utc);
    std::strftime(time, sizeof time, "%H%M%S", &utc);
    const std::string seriesUid = newDicomUid();

    put(data, DCM_SOPClassUID, UID_EncapsulatedPDFStorage);
    put(data, DCM_SOPInstanceUID, newDicomUid());
    put(data, DCM_SpecificCharacterSet, "ISO_IR 192");
    // Patient and general study: the study the report belongs to.
    put(data, DCM_PatientName, identity.patientName);
    put(data, DCM_PatientID, identity.patientId);
    put(data, DCM_PatientBirthDate, identity.patientBirthDate);
    put(data, DCM_PatientSex, identity.patientSex);
    put(data, DCM_StudyInstanceUID, identity.studyInstanceUid.empty() ? newDicomUid() : identity.studyInstanceUid);
    put(data, DCM_StudyDate, identity.studyDate);
    put(data, DCM_StudyTime, identity.studyTime);
    put(data, DCM_ReferringPhysicianName, "");
    put(data, DCM_StudyID, identity.studyId);
    put(data, DCM_AccessionNumber, identity.accessionNumber);
    put(data, DCM_StudyDescription, identity.studyDescription);
    // Encapsulated document series and equipment.
    put(data, DCM_Modality, "DOC");
    put(data, DCM_SeriesInstanceUID, seriesUid);
    put(data, DCM_SeriesNumber, "9001");
    put(data, DCM_SeriesDescription, identity.documentTitle);
    put(data, DCM_Manufacturer, "VascuSim");
    put(data, DCM_InstitutionName, identity.institution);
    put(data, DCM_SoftwareVersions, identity.softwareVersion);
    put(data, DCM_ConversionType, "WSD");
    // Encapsulated document.
    put(data, DCM_InstanceNumber, "1");
    put(data, DCM_ContentDate, date);
    put(data, DCM_ContentTime, time);
    put(data, DCM_AcquisitionDateTime, std::string(date) + time);
    put(data, DCM_BurnedInAnnotation, identity.identifiesPatient ? "YES" : "NO");
    if (!identity.identifiesPatient)
    {
        // PS3.15 E.1: the de-identification stated, so that `pacs store` keeps this out of a patient's study.
        put(data, DCM_PatientIdentityRemoved, "YES");
        put(data, DCM_DeidentificationMethod, "VascuSim report --anonymize: a new study; no patient name, ID, "
                                              "dates or study text");
    }
    put(data, DCM_DocumentTitle, identity.documentTitle);
    put(data, DCM_MIMETypeOfEncapsulatedDocument, "application/pdf");
    if (data.putAndInsertUint32(DCM_EncapsulatedDocumentLength, Uint32(pdf.size())).bad())
        throw Error("cannot set the encapsulated document's length");
    // An even length (PS3.5 8.1.1): a PDF may carry trailing bytes after %%EOF.
    std::vector<Uint8> bytes(pdf.begin(), pdf.end());
    if (bytes.size() % 2)
        bytes.push_back(0);
    const OFCondition document =
        data.putAndInsertUint8Array(DCM_EncapsulatedDocument, bytes.data(), static_cast<unsigned long>(bytes.size()));
    if (document.bad())
        throw Error(Pattern{"cannot encapsulate the PDF: %1", {document.text()}});
    const OFCondition saved = format.saveFile(file.string().c_str(), EXS_LittleEndianExplicit);
    if (saved.bad())
        throw Error(Pattern{"cannot write the DICOM report: %1", {saved.text()}}, {{"file", file.string()}});
    return seriesUid;
}

} // namespace vsim::report
