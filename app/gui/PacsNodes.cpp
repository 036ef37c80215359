#include "PacsNodes.h"

#include "vsim/core/DicomUid.h"
#include "vsim/core/Error.h"
#include "vsim/core/StoredText.h"

#include <QSettings>
#include <QtGlobal>

namespace vsim::gui {
namespace {

constexpr const char* kNodes = "pacs/nodes";
constexpr const char* kUidRoot = "dicom/uid_root";

} // namespace

QList<PacsNodeEntry> loadPacsNodes()
{
    QSettings settings;
    QList<PacsNodeEntry> nodes;
    const int count = settings.beginReadArray(kNodes);
    for (int i = 0; i < count; ++i)
    {
        settings.setArrayIndex(i);
        PacsNodeEntry entry;
        entry.name = settings.value("name").toString();
        entry.node.calledAeTitle = settings.value("ae_title").toString().toStdString();
        entry.node.host = settings.value("host").toString().toStdString();
        entry.node.port = settings.value("port", 104).toInt();
        entry.node.callingAeTitle = settings.value("calling_ae_title", "VASCUSIM").toString().toStdString();
        entry.node.timeoutS = settings.value("timeout_s", 30).toInt();
        entry.node.tls.enabled = settings.value("tls", false).toBool();
        entry.node.tls.trustedCertificates = settings.value("tls_trusted_certificates").toString().toStdString();
        entry.node.tls.certificate = settings.value("tls_certificate").toString().toStdString();
        entry.node.tls.privateKey = settings.value("tls_private_key").toString().toStdString();
        nodes << entry;
    }
    settings.endArray();
    return nodes;
}

void savePacsNodes(const QList<PacsNodeEntry>& nodes)
{
    QSettings settings;
    settings.remove(kNodes);
    settings.beginWriteArray(kNodes, int(nodes.size()));
    for (int i = 0; i < nodes.size(); ++i)
    {
        settings.setArrayIndex(i);
        const PacsNodeEntry& entry = nodes[i];
        settings.setValue("name", entry.name);
        settings.setValue("ae_title", QString::fromStdString(entry.node.calledAeTitle));
        settings.setValue("host", QString::fromStdString(entry.node.host));
        settings.setValue("port", entry.node.port);
        settings.setValue("calling_ae_title", QString::fromStdString(entry.node.callingAeTitle));
        settings.setValue("timeout_s", entry.node.timeoutS);
        settings.setValue("tls", entry.node.tls.enabled); // the files' paths only: the keys stay where they are
        settings.setValue("tls_trusted_certificates", QString::fromStdString(entry.node.tls.trustedCertificates));
        settings.setValue("tls_certificate", QString::fromStdString(entry.node.tls.certificate));
        settings.setValue("tls_private_key", QString::fromStdString(entry.node.tls.privateKey));
    }
    settings.endArray();
}

QString nodeText(const dicom::PacsNode& node)
{
    return QString::fromStdString(storedTextForPeople(dicom::describe(node)));
}

QString savedUidRoot()
{
    return QSettings().value(kUidRoot).toString();
}

void saveUidRoot(const QString& root)
{
    setDicomUidRoot(root.trimmed().toStdString()); // throws for an invalid root: nothing saved then
    QSettings().setValue(kUidRoot, root.trimmed());
}

void applySavedUidRoot()
{
    try
    {
        setDicomUidRoot(savedUidRoot().toStdString());
    }
    catch (const Error& error)
    {
        qWarning("the saved DICOM UID root is not valid, UUID UIDs are used: %s", error.what());
    }
}

} // namespace vsim::gui
