#pragma once

// One DICOM association to a PACS node, shared by the PACS client's calls (PacsClient, PacsFind, PacsMove, PacsStore):
// checks the node's settings, proposes the presentation contexts, negotiates (over TLS on a TLS node), maps a
// rejection to words, and releases at the end of its scope. Internal to the dicom module.

#include "vsim/core/Error.h"
#include "vsim/dicom/PacsClient.h"

#include "DcmtkSetup.h"

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <dcmtk/dcmnet/scu.h>
#include <dcmtk/dcmtls/tlslayer.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace vsim::dicom::detail {

/// The TLS layer of our end of an association (PacsTls.cpp): a requestor verifies the PACS and shows our
/// certificate when one is set; an acceptor (the move's listener) always shows ours. Throws vsim::Error naming the
/// file that is missing, unreadable or does not match.
std::unique_ptr<DcmTLSTransportLayer> makeTlsLayer(const PacsTls& tls, bool acceptor);

/// A presentation context to propose: an abstract syntax and our role (SCP for the storage classes of a C-GET,
/// whose objects come back on the same association).
struct Proposed
{
    std::string abstractSyntax;
    T_ASC_SC_ROLE role = ASC_SC_ROLE_DEFAULT;
    /// A transfer syntax to propose first (an object's own, for C-STORE); explicit and implicit little endian follow.
    std::string transferSyntax = {};
};

/// DCMTK's SCU with its TLS switch in reach (DcmSCU keeps it protected; DcmTLSSCU would fix the SCU's class).
class PacsScu : public DcmSCU
{
public:
    using DcmSCU::useSecureConnection;
};

/// An association to `node` on `scu` proposing the given contexts (explicit then implicit little endian).
class Association
{
public:
    Association(const PacsNode& node, const std::vector<Proposed>& contexts, PacsScu* scu = nullptr)
        : m_node(node), m_owned(scu ? nullptr : std::make_unique<PacsScu>()), m_scu(scu ? *scu : *m_owned)
    {
        ensureDcmtkCodecs(); // and DCMTK's own logging quiet
        prepareDicomNetworking();
        if (node.calledAeTitle.empty() || node.calledAeTitle.size() > 16 || node.callingAeTitle.empty() ||
            node.callingAeTitle.size() > 16)
            throw Error(Pattern{"AE titles have 1 to 16 characters (PACS '%1', ours '%2')",
                                {node.calledAeTitle, node.callingAeTitle}});
        if (node.host.empty() || node.port < 1 || node.port > 65535)
            throw Error(Pattern{"a PACS node needs a host and a port from 1 to 65535 (%1)", {describe(node)}});
        m_scu.setAETitle(node.callingAeTitle.c_str());
        m_scu.setPeerAETitle(node.calledAeTitle.c_str());
        m_scu.setPeerHostName(node.host.c_str());
        m_scu.setPeerPort(Uint16(node.port));
        m_scu.setACSETimeout(Uint32(node.timeoutS));
        m_scu.setConnectionTimeout(Sint32(node.timeoutS));
        m_scu.setDIMSEBlockingMode(DIMSE_NONBLOCKING);
        m_scu.setDIMSETimeout(Uint32(node.timeoutS));
        for (const Proposed& context : contexts)
        {
            OFList<OFString> syntaxes;
            for (const std::string& syntax : {context.transferSyntax, std::string(UID_LittleEndianExplicitTransferSyntax),
                                              std::string(UID_LittleEndianImplicitTransferSyntax)})
                if (!syntax.empty() && std::find(syntaxes.begin(), syntaxes.end(), OFString(syntax.c_str())) == syntaxes.end())
                    syntaxes.push_back(syntax.c_str());
            m_scu.addPresentationContext(context.abstractSyntax.c_str(), syntaxes, context.role);
        }
        check(m_scu.initNetwork(), "could not start the network");
        if (node.tls.enabled)
        {
            m_tls = makeTlsLayer(node.tls, false);
            check(m_scu.useSecureConnection(m_tls.get()), "could not set up DICOM TLS");
        }
        const OFCondition negotiated = m_scu.negotiateAssociation();
        if (negotiated == DUL_ASSOCIATIONREJECTED)
            throw Error(Pattern{"the PACS %1 rejected the association: is our AE title '%2' registered there, and is "
                                "its own '%3'?",
                                {describe(node), node.callingAeTitle, node.calledAeTitle}});
        if (negotiated == DUL_READTIMEOUT)
            throw Error(node.tls.enabled
                            ? Pattern{"the PACS %1 took the connection but did not answer within %2 s (is it a DICOM "
                                      "node, is the port its DICOM port, and does it speak DICOM TLS there?)",
                                      {describe(node), std::to_string(node.timeoutS)}}
                            : Pattern{"the PACS %1 took the connection but did not answer within %2 s (is it a DICOM "
                                      "node, and is the port its DICOM port?)",
                                      {describe(node), std::to_string(node.timeoutS)}});
        if (negotiated.bad() && node.tls.enabled)
            throw Error(Pattern{"could not connect over DICOM TLS (%1): %2 (does the PACS speak TLS on this port, is "
                                "its certificate among those we trust (%3), and does it trust ours?)",
                                {describe(node), negotiated.text(), node.tls.trustedCertificates}});
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
    T_ASC_PresentationContextID context(const std::string& abstractSyntax, const std::string& what)
    {
        const T_ASC_PresentationContextID id = m_scu.findPresentationContextID(abstractSyntax.c_str(), "");
        if (id == 0)
            throw Error(Pattern{"the PACS %1 does not offer %2", {describe(m_node), what}});
        return id;
    }

    void check(const OFCondition& condition, const std::string& what) const
    {
        if (condition.bad())
            throw Error(Pattern{"%1 (%2): %3", {what, describe(m_node), condition.text()}});
    }

private:
    PacsNode m_node;
    std::unique_ptr<PacsScu> m_owned;
    PacsScu& m_scu;
    std::unique_ptr<DcmTLSTransportLayer> m_tls; ///< outlives the association (the SCU does not own it)
};

/// A DIMSE status as the standard writes it, e.g. "0xA700" (PS3.7 C).
inline std::string statusText(Uint16 status)
{
    char text[8];
    std::snprintf(text, sizeof text, "%04X", unsigned(status));
    return std::string("0x") + text;
}

/// Follows a C-GET's or C-MOVE's responses and received objects: reports the fraction of sub-operations done, and
/// turns the user's Cancel into a C-CANCEL (PS3.7 9.3.2.3) at the next response, so that DCMTK's loops are never
/// left by an exception. The caller removes what was received when cancelled() or failed.
class RetrieveWatcher
{
public:
    explicit RetrieveWatcher(const Progress& progress) : m_progress(progress) {}

