#pragma once

// A DICOM network client for a PACS (issue 22; DCMTK dcmnet, PS3.4 / PS3.7): C-ECHO to test a node; C-FIND at the
// patient level (Patient Root information model), the study and the series level (Study Root); C-GET or C-MOVE of a
// study or one of its series into a folder; C-STORE of our results. Each call opens one association from our AE
// title to the node's, over DICOM TLS when the node asks for it (PS3.15 B.1; DCMTK dcmtls), and releases it.
// Failures come back as vsim::Error with what went wrong in words: the connection refused or not answered within
// the timeout, the association rejected (the node does not know our AE title, or its own is not the one
// configured), a certificate not trusted, a response that is not success. Text in queries and answers is UTF-8
// (ISO_IR 192).

#include "vsim/core/Progress.h"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace vsim::dicom {

/// DICOM TLS to a node (PS3.15 B.1, the BCP 195 profile): the PACS proves itself with a certificate that one of
/// `trustedCertificates` signed (or that is one of them); we show ours when the PACS asks for one. Files are PEM.
struct PacsTls
{
    bool enabled = false;
    std::string trustedCertificates; ///< the PACS's certificate or its authority's (required with TLS)
    std::string certificate;         ///< ours (optional: for a PACS that requires client certificates, and for C-MOVE)
    std::string privateKey;          ///< the private key of ours, not encrypted (with `certificate`)
};

/// A PACS node as the settings hold it.
struct PacsNode
{
    std::string calledAeTitle;               ///< the PACS's AE title (at most 16 characters)
    std::string host;                        ///< name or address
    int port = 104;
    std::string callingAeTitle = "VASCUSIM"; ///< ours
    int timeoutS = 30;                       ///< connection and each response (s)
    PacsTls tls;                             ///< plain DICOM unless tls.enabled
};

/// Patient-level filters (Patient Root model); empty fields match anything. Names may hold the wildcards * and ?.
struct PatientQuery
{
    std::string patientName, patientId;
};

struct PatientMatch
{
    std::string patientName, patientId, birthDate, sex;
    int studyCount = -1; ///< -1 when the PACS does not say
};

/// Study-level filters; empty fields match anything. Names may hold the wildcards * and ?.
struct StudyQuery
{
    std::string patientName, patientId;
    std::string dateFrom, dateTo; ///< YYYYMMDD, inclusive; either may be empty (open range)
    std::string modality;         ///< e.g. CT (matched against the study's modalities)
};

struct StudyMatch
{
    std::string studyInstanceUid, patientName, patientId, studyDate, studyDescription, accessionNumber;
    std::string modalities; ///< as the PACS lists them, e.g. "CT\SEG"
    int seriesCount = -1;   ///< -1 when the PACS does not say
};

struct SeriesMatch
{
    std::string seriesInstanceUid, modality, seriesNumber, seriesDescription, seriesDate;
    int instanceCount = -1; ///< -1 when the PACS does not say
};

/// What a retrieve fetches: a study, or one series of it.
struct RetrieveTarget
{
    std::string studyInstanceUid;
    std::string seriesInstanceUid; ///< empty: the whole study

    RetrieveTarget(std::string study, std::string series = {}) // NOLINT: a study UID is the common target
        : studyInstanceUid(std::move(study)), seriesInstanceUid(std::move(series))
    {
    }
    /// "study 1.2.3" or "series 1.2.3.4 of study 1.2.3" (for messages).
    std::string describe() const;
};

/// DICOM associations without Nagle's algorithm. DCMTK leaves it on unless the environment variable TCP_NODELAY
/// says otherwise, and then each small PDU of a query or a transfer waits for the peer's delayed acknowledgement
/// (about 40 ms on Linux): a phantom study's echo, queries and C-GETs took 17.2 s against 2.7 s without it
/// (tst_dicom_pacs, 2026-12-02). Sets TCP_NODELAY=1 for this process unless it is set already (the user's choice
/// stands). The programs call it at start, before any thread; every association and the move's listener call it
/// too (once per process).
void prepareDicomNetworking();

