#pragma once

#include "vsim/dicom/PacsClient.h"

#include <QDialog>
#include <QFutureWatcher>

#include <memory>
#include <vector>

class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace vsim::gui {

/// File > Query/Retrieve (PACS): the PACS nodes (saved in the settings, PacsNodes.h; Echo tests one), the DICOM UID
/// root of the results sent back, a study-level C-FIND with filters (patient name with wildcards, patient ID, a date
/// range, modality) and the matching studies. Retrieve accepts the dialog with the chosen study; the main window
/// then fetches it (C-GET) and imports it in the background, with progress and Cancel in the status bar. Echo and
/// find run off the GUI thread, bounded by the node's timeout.
class PacsDialog : public QDialog
{
    Q_OBJECT
public:
    explicit PacsDialog(QWidget* parent = nullptr);
    ~PacsDialog() override;

    /// The node as the fields give it.
    dicom::PacsNode node() const;
    /// Fills the node's fields (as choosing a saved node does).
    void setNode(const QString& name, const dicom::PacsNode& node);
    /// Saves the node of the fields under its name (replacing a node of that name) and the UID root; false, with
    /// the reason in the status line, when the name is empty or the root invalid.
    bool saveNode();
    /// C-ECHO to the node in the background; echoFinished() when done (the status line says how it went).
    void echo();
    /// C-FIND with the filters in the background; searchFinished() when the table is filled.
    void search();
    void setFilters(const QString& patientName, const QString& patientId, const QString& dateFrom = {},
                    const QString& dateTo = {}, const QString& modality = {});
    bool isBusy() const;
    QTableWidget* results() const { return m_results; }
    QString statusText() const;
    /// The Study Instance UID of the selected row ("" when none).
    QString selectedStudyUid() const;
    /// The description of the selected row, for the task's title.
    QString selectedStudyLabel() const;

signals:
    void echoFinished();
    void searchFinished();

private:
    QWidget* createNodeBox();
    QWidget* createFilterBox();
    void fillSavedNodes(const QString& current);
    void chooseSaved(int index);
    void removeNode();
    void runInBackground(std::function<void()> work, std::function<void()> done);
    void showMatches();
    void updateButtons();

    QComboBox* m_saved = nullptr;
    QLineEdit* m_name = nullptr;
    QLineEdit* m_aeTitle = nullptr;
    QLineEdit* m_host = nullptr;
    QSpinBox* m_port = nullptr;
    QLineEdit* m_callingAeTitle = nullptr;
    QSpinBox* m_timeout = nullptr;
    QLineEdit* m_uidRoot = nullptr;
    QLineEdit* m_patientName = nullptr;
    QLineEdit* m_patientId = nullptr;
    QLineEdit* m_dateFrom = nullptr;
    QLineEdit* m_dateTo = nullptr;
    QComboBox* m_modality = nullptr;
    QPushButton* m_echo = nullptr;
    QPushButton* m_search = nullptr;
    QPushButton* m_retrieve = nullptr;
    QTableWidget* m_results = nullptr;
    QLabel* m_status = nullptr;
    QFutureWatcher<void> m_watcher;
    std::function<void()> m_done;
    std::shared_ptr<std::string> m_error = std::make_shared<std::string>();
    std::shared_ptr<std::vector<dicom::StudyMatch>> m_matches = std::make_shared<std::vector<dicom::StudyMatch>>();
};

} // namespace vsim::gui