    /// An object arrived (counted for PACSes that send no pending responses).
    void objectReceived() const
    {
        ++m_received;
        report(m_received, m_total, "retrieved " + std::to_string(m_received) + " objects");
    }

    /// A response of the retrieve; true when the retrieve must be cancelled now (once).
    bool response(const RetrieveResponse& answer) const
    {
        const long done = long(answer.m_numberOfCompletedSubops) + answer.m_numberOfFailedSubops +
                          answer.m_numberOfWarningSubops;
        if (answer.m_status == STATUS_Pending)
            m_total = done + answer.m_numberOfRemainingSubops;
        report(done, m_total, "retrieved " + std::to_string(done) + " of " + std::to_string(m_total) + " objects");
        if (m_cancelRequested && !m_cancelSent)
            return m_cancelSent = true;
        return false;
    }

    bool cancelled() const { return m_cancelRequested; }

private:
    void report(long done, long total, const std::string& stage) const
    {
        try
        {
            m_progress.report(total > 0 ? std::min(1.0, double(done) / double(total)) : 0.0, stage);
        }
        catch (const Cancelled&)
        {
            m_cancelRequested = true;
        }
    }

    const Progress& m_progress;
    mutable long m_received = 0, m_total = 0;
    mutable bool m_cancelRequested = false, m_cancelSent = false;
};

/// The SCU of a C-GET or a C-MOVE: progress and Cancel through the watcher; the files a C-GET writes (a C-MOVE's go
/// to its listener).
class RetrievingScu : public PacsScu
{
public:
    explicit RetrievingScu(const RetrieveWatcher& watcher) : m_watcher(watcher) {}

    mutable std::vector<std::filesystem::path> files; ///< DCMTK tells of each in a const function

protected:
    void notifyInstanceStored(const OFString& filename, const OFString&, const OFString&) const override
    {
        files.emplace_back(filename.c_str());
        m_watcher.objectReceived();
    }

    OFCondition handleCGETResponse(const T_ASC_PresentationContextID id, RetrieveResponse* response,
                                   OFBool& continueSession) override
    {
        const OFCondition handled = DcmSCU::handleCGETResponse(id, response, continueSession);
        watch(id, response);
        return handled;
    }

