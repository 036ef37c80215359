#pragma once

// File > Send to PACS: which saved node, and which of the open study's results go there: its newest report as a
// DICOM Encapsulated PDF and its newest label as a DICOM SEG, into the patient's study (C-STORE). A report made
// anonymized is not sent into the patient's study: the user chooses to leave it out or to send it as a new study.

#include "vsim/dicom/PacsClient.h"

#include <QDialog>

#include <string>

class QCheckBox;
class QComboBox;
class QPushButton;

namespace vsim::study {
class Study;
}

namespace vsim::gui {

struct PacsSendRequest
{
    QString nodeName;
    dicom::PacsNode node;
    std::string reportId; ///< "" : no report
    std::string labelId;  ///< "" : no label
    dicom::AnonymizedObjects anonymized = dicom::AnonymizedObjects::Refuse;
};

class PacsSendDialog : public QDialog
{
    Q_OBJECT
public:
    PacsSendDialog(const study::Study& study, QWidget* parent = nullptr);
    PacsSendRequest request() const;
    /// Chooses the saved node of that name (tests; the user picks it in the list).
    void chooseNode(const QString& name);

private:
    void updateButtons();

    QComboBox* m_node = nullptr;
    QCheckBox* m_report = nullptr;
    QCheckBox* m_label = nullptr;
    QComboBox* m_anonymized = nullptr;
    std::string m_reportId, m_labelId;
    QPushButton* m_send = nullptr;
};

} // namespace vsim::gui
