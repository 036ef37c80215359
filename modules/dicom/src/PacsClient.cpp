#include "vsim/dicom/PacsClient.h"

#include "vsim/core/Error.h"

#include "DatasetText.h"
#include "DcmtkSetup.h"

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
namespace {

/// A presentation context to propose: an abstract syntax and our role (SCP for the storage classes of a C-GET,
/// whose objects come back on the same association).
struct Proposed
{
    const char* abstractSyntax;
    T_ASC_SC_ROLE role = ASC_SC_ROLE_DEFAULT;
};

/// The SCU of a C-GET: counts the objects it writes and reports them.
class RetrievingScu : public DcmSCU
{
public:
    mutable std::vector<std::filesystem::path> files; ///< DCMTK tells of each in a const function
    const Progress* progress = nullptr;

protected:
    void notifyInstanceStored(const OFString& filename, const OFString&, const OFString&) const override
    {
        files.emplace_back(filename.c_str());
        if (progress)
            progress->report(0.0, "retrieved " + std::to_string(files.size()) + " objects");
    }
};

/// An association to `node` on `scu` proposing the given contexts (explicit then implicit little endian).
class Association
{
public:
    Association(const PacsNode& node, const std::vector<Proposed>& contexts, DcmSCU* scu = nullptr)
        : m_node(node), m_owned(scu ? nullptr : std::make_unique<DcmSCU>()), m_scu(scu ? *scu : *m_owned)
    {
        ensureDcmtkCodecs(); // and DCMTK's own logging quiet
        if (node.calledAeTitle.empty() || node.calledAeTitle.size() > 16 || node.callingAeTitle.empty() ||
            node.callingAeTitle.size() > 16)
            throw Error("AE titles have 1 to 16 characters (PACS '" + node.calledAeTitle + "', ours '" +
                        node.callingAeTitle + "')");
        if (node.host.empty() || node.port < 1 || node.port > 65535)
            throw Error("a PACS node needs a host and a port from 1 to 65535 (" + describe(node) + ")");
        m_scu.setAETitle(node.callingAeTitle.c_str());
        m_scu.setPeerAETitle(node.calledAeTitle.c_str());
        m_scu.setPeerHostName(node.host.c_str());
        m_scu.setPeerPort(Uint16(node.port));
        m_scu.setACSETimeout(Uint32(node.timeoutS));
        m_scu.setConnectionTimeout(Sint32(node.timeoutS));
        m_scu.setDIMSEBlockingMode(DIMSE_NONBLOCKING);
        m_scu.setDIMSETimeout(Uint32(node.timeoutS));
        OFList<OFString> syntaxes;
        syntaxes.push_back(UID_LittleEndianExplicitTransferSyntax);
        syntaxes.push_back(UID_LittleEndianImplicitTransferSyntax);
        for (const Proposed& context : contexts)
            m_scu.addPresentationContext(context.abstractSyntax, syntaxes, context.role);
        check(m_scu.initNetwork(), "could not start the network");
        const OFCondition negotiated = m_scu.negotiateAssociation();
        if (negotiated == DUL_ASSOCIATIONREJECTED)
            throw Error("the PACS " + describe(node) + " rejected the association: is our AE title '" + node.callingAeTitle +
                        "' registered there, and is its own '" + node.calledAeTitle + "'?");
        check(negotiated, "could not connect");
    }

    ~Association()
    {
        if (m_scu.isConnected())
            m_scu.releaseAssociation();
    }

    Association(const Association&) = delete;
    Association& operator=(const Association&) = delete;

    DcmSCU& scu() { return m_scu; }

    /// The accepted presentation context for `abstractSyntax`; throws when the PACS accepted none.
    T_ASC_PresentationContextID context(const char* abstractSyntax, const char* what)
    {
        const T_ASC_PresentationContextID id = m_scu.findPresentationContextID(abstractSyntax, "");
        if (id == 0)
            throw Error("the PACS " + describe(m_node) + " does not offer " + what);
        return id;
    }

    void check(const OFCondition& condition, const std::string& what) const
    {
        if (condition.bad())
            throw Error(what + " (" + describe(m_node) + "): " + condition.text());
    }

private:
    PacsNode m_node;
    std::unique_ptr<DcmSCU> m_owned;
    DcmSCU& m_scu;
};

} // namespace

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
        {
            char status[8];
            std::snprintf(status, sizeof status, "%04X", unsigned(response->m_status));
            failure = std::string("the PACS answered the query with status 0x") + status;
        }
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
    std::error_code error;
    if (std::filesystem::exists(folder, error) && !std::filesystem::is_empty(folder, error))
        throw Error("the retrieve's folder is not empty: " + folder.string());
    std::filesystem::create_directories(folder, error);
    if (error)
        throw Error("cannot create the retrieve's folder " + folder.string() + ": " + error.message());
    RetrievingScu scu;
    scu.progress = &progress;
    scu.setStorageDir(folder.string().c_str());
    scu.setStorageMode(DCMSCU_STORAGE_DISK);
    // The objects a study holds that VascuSim reads or made.
    std::vector<Proposed> contexts = {{UID_GETStudyRootQueryRetrieveInformationModel}};
    for (const char* storage : {UID_CTImageStorage, UID_EnhancedCTImageStorage, UID_SegmentationStorage,
                                UID_EncapsulatedPDFStorage, UID_SecondaryCaptureImageStorage})
        contexts.push_back({storage, ASC_SC_ROLE_SCP});
    OFList<RetrieveResponse*> responses;
    OFCondition sent;
    std::string failure;
    {
        Association association(node, contexts, &scu);
        const T_ASC_PresentationContextID id =
            association.context(UID_GETStudyRootQueryRetrieveInformationModel, "study-root retrieval (C-GET)");
        DcmDataset request;
        request.putAndInsertString(DCM_QueryRetrieveLevel, "STUDY");
        request.putAndInsertString(DCM_StudyInstanceUID, studyInstanceUid.c_str());
        sent = scu.sendCGETRequest(id, &request, &responses);
        for (RetrieveResponse* response : responses)
        {
            std::unique_ptr<RetrieveResponse> owned(response);
            if (response->m_status == STATUS_Pending)
                continue;
            if (response->m_status != STATUS_Success || response->m_numberOfFailedSubops > 0)
            {
                char status[8];
                std::snprintf(status, sizeof status, "%04X", unsigned(response->m_status));
                failure = std::string("the PACS ended the retrieve with status 0x") + status + ", " +
                          std::to_string(response->m_numberOfFailedSubops) + " objects failed";
            }
        }
        if (sent.bad() && failure.empty())
            failure = std::string("the retrieve broke off: ") + sent.text();
    }
    if (failure.empty() && scu.files.empty())
        failure = "the PACS sent nothing for study " + studyInstanceUid;
    if (!failure.empty())
    {
        // No half retrieve: the objects written so far go (the folder was empty or new).
        for (const std::filesystem::path& file : scu.files)
            std::filesystem::remove(file, error);
        throw Error(failure + " (" + describe(node) + ")");
    }
    return scu.files;
}

} // namespace vsim::dicom
