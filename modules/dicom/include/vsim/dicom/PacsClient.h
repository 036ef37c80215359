#pragma once

// A DICOM network client for a PACS (issue 22; DCMTK dcmnet, PS3.4 / PS3.7): C-ECHO to test a node, C-FIND at the
// study level of the Study Root information model, C-GET of a study into a folder. Each call opens one association from our AE title to the node's
// and releases it. Failures come back as vsim::Error with what went wrong in words: the connection refused or not
// answered within the timeout, the association rejected (the node does not know our AE title, or its own is not
// the one configured), a response that is not success. Text in queries and answers is UTF-8 (ISO_IR 192).

#include "vsim/core/Progress.h"

#include <filesystem>
#include <string>
#include <vector>

namespace vsim::dicom {

/// A PACS node as the settings hold it.
struct PacsNode
{
    std::string calledAeTitle;               ///< the PACS's AE title (at most 16 characters)
    std::string host;                        ///< name or address
    int port = 104;
    std::string callingAeTitle = "VASCUSIM"; ///< ours
    int timeoutS = 30;                       ///< connection and each response (s)
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

/// Throws vsim::Error when the node cannot be reached, rejects us, or does not answer the echo with success.
void pacsEcho(const PacsNode& node);

/// The studies matching `query`, in the PACS's order. Throws vsim::Error as pacsEcho, and for a failed query.
std::vector<StudyMatch> findStudies(const PacsNode& node, const StudyQuery& query);

/// C-GET of every object of the study (CT, enhanced CT, SEG, encapsulated PDF, secondary capture) into `folder`
/// (created; it must be new or empty). Returns the files written. Throws vsim::Error as pacsEcho, and when the
/// PACS reports a failure, sends nothing, or the transfer breaks off; the files written so far are removed then
/// (nothing half retrieved is left).
std::vector<std::filesystem::path> retrieveStudy(const PacsNode& node, const std::string& studyInstanceUid,
                                                const std::filesystem::path& folder, const Progress& progress = {});

/// "ORTHANC at 127.0.0.1:4242" (for messages).
std::string describe(const PacsNode& node);

} // namespace vsim::dicom
