// C-MOVE of a study or a series to VascuSim's own storage listener (PS3.4 C.4.2; issue 22). The move request goes
// on one association; the PACS opens a second one to the move destination (our AE title at our listener, over TLS
// on a TLS node) and stores the objects there, while its pending responses on the first tell how far it is.

#include "vsim/dicom/PacsClient.h"

#include "vsim/core/Error.h"

#include "PacsAssociation.h"

#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmnet/dstorscp.h>

#include <atomic>
#include <mutex>
#include <thread>

namespace vsim::dicom {
namespace {

/// The move destination: a storage SCP that writes each object it receives into the folder, until stopped. It runs
/// on its own thread; the progress comes from the move's responses on the caller's.
class MoveListener : public DcmStorageSCP
{
public:
    std::vector<std::filesystem::path> files() const
    {
        std::lock_guard lock(m_mutex);
        return m_files;
    }

    void stop() { m_stop = true; }

protected:
    void notifyInstanceStored(const OFString& filename, const OFString&, const OFString&, DcmDataset*) const override
    {
        std::lock_guard lock(m_mutex);
        m_files.emplace_back(filename.c_str());
    }

    OFBool stopAfterConnectionTimeout() override { return m_stop; }
    OFBool stopAfterCurrentAssociation() override { return m_stop; }

private:
    mutable std::mutex m_mutex;
    mutable std::vector<std::filesystem::path> m_files;
    std::atomic<bool> m_stop{false};
};

} // namespace

std::vector<std::filesystem::path> moveStudy(const PacsNode& node, const RetrieveTarget& target,
                                            const std::filesystem::path& folder, int listenPort,
                                            const Progress& progress)
{
    DcmDataset request;
    detail::retrieveRequest(request, target); // checks the target before the folder is made
    if (listenPort < 1 || listenPort > 65535)
        throw Error(Pattern{"the move's listening port must be from 1 to 65535, not %1", {std::to_string(listenPort)}});
    // The listener's TLS layer first: a certificate that is missing fails before any folder is made.
    const std::unique_ptr<DcmTLSTransportLayer> tls = node.tls.enabled ? detail::makeTlsLayer(node.tls, true) : nullptr;
    detail::prepareRetrieveFolder(folder);
    const detail::RetrieveWatcher watcher(progress);

    prepareDicomNetworking();
    MoveListener listener;
    if (tls)
        listener.getConfig().setTransportLayer(tls.get());
    listener.setAETitle(node.callingAeTitle.c_str());
    listener.setPort(Uint16(listenPort));
    listener.setConnectionBlockingMode(DUL_NOBLOCK);
    listener.setConnectionTimeout(1); // s: how soon it notices stop()
    listener.setACSETimeout(Uint32(node.timeoutS));
    listener.setDIMSETimeout(Uint32(node.timeoutS));
    listener.setHostLookupEnabled(OFFalse);
    listener.setOutputDirectory(folder.string().c_str());
    listener.setDirectoryGenerationMode(DcmStorageSCP::DGM_NoSubdirectory);
    listener.setFilenameGenerationMode(DcmStorageSCP::FGM_SOPInstanceUID);
    OFList<OFString> syntaxes;
    syntaxes.push_back(UID_LittleEndianExplicitTransferSyntax);
    syntaxes.push_back(UID_LittleEndianImplicitTransferSyntax);
    for (const char* storage : detail::retrievedStorageClasses())
        listener.addPresentationContext(storage, syntaxes);
    const OFCondition opened = listener.openListenPort();
    if (opened.bad())
        throw Error(Pattern{"cannot listen on port %1 for the move: %2 (is another program using it?)",
                            {std::to_string(listenPort), opened.text()}});
    std::thread listening([&listener] { listener.acceptAssociations(); });

    std::string failure;
    try
    {
        detail::RetrievingScu scu(watcher);
        detail::Association association(node, {{UID_MOVEStudyRootQueryRetrieveInformationModel}}, &scu);
        const T_ASC_PresentationContextID id =
            association.context(UID_MOVEStudyRootQueryRetrieveInformationModel, "study-root retrieval (C-MOVE)");
        OFList<RetrieveResponse*> responses;
        const OFCondition sent = scu.sendMOVERequest(id, node.callingAeTitle.c_str(), &request, &responses);
        failure = detail::retrieveFailure(responses);
        for (RetrieveResponse* response : responses)
            delete response;
        if (sent.bad() && failure.empty())
            failure = std::string("the move broke off: ") + sent.text();
    }
    catch (const Error& error)
    {
        failure = error.what();
    }
    // The final response comes after the PACS's last store; the listener then stops within its 1 s timeout.
    listener.stop();
    listening.join();
    // A move that delivered nothing most often went nowhere: the PACS sends to the address it has for our AE title
    // (0xA801 "move destination unknown"; Orthanc answers 0xC000).
    return detail::settleRetrieve(watcher, listener.files(), failure, target, node,
                                  "is our AE title " + node.callingAeTitle + " registered at the PACS with this "
                                  "machine's address and port " + std::to_string(listenPort) + "?");
}

} // namespace vsim::dicom
