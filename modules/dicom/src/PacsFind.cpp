// C-FIND at the three levels a reading workstation browses (PS3.4 C.6; issue 22): patients (Patient Root
// information model), the studies, and the series of a study (Study Root). One query runner for all three: the
// request names its level and the keys to return, the answers come back as datasets; Cancel is a C-CANCEL at the
// next answer.

#include "vsim/dicom/PacsClient.h"

#include "vsim/core/Error.h"

#include "DatasetText.h"
#include "PacsAssociation.h"

#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcuid.h>

#include <cstdlib>
#include <memory>

namespace vsim::dicom {
namespace {

using Answers = std::vector<std::unique_ptr<DcmDataset>>;

/// The SCU of a query: counts the answers on the progress and turns Cancel into a C-CANCEL, once.
class FindingScu : public detail::PacsScu
{
public:
    explicit FindingScu(const Progress& progress) : m_progress(progress) {}
    bool cancelled() const { return m_cancelled; }

protected:
    OFCondition handleFINDResponse(const T_ASC_PresentationContextID id, QRResponse* response,
                                   OFBool& waitForNextResponse) override
    {
        const OFCondition handled = DcmSCU::handleFINDResponse(id, response, waitForNextResponse);
        ++m_answers;
        try
        {
            m_progress.report(0.0, std::to_string(m_answers) + " answers");
        }
        catch (const Cancelled&)
        {
            if (!m_cancelled)
                sendCANCELRequest(id);
            m_cancelled = true;
        }
        return handled;
    }

private:
    const Progress& m_progress;
    long m_answers = 0;
    bool m_cancelled = false;
};

bool isPending(Uint16 status)
{
    return status == STATUS_FIND_Pending_MatchesAreContinuing || status == STATUS_FIND_Pending_WarningUnsupportedOptionalKeys;
}

/// One C-FIND in `model` ("patient-root queries" for messages): the answers' datasets in the PACS's order.
Answers runFind(const PacsNode& node, const char* model, const std::string& what, DcmDataset& request,
                const Progress& progress)
{
    request.putAndInsertString(DCM_SpecificCharacterSet, "ISO_IR 192");
    FindingScu scu(progress);
    detail::Association association(node, {{model}}, &scu);
    const T_ASC_PresentationContextID id = association.context(model, what + " (C-FIND)");
    OFList<QRResponse*> responses;
    const OFCondition sent = scu.sendFINDRequest(id, &request, &responses);
    Answers answers;
    std::string failure;
    for (QRResponse* response : responses)
    {
        const std::unique_ptr<QRResponse> owned(response);
        if (response->m_status != STATUS_Success && response->m_status != STATUS_FIND_Cancel_MatchingTerminatedDueToCancelRequest &&
            !isPending(response->m_status))
            failure = "the PACS answered the query with status " + detail::statusText(response->m_status);
        if (response->m_dataset && isPending(response->m_status))
        {
            answers.emplace_back(response->m_dataset);
            response->m_dataset = nullptr; // now ours
        }
    }
    if (scu.cancelled())
        throw Cancelled();
    association.check(sent, "the query failed");
    if (!failure.empty())
        throw Error(Pattern{"%1 (%2)", {failure, describe(node)}});
    return answers;
}

int countOf(DcmDataset& answer, const DcmTagKey& tag)
{
    const std::string count = detail::datasetText(answer, tag);
    return count.empty() ? -1 : int(std::strtol(count.c_str(), nullptr, 10));
}

} // namespace

std::vector<PatientMatch> findPatients(const PacsNode& node, const PatientQuery& query, const Progress& progress)
{
    DcmDataset request;
    request.putAndInsertString(DCM_QueryRetrieveLevel, "PATIENT");
    request.putAndInsertString(DCM_PatientName, query.patientName.c_str());
    request.putAndInsertString(DCM_PatientID, query.patientId.c_str());
    request.putAndInsertString(DCM_PatientBirthDate, "");
    request.putAndInsertString(DCM_PatientSex, "");
    request.putAndInsertString(DCM_NumberOfPatientRelatedStudies, "");
    std::vector<PatientMatch> matches;
    for (const std::unique_ptr<DcmDataset>& answer :
         runFind(node, UID_FINDPatientRootQueryRetrieveInformationModel, "patient-root queries", request, progress))
    {
        PatientMatch match;
        match.patientName = detail::datasetText(*answer, DCM_PatientName);
        match.patientId = detail::datasetText(*answer, DCM_PatientID);
        match.birthDate = detail::datasetText(*answer, DCM_PatientBirthDate);
        match.sex = detail::datasetText(*answer, DCM_PatientSex);
        match.studyCount = countOf(*answer, DCM_NumberOfPatientRelatedStudies);
        matches.push_back(std::move(match));
    }
    return matches;
}

std::vector<StudyMatch> findStudies(const PacsNode& node, const StudyQuery& query, const Progress& progress)
{
    DcmDataset request;
    request.putAndInsertString(DCM_QueryRetrieveLevel, "STUDY");
    request.putAndInsertString(DCM_StudyInstanceUID, "");
    request.putAndInsertString(DCM_PatientName, query.patientName.c_str());
    request.putAndInsertString(DCM_PatientID, query.patientId.c_str());
    const std::string dates = query.dateFrom.empty() && query.dateTo.empty() ? "" : query.dateFrom + "-" + query.dateTo;
    request.putAndInsertString(DCM_StudyDate, dates.c_str());
    request.putAndInsertString(DCM_ModalitiesInStudy, query.modality.c_str());
    request.putAndInsertString(DCM_StudyDescription, "");
    request.putAndInsertString(DCM_AccessionNumber, "");
    request.putAndInsertString(DCM_NumberOfStudyRelatedSeries, "");
    std::vector<StudyMatch> matches;
    for (const std::unique_ptr<DcmDataset>& answer :
         runFind(node, UID_FINDStudyRootQueryRetrieveInformationModel, "study-root queries", request, progress))
    {
        StudyMatch match;
        match.studyInstanceUid = detail::datasetText(*answer, DCM_StudyInstanceUID);
        match.patientName = detail::datasetText(*answer, DCM_PatientName);
        match.patientId = detail::datasetText(*answer, DCM_PatientID);
        match.studyDate = detail::datasetText(*answer, DCM_StudyDate);
        match.studyDescription = detail::datasetText(*answer, DCM_StudyDescription);
        match.accessionNumber = detail::datasetText(*answer, DCM_AccessionNumber);
        match.modalities = detail::datasetText(*answer, DCM_ModalitiesInStudy);
        match.seriesCount = countOf(*answer, DCM_NumberOfStudyRelatedSeries);
        if (!match.studyInstanceUid.empty())
            matches.push_back(std::move(match));
    }
    return matches;
}

std::vector<SeriesMatch> findSeries(const PacsNode& node, const std::string& studyInstanceUid,
                                    const std::string& modality, const Progress& progress)
{
    if (studyInstanceUid.empty())
        throw Error("a series query needs the study's instance UID");
    DcmDataset request;
    request.putAndInsertString(DCM_QueryRetrieveLevel, "SERIES");
    request.putAndInsertString(DCM_StudyInstanceUID, studyInstanceUid.c_str());
    request.putAndInsertString(DCM_SeriesInstanceUID, "");
    request.putAndInsertString(DCM_Modality, modality.c_str());
    request.putAndInsertString(DCM_SeriesNumber, "");
    request.putAndInsertString(DCM_SeriesDescription, "");
    request.putAndInsertString(DCM_SeriesDate, "");
    request.putAndInsertString(DCM_NumberOfSeriesRelatedInstances, "");
    std::vector<SeriesMatch> matches;
    for (const std::unique_ptr<DcmDataset>& answer :
         runFind(node, UID_FINDStudyRootQueryRetrieveInformationModel, "study-root queries", request, progress))
    {
        SeriesMatch match;
        match.seriesInstanceUid = detail::datasetText(*answer, DCM_SeriesInstanceUID);
        match.modality = detail::datasetText(*answer, DCM_Modality);
        match.seriesNumber = detail::datasetText(*answer, DCM_SeriesNumber);
        match.seriesDescription = detail::datasetText(*answer, DCM_SeriesDescription);
        match.seriesDate = detail::datasetText(*answer, DCM_SeriesDate);
        match.instanceCount = countOf(*answer, DCM_NumberOfSeriesRelatedInstances);
        if (!match.seriesInstanceUid.empty())
            matches.push_back(std::move(match));
    }
    return matches;
}

} // namespace vsim::dicom