/// Throws vsim::Error when the node cannot be reached, rejects us, or does not answer the echo with success.
void pacsEcho(const PacsNode& node);

/// The queries: the matches in the PACS's order. Each reports the number of answers so far on `progress`; Cancel
/// there sends a C-CANCEL (PS3.7 9.3.2.3) at the next answer and throws vsim::Cancelled. Throws vsim::Error as
/// pacsEcho, and for a failed query.
std::vector<PatientMatch> findPatients(const PacsNode& node, const PatientQuery& query, const Progress& progress = {});
std::vector<StudyMatch> findStudies(const PacsNode& node, const StudyQuery& query, const Progress& progress = {});
/// The series of one study; `modality` empty matches any.
std::vector<SeriesMatch> findSeries(const PacsNode& node, const std::string& studyInstanceUid,
                                    const std::string& modality = {}, const Progress& progress = {});

/// C-GET of every object of the study, or of the one series (CT, enhanced CT, SEG, encapsulated PDF, secondary
/// capture) into `folder` (created; it must be new or empty). Returns the files written. Throws vsim::Error as
/// pacsEcho, and when the PACS reports a failure, sends nothing, or the transfer breaks off; the files written so
/// far are removed then (nothing half retrieved is left).
std::vector<std::filesystem::path> retrieveStudy(const PacsNode& node, const RetrieveTarget& target,
                                                const std::filesystem::path& folder, const Progress& progress = {});

/// C-MOVE of every object of the study, or of the one series, to VascuSim itself: a storage listener with our AE
/// title opens on `listenPort` for the move, and the PACS sends the objects there on an association of its own
/// (over TLS on a TLS node: the listener shows our certificate, which the node then needs). The PACS must know our
/// AE title with this machine's address and that port (its configuration, as for any move destination; C-GET
/// needs none). Files into `folder` with retrieveStudy's guarantees, and throws as it does, also when the port
/// cannot be opened; a move that delivered nothing asks whether our AE title is registered there.
std::vector<std::filesystem::path> moveStudy(const PacsNode& node, const RetrieveTarget& target,
                                            const std::filesystem::path& folder, int listenPort,
                                            const Progress& progress = {});

/// What to do with a de-identified object (Patient Identity Removed YES, e.g. a report made with --anonymize).
enum class AnonymizedObjects
{
    Refuse,  ///< nothing is sent; the message says why (the default: it must not join a patient's study)
    NewStudy ///< sent as a new study: new study, series and instance UIDs (the file itself is not changed)
};

/// One object sent by storeFiles.
struct StoredObject
{
    std::filesystem::path file;
    std::string sopClassUid, sopInstanceUid, studyInstanceUid, seriesInstanceUid, modality;
    bool asNewStudy = false; ///< its UIDs were replaced (AnonymizedObjects::NewStudy)
};

/// C-STORE of DICOM files (e.g. the report's Encapsulated PDF and the labels' SEG) to the node, on one association.
/// Every file is read and checked before anything is sent. Throws vsim::Error when a file is not DICOM, when a
/// de-identified one is refused (`anonymized`), as pacsEcho, when the PACS accepts no presentation context for a
/// file's class, and when an object is not stored (the message names which, with the status; the objects stored
/// before it stay on the PACS, which has no undo). The files are never changed.
std::vector<StoredObject> storeFiles(const PacsNode& node, const std::vector<std::filesystem::path>& files,
                                     AnonymizedObjects anonymized = AnonymizedObjects::Refuse,
                                     const Progress& progress = {});

/// "ORTHANC at 127.0.0.1:4242", with " (TLS)" on a TLS node (for messages; a stored text, core StoredText.h).
std::string describe(const PacsNode& node);

} // namespace vsim::dicom