    OFCondition handleMOVEResponse(const T_ASC_PresentationContextID id, RetrieveResponse* response,
                                   OFBool& waitForNext) override
    {
        const OFCondition handled = DcmSCU::handleMOVEResponse(id, response, waitForNext);
        watch(id, response);
        return handled;
    }

private:
    void watch(T_ASC_PresentationContextID id, const RetrieveResponse* response)
    {
        if (response != nullptr && m_watcher.response(*response))
            sendCANCELRequest(id);
    }

    const RetrieveWatcher& m_watcher;
};

/// The request of a study- or series-level retrieve; throws when the target names no study.
inline void retrieveRequest(DcmDataset& request, const RetrieveTarget& target)
{
    if (target.studyInstanceUid.empty())
        throw Error("a retrieve needs the study's instance UID");
    const bool series = !target.seriesInstanceUid.empty();
    request.putAndInsertString(DCM_QueryRetrieveLevel, series ? "SERIES" : "STUDY");
    request.putAndInsertString(DCM_StudyInstanceUID, target.studyInstanceUid.c_str());
    if (series)
        request.putAndInsertString(DCM_SeriesInstanceUID, target.seriesInstanceUid.c_str());
}

/// Removes the files a failed or cancelled retrieve wrote (its folder was new or empty): nothing half retrieved.
inline void removeReceived(const std::vector<std::filesystem::path>& files)
{
    std::error_code ignored;
    for (const std::filesystem::path& file : files)
        std::filesystem::remove(file, ignored);
}

/// Ends a retrieve: the files when it brought some and did not fail; otherwise removes what arrived and throws
/// Cancelled, or vsim::Error with the failure (`hintWhenEmpty` added when nothing arrived) and the node.
inline std::vector<std::filesystem::path> settleRetrieve(const RetrieveWatcher& watcher,
                                                        const std::vector<std::filesystem::path>& files,
                                                        std::string failure, const RetrieveTarget& target,
                                                        const PacsNode& node, const std::string& hintWhenEmpty = {})
{
    if (watcher.cancelled())
    {
        removeReceived(files);
        throw Cancelled();
    }
    if (failure.empty() && files.empty())
        failure = "the PACS sent nothing for " + target.describe();
    if (failure.empty())
        return files;
    removeReceived(files);
    if (failure.find(target.studyInstanceUid) == std::string::npos)
        failure += " (" + target.describe() + ")";
    if (files.empty() && !hintWhenEmpty.empty())
        failure += "; " + hintWhenEmpty;
    if (failure.find(describe(node)) == std::string::npos)
        failure += " (" + describe(node) + ")";
    throw Error(failure);
}

/// Checks that `folder` is new or empty and creates it.
inline void prepareRetrieveFolder(const std::filesystem::path& folder)
{
    std::error_code error;
    if (std::filesystem::exists(folder, error) && !std::filesystem::is_empty(folder, error))
        throw Error(Pattern{"the retrieve's folder is not empty: %1", {folder.string()}});
    std::filesystem::create_directories(folder, error);
    if (error)
        throw Error(Pattern{"cannot create the retrieve's folder %1: %2", {folder.string(), error.message()}});
}

/// The storage classes a retrieve accepts: DCMTK's list of the 120 most common (CT, enhanced CT, SEG, encapsulated
/// PDF and secondary capture among them, which VascuSim reads or made; MR, PET, the dose and other structured
/// reports, key objects and presentation states too), so that a study's other objects do not fail its retrieve.
/// With the retrieve's own context they fit the 128 contexts of one association (PS3.8 9.3.2.2).
inline std::vector<const char*> retrievedStorageClasses()
{
    return {dcmLongSCUStorageSOPClassUIDs, dcmLongSCUStorageSOPClassUIDs + numberOfDcmLongSCUStorageSOPClassUIDs};
}

/// The failure that the final response of a retrieve reports, or "" for success.
inline std::string retrieveFailure(const OFList<RetrieveResponse*>& responses)
{
    std::string failure;
    for (const RetrieveResponse* response : responses)
    {
        if (response->m_status == STATUS_Pending)
            continue;
        if (response->m_status != STATUS_Success || response->m_numberOfFailedSubops > 0)
            failure = "the PACS ended the retrieve with status " + statusText(response->m_status) + " (objects sent " +
                      std::to_string(response->m_numberOfCompletedSubops) + ", failed " +
                      std::to_string(response->m_numberOfFailedSubops) + ", not sent " +
                      std::to_string(response->m_numberOfRemainingSubops) + ")";
    }
    return failure;
}

} // namespace vsim::dicom::detail
