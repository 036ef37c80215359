// C-STORE of VascuSim's results to a PACS (PS3.4 B; issue 22): the report's Encapsulated PDF and the labels' SEG,
// into the patient's study they name, or a de-identified object as a new study.

#include "vsim/dicom/PacsClient.h"

#include "vsim/core/DicomUid.h"
#include "vsim/core/Error.h"

#include "DatasetText.h"
#include "PacsAssociation.h"

#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcxfer.h>

#include <memory>
#include <set>

namespace vsim::dicom {
namespace {

struct Outgoing
{
    std::unique_ptr<DcmFileFormat> format;
    StoredObject object;
    std::string transferSyntax;
};

Outgoing readOutgoing(const std::filesystem::path& file, AnonymizedObjects anonymized)
{
    Outgoing outgoing{std::make_unique<DcmFileFormat>(), {}, {}};
    const OFCondition loaded = outgoing.format->loadFile(file.string().c_str());
    if (loaded.bad())
        throw Error(Pattern{"not a DICOM file: %1 (%2)", {file.string(), loaded.text()}});
    DcmDataset& data = *outgoing.format->getDataset();
    StoredObject& object = outgoing.object;
    object.file = file;
    object.sopClassUid = detail::datasetText(data, DCM_SOPClassUID);
    object.sopInstanceUid = detail::datasetText(data, DCM_SOPInstanceUID);
    object.studyInstanceUid = detail::datasetText(data, DCM_StudyInstanceUID);
    object.seriesInstanceUid = detail::datasetText(data, DCM_SeriesInstanceUID);
    object.modality = detail::datasetText(data, DCM_Modality);
    if (object.sopClassUid.empty() || object.sopInstanceUid.empty() || object.studyInstanceUid.empty())
        throw Error(Pattern{"a DICOM object to store needs its SOP class, instance and study UIDs: %1",
                            {file.string()}});
    if (detail::datasetText(data, DCM_PatientIdentityRemoved) == "YES")
    {
        if (anonymized == AnonymizedObjects::Refuse)
            throw Error(Pattern{"%1 is de-identified (Patient Identity Removed YES, e.g. a report made with "
                                "--anonymize): it is not stored into a patient's study. Nothing was sent; to store it "
                                "as a new anonymized study, ask for that (pacs store --anonymized new-study)",
                                {file.string()}});
        // A new study of its own: whatever UIDs it carries (another tool's anonymizer may have kept the patient's).
        object.studyInstanceUid = newDicomUid();
        object.seriesInstanceUid = newDicomUid();
        object.sopInstanceUid = newDicomUid();
        data.putAndInsertString(DCM_StudyInstanceUID, object.studyInstanceUid.c_str());
        data.putAndInsertString(DCM_SeriesInstanceUID, object.seriesInstanceUid.c_str());
        data.putAndInsertString(DCM_SOPInstanceUID, object.sopInstanceUid.c_str());
        outgoing.format->getMetaInfo()->putAndInsertString(DCM_MediaStorageSOPInstanceUID, object.sopInstanceUid.c_str());
        object.asNewStudy = true;
    }
    outgoing.transferSyntax = DcmXfer(data.getOriginalXfer()).getXferID();
    return outgoing;
}

} // namespace

std::vector<StoredObject> storeFiles(const PacsNode& node, const std::vector<std::filesystem::path>& files,
                                     AnonymizedObjects anonymized, const Progress& progress)
{
    if (files.empty())
        throw Error("nothing to store: name one or more DICOM files");
    std::vector<Outgoing> outgoing;
    for (const std::filesystem::path& file : files)
        outgoing.push_back(readOutgoing(file, anonymized));

    // One presentation context per SOP class and transfer syntax, the object's own syntax proposed first.
    std::vector<detail::Proposed> contexts;
    std::set<std::pair<std::string, std::string>> proposed;
    for (const Outgoing& item : outgoing)
        if (proposed.insert({item.object.sopClassUid, item.transferSyntax}).second)
            contexts.push_back({item.object.sopClassUid, ASC_SC_ROLE_DEFAULT, item.transferSyntax});
    detail::Association association(node, contexts);
    std::vector<StoredObject> stored;
    for (std::size_t i = 0; i < outgoing.size(); ++i)
    {
        Outgoing& item = outgoing[i];
        progress.report(double(i) / double(outgoing.size()),
                        "storing " + std::to_string(i + 1) + " of " + std::to_string(outgoing.size()));
        const T_ASC_PresentationContextID id = association.context(
            item.object.sopClassUid, "storage of " + item.object.file.filename().string() + " (class " +
                                         item.object.sopClassUid + ")");
        Uint16 status = 0;
        const OFCondition sent =
            association.scu().sendSTORERequest(id, "", item.format->getDataset(), status);
        const std::string done = stored.empty() ? "nothing was stored"
                                                : std::to_string(stored.size()) + " of " +
                                                      std::to_string(outgoing.size()) + " objects were stored before it";
        if (sent.bad())
            throw Error(Pattern{"the store of %1 broke off (%2): %3; %4",
                                {item.object.file.string(), describe(node), sent.text(), done}});
        // 0000 success; Bxxx warnings (coercion, elements discarded) still store the object (PS3.4 B.2.3).
        if (status != STATUS_Success && (status & 0xF000) != 0xB000)
            throw Error(Pattern{"the PACS %1 refused %2 with status %3; %4",
                                {describe(node), item.object.file.string(), detail::statusText(status), done}});
        stored.push_back(item.object);
    }
    progress.report(1.0, "stored " + std::to_string(stored.size()) + " objects");
    return stored;
}

} // namespace vsim::dicom
