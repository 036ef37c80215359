#pragma once

// The PACS nodes and the DICOM UID root as the workstation's settings keep them (QSettings "pacs/nodes",
// "dicom/uid_root"), as Horos's and Slicer's DICOM settings do: a name for people and the node's AE title, host, port,
// our AE title, timeout and DICOM TLS (whether, and the paths of the certificate files: never their contents).

#include "vsim/dicom/PacsClient.h"

#include <QList>
#include <QString>

namespace vsim::gui {

struct PacsNodeEntry
{
    QString name; ///< e.g. "Radiology PACS"
    dicom::PacsNode node;
};

/// The node as people read it ("ORTHANC auf 127.0.0.1:4242" in German).
QString nodeText(const dicom::PacsNode& node);

/// The saved nodes, in the order saved.
QList<PacsNodeEntry> loadPacsNodes();
/// Replaces the saved nodes.
void savePacsNodes(const QList<PacsNodeEntry>& nodes);

/// The organisation's DICOM UID root saved in the settings ("" = 2.25 UUID UIDs).
QString savedUidRoot();
/// Checks `root` (vsim::Error when invalid), applies it to this process (vsim/core/DicomUid.h) and saves it.
void saveUidRoot(const QString& root);
/// Applies the saved root at start; a saved root that is no longer valid is ignored (UUID UIDs), with a warning.
void applySavedUidRoot();

} // namespace vsim::gui
