#include "vsim/dicom/PacsClient.h"

#include "vsim/core/Error.h"

#include "DatasetText.h"
#include "PacsAssociation.h"

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <dcmtk/dcmnet/diutil.h>
#include <dcmtk/dcmnet/scu.h>

#include <cstdio>
#include <filesystem>
#include <cstdlib>
#include <memory>

namespace vsim::dicom {

using detail::Association;
using detail::Proposed;

std::string describe(const PacsNode& node)
{
    return node.calledAeTitle + " at " + node.host + ":" + std::to_string(node.port);
}

void pacsEcho(const PacsNode& node)
{
    Association association(node, {{UID_VerificationSOPClass}});
    const T_ASC_PresentationContextID id = association.context(UID_VerificationSOPClass, "verification (C-ECHO)");
    association.check(association.scu().sendECHORequest(id), "the echo failed");
}

std::vector<StudyMatch> findStudies(const PacsNode& node, const StudyQuery& query)
{
    Association association(node, {{UID_FINDStudyRootQueryRetrieveInformationModel}});
    const T_ASC_PresentationContextID id =
        association.context(UID_FINDStudyRootQueryRetrieveInformationModel, "study-root queries (C-FIND)");
    DcmDataset request;
    request.putAndInsertString(DCM_SpecificCharacterSet, "ISO_IR 192");
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
    OFList<QRResponse*> responses;
    const OFCondition sent = association.scu().sendFINDRequest(id, &request, &responses);
    std::vector<StudyMatch> matches;
    std::string failure;
    for (QRResponse* response : responses)
    {
        std::unique_ptr<QRResponse> owned(response);
        if (response->m_status != STATUS_Success && response->m_status != STATUS_FIND_Pending_MatchesAreContinuing &&
            response->m_status != STATUS_FIND_Pending_WarningUnsupportedOptionalKeys)
            failure = "the PACS answered the query with status " + detail::statusText(response->m_status);
        if (!response->m_dataset)
            continue;
        DcmDataset& answer = *response->m_dataset;
        StudyMatch match;
        match.studyInstanceUid = detail::datasetText(answer, DCM_StudyInstanceUID);
        match.patientName = detail::datasetText(answer, DCM_PatientName);
        match.patientId = detail::datasetText(answer, DCM_PatientID);
        match.studyDate = detail::datasetText(answer, DCM_StudyDate);
        match.studyDescription = detail::datasetText(answer, DCM_StudyDescription);
        match.accessionNumber = detail::datasetText(answer, DCM_AccessionNumber);
        match.modalities = detail::datasetText(answer, DCM_ModalitiesInStudy);
        const std::string series = detail::datasetText(answer, DCM_NumberOfStudyRelatedSeries);
        match.seriesCount = series.empty() ? -1 : int(std::strtol(series.c_str(), nullptr, 10));
        if (!match.studyInstanceUid.empty())
            matches.push_back(std::move(match));
    }
    association.check(sent, "the query failed");
    if (!failure.empty())
        throw Error(failure + " (" + describe(node) + ")");
    return matches;
}

std::vector<std::filesystem::path> retrieveStudy(const PacsNode& node, const std::string& studyInstanceUid,
                                                const std::filesystem::path& folder, const Progress& progress)
{
    if (studyInstanceUid.empty())
        throw Error("a retrieve needs the study's instance UID");
    detail::prepareRetrieveFolder(folder);
    const detail::RetrieveWatcher watcher(progress);
    detail::RetrievingScu scu(watcher);
    scu.setStorageDir(folder.string().c_str());
    scu.setStorageMode(DCMSCU_STORAGE_DISK);
    std::vector<Proposed> contexts = {{UID_GETStudyRootQueryRetrieveInformationModel}};
    for (const char* storage : detail::retrievedStorageClasses())
        contexts.push_back({storage, ASC_SC_ROLE_SCP}); // the objects come back on the same association
    std::string failure;
    {
        Association association(node, contexts, &scu);
        const T_ASC_PresentationContextID id =
            association.context(UID_GETStudyRootQueryRetrieveInformationModel, "study-root retrieval (C-GET)");
        DcmDataset request;
        detail::studyRetrieveRequest(request, studyInstanceUid);
        OFList<RetrieveResponse*> responses;
        const OFCondition sent = scu.sendCGETRequest(id, &request, &responses);
        failure = detail::retrieveFailure(responses);
        for (RetrieveResponse* response : responses)
            delete response;
        if (sent.bad() && failure.empty())
            failure = std::string("the retrieve broke off: ") + sent.text();
    }
    return detail::settleRetrieve(watcher, scu.files, failure, studyInstanceUid, node);
}

} // namespace vsim::dicom
