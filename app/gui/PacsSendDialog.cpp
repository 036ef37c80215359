#include "PacsSendDialog.h"

#include "PacsNodes.h"
#include "vsim/study/Study.h"
#include "vsim/core/StoredText.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>

namespace vsim::gui {

PacsSendDialog::PacsSendDialog(const study::Study& study, QWidget* parent) : QDialog(parent)
{
    setWindowTitle(tr("Send to PACS"));
    auto* form = new QFormLayout(this);
    m_node = new QComboBox(this);
    for (const PacsNodeEntry& entry : loadPacsNodes())
        m_node->addItem(tr("%1 (%2)").arg(entry.name, QString::fromStdString(storedTextForPeople(dicom::describe(entry.node)))),
                        entry.name);
    form->addRow(tr("PACS node:"), m_node);
    if (m_node->count() == 0)
        form->addRow(new QLabel(tr("No PACS node is saved: add one in File > Query/Retrieve (PACS)."), this));

    m_reportId = study.newestArtifact(study::ArtifactKind::Report);
    m_labelId = study.newestArtifact(study::ArtifactKind::Label);
    const auto artifactText = [&](const std::string& id, const QString& what) {
        if (id.empty())
            return tr("%1: none in the study").arg(what);
        const study::Artifact& artifact = study.artifact(id);
        return tr("%1: %2 (%3)").arg(what, QString::fromStdString(storedTextForPeople(artifact.name)),
                                        QString::fromStdString(artifact.provenance.time));
    };
    m_report = new QCheckBox(artifactText(m_reportId, tr("Newest report as a DICOM Encapsulated PDF")), this);
    m_label = new QCheckBox(artifactText(m_labelId, tr("Newest label as a DICOM SEG")), this);
    m_report->setChecked(!m_reportId.empty());
    m_report->setEnabled(!m_reportId.empty());
    m_label->setChecked(!m_labelId.empty());
    m_label->setEnabled(!m_labelId.empty());
    form->addRow(m_report);
    form->addRow(m_label);
    const bool anonymizedReport =
        !m_reportId.empty() && study.artifact(m_reportId).provenance.parameters.count("anonymized") != 0 &&
        study.artifact(m_reportId).provenance.parameters.at("anonymized") == "1";
    m_anonymized = new QComboBox(this);
    m_anonymized->addItem(tr("Do not send it (never into the patient's study)"), int(dicom::AnonymizedObjects::Refuse));
    m_anonymized->addItem(tr("Send it as a new anonymized study"), int(dicom::AnonymizedObjects::NewStudy));
    m_anonymized->setEnabled(anonymizedReport);
    form->addRow(tr("An anonymized report:"), m_anonymized);
    form->addRow(new QLabel(tr("The objects go into the patient's study, referencing the CT series, under the UID root "
                               "of Query/Retrieve."),
                            this));

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
    m_send = buttons->addButton(tr("Send"), QDialogButtonBox::AcceptRole);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    form->addRow(buttons);
    for (QCheckBox* box : {m_report, m_label})
        connect(box, &QCheckBox::toggled, this, &PacsSendDialog::updateButtons);
    updateButtons();
}

void PacsSendDialog::chooseNode(const QString& name)
{
    m_node->setCurrentIndex(m_node->findData(name));
    updateButtons();
}

PacsSendRequest PacsSendDialog::request() const
{
    PacsSendRequest request;
    request.nodeName = m_node->currentData().toString();
    for (const PacsNodeEntry& entry : loadPacsNodes())
        if (entry.name == request.nodeName)
            request.node = entry.node;
    request.reportId = m_report->isChecked() ? m_reportId : std::string();
    request.labelId = m_label->isChecked() ? m_labelId : std::string();
    request.anonymized = dicom::AnonymizedObjects(m_anonymized->currentData().toInt());
    return request;
}

void PacsSendDialog::updateButtons()
{
    m_send->setEnabled(m_node->currentIndex() >= 0 && (m_report->isChecked() || m_label->isChecked()));
}

} // namespace vsim::gui
