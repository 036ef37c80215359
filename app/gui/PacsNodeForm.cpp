// PacsDialog's node form (PacsDialog.h): the called node's fields, its DICOM TLS files, our AE title and UID root,
// and the nodes saved in the settings (PacsNodes.h), chosen, saved and removed.

#include "PacsDialog.h"

#include "PacsNodes.h"
#include "vsim/core/Error.h"

#include <QComboBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRegularExpressionValidator>
#include <QSpinBox>
#include <QToolButton>

namespace vsim::gui {

QWidget* PacsDialog::createNodeBox()
{
    auto* box = new QGroupBox(tr("PACS node"), this);
    auto* form = new QFormLayout(box);
    m_saved = new QComboBox(box);
    connect(m_saved, &QComboBox::activated, this, &PacsDialog::chooseSaved);
    form->addRow(tr("Saved:"), m_saved);
    m_name = new QLineEdit(box);
    m_name->setPlaceholderText(tr("e.g. Radiology PACS"));
    form->addRow(tr("Name:"), m_name);
    const auto aeTitle = new QRegularExpressionValidator(QRegularExpression("[\\x20-\\x5b\\x5d-\\x7e]{1,16}"), box);
    m_aeTitle = new QLineEdit(box);
    m_aeTitle->setValidator(aeTitle);
    form->addRow(tr("AE title:"), m_aeTitle);
    m_host = new QLineEdit(box);
    form->addRow(tr("Host:"), m_host);
    m_port = new QSpinBox(box);
    m_port->setRange(1, 65535);
    m_port->setValue(104);
    form->addRow(tr("Port:"), m_port);
    m_callingAeTitle = new QLineEdit("VASCUSIM", box);
    m_callingAeTitle->setValidator(aeTitle);
    m_callingAeTitle->setToolTip(tr("Our AE title, as the PACS has it registered"));
    form->addRow(tr("Our AE title:"), m_callingAeTitle);
    m_timeout = new QSpinBox(box);
    m_timeout->setRange(1, 600);
    m_timeout->setValue(30);
    m_timeout->setSuffix(tr(" s"));
    form->addRow(tr("Timeout:"), m_timeout);
    form->addRow(createTlsBox(box));
    m_uidRoot = new QLineEdit(savedUidRoot(), box);
    m_uidRoot->setPlaceholderText(tr("empty: UUID-based UIDs (2.25...)"));
    m_uidRoot->setToolTip(tr("The organisation's DICOM UID root for the reports and segmentations VascuSim makes"));
    form->addRow(tr("UID root:"), m_uidRoot);
    auto* buttons = new QHBoxLayout;
    auto* save = new QPushButton(tr("Save"), box);
    auto* remove = new QPushButton(tr("Remove"), box);
    m_echo = new QPushButton(tr("Echo"), box);
    m_echo->setToolTip(tr("Test the connection (C-ECHO)"));
    buttons->addWidget(save);
    buttons->addWidget(remove);
    buttons->addStretch();
    buttons->addWidget(m_echo);
    form->addRow(buttons);
    connect(save, &QPushButton::clicked, this, &PacsDialog::saveNode);
    connect(remove, &QPushButton::clicked, this, &PacsDialog::removeNode);
    connect(m_echo, &QPushButton::clicked, this, &PacsDialog::echo);
    return box;
}

QGroupBox* PacsDialog::createTlsBox(QWidget* parent)
{
    m_tls = new QGroupBox(tr("DICOM TLS"), parent);
    m_tls->setCheckable(true);
    m_tls->setChecked(false);
    m_tls->setToolTip(tr("Encrypt the connection (DICOM TLS, BCP 195); the PACS must prove itself with a trusted "
                         "certificate"));
    auto* form = new QFormLayout(m_tls);
    const auto fileRow = [this, form](const QString& label, const QString& tip, const QString& filter) {
        auto* edit = new QLineEdit(m_tls);
        edit->setToolTip(tip);
        auto* browse = new QToolButton(m_tls);
        browse->setText(QStringLiteral("..."));
        connect(browse, &QToolButton::clicked, this, [this, edit, label, filter] {
            const QString file = QFileDialog::getOpenFileName(this, label, edit->text(), filter);
            if (!file.isEmpty())
                edit->setText(file);
        });
        auto* line = new QHBoxLayout;
        line->addWidget(edit, 1);
        line->addWidget(browse);
        form->addRow(label, line);
        return edit;
    };
    const QString pem = tr("PEM files (*.pem *.crt *.cer *.key);;All files (*)");
    m_trusted = fileRow(tr("Trusted certificates:"), tr("The PACS's certificate or its authority's (PEM)"), pem);
    m_certificate = fileRow(tr("Our certificate:"), tr("Ours, for a PACS that requires one (PEM; optional)"), pem);
    m_privateKey = fileRow(tr("Our private key:"), tr("The private key of our certificate (PEM, not encrypted)"), pem);
    return m_tls;
}

dicom::PacsNode PacsDialog::node() const
{
    dicom::PacsNode node;
    node.calledAeTitle = m_aeTitle->text().trimmed().toStdString();
    node.host = m_host->text().trimmed().toStdString();
    node.port = m_port->value();
    node.callingAeTitle = m_callingAeTitle->text().trimmed().toStdString();
    node.timeoutS = m_timeout->value();
    node.tls.enabled = m_tls->isChecked();
    node.tls.trustedCertificates = m_trusted->text().trimmed().toStdString();
    node.tls.certificate = m_certificate->text().trimmed().toStdString();
    node.tls.privateKey = m_privateKey->text().trimmed().toStdString();
    return node;
}

void PacsDialog::setNode(const QString& name, const dicom::PacsNode& node)
{
    m_name->setText(name);
    m_aeTitle->setText(QString::fromStdString(node.calledAeTitle));
    m_host->setText(QString::fromStdString(node.host));
    m_port->setValue(node.port);
    m_callingAeTitle->setText(QString::fromStdString(node.callingAeTitle));
    m_timeout->setValue(node.timeoutS);
    m_tls->setChecked(node.tls.enabled);
    m_trusted->setText(QString::fromStdString(node.tls.trustedCertificates));
    m_certificate->setText(QString::fromStdString(node.tls.certificate));
    m_privateKey->setText(QString::fromStdString(node.tls.privateKey));
}

void PacsDialog::fillSavedNodes(const QString& current)
{
    m_saved->clear();
    const QList<PacsNodeEntry> nodes = loadPacsNodes();
    for (const PacsNodeEntry& entry : nodes)
        m_saved->addItem(tr("%1 (%2)").arg(entry.name, nodeText(entry.node)), entry.name);
    const int index = std::max(0, m_saved->findData(current));
    if (!nodes.isEmpty())
    {
        m_saved->setCurrentIndex(index);
        chooseSaved(index);
    }
}

void PacsDialog::chooseSaved(int index)
{
    const QList<PacsNodeEntry> nodes = loadPacsNodes();
    if (index >= 0 && index < nodes.size())
        setNode(nodes[index].name, nodes[index].node);
}

bool PacsDialog::saveNode()
{
    const QString name = m_name->text().trimmed();
    if (name.isEmpty())
    {
        m_status->setText(tr("Give the node a name to save it."));
        return false;
    }
    try
    {
        saveUidRoot(m_uidRoot->text());
    }
    catch (const Error& error)
    {
        m_status->setText(tr("Not saved: %1").arg(QString::fromStdString(error.messageForPeople())));
        return false;
    }
    QList<PacsNodeEntry> nodes = loadPacsNodes();
    const auto same = std::find_if(nodes.begin(), nodes.end(), [&](const PacsNodeEntry& entry) { return entry.name == name; });
    if (same != nodes.end())
        same->node = node();
    else
        nodes << PacsNodeEntry{name, node()};
    savePacsNodes(nodes);
    fillSavedNodes(name);
    m_status->setText(tr("Saved %1.").arg(name));
    return true;
}

void PacsDialog::removeNode()
{
    QList<PacsNodeEntry> nodes = loadPacsNodes();
    const QString name = m_saved->currentData().toString();
    nodes.erase(std::remove_if(nodes.begin(), nodes.end(), [&](const PacsNodeEntry& entry) { return entry.name == name; }),
                nodes.end());
    savePacsNodes(nodes);
    fillSavedNodes({});
}

} // namespace vsim::gui
