#include "vsim/dicom/PacsClient.h"

#include "vsim/core/Error.h"
#include "vsim/core/StoredText.h"

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
#include <mutex>

namespace vsim::dicom {

using detail::Association;
using detail::Proposed;

void prepareDicomNetworking()
{
    static std::once_flag once;
    std::call_once(once, [] { setenv("TCP_NODELAY", "1", 0); }); // read by DCMTK at each connection (DUL, DULFSM)
}

std::string describe(const PacsNode& node)
{
    const std::vector<std::string> values = {node.calledAeTitle, node.host, std::to_string(node.port)};
    return node.tls.enabled ? storedText(Pattern{"%1 at %2:%3 (TLS)", values}) : storedText(Pattern{"%1 at %2:%3", values});
}

std::string RetrieveTarget::describe() const
{
    return seriesInstanceUid.empty() ? "study " + studyInstanceUid
                                     : "series " + seriesInstanceUid + " of study " + studyInstanceUid;
}

void pacsEcho(const PacsNode& node)
{
    Association association(node, {{UID_VerificationSOPClass}});
    const T_ASC_PresentationContextID id = association.context(UID_VerificationSOPClass, "verification (C-ECHO)");
    association.check(association.scu().sendECHORequest(id), "the echo failed");
}

std::vector<std::filesystem::path> retrieveStudy(const PacsNode& node, const RetrieveTarget& target,
                                                const std::filesystem::path& folder, const Progress& progress)
{
    DcmDataset request;
    detail::retrieveRequest(request, target); // checks the target before the folder is made
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
        OFList<RetrieveResponse*> responses;
        const OFCondition sent = scu.sendCGETRequest(id, &request, &responses);
        failure = detail::retrieveFailure(responses);
        for (RetrieveResponse* response : responses)
            delete response;
        if (sent.bad() && failure.empty())
            failure = std::string("the retrieve broke off: ") + sent.text();
    }
    return detail::settleRetrieve(watcher, scu.files, failure, target, node);
}

} // namespace vsim::dicom
