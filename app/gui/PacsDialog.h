#pragma once

#include "vsim/core/Progress.h"
#include "vsim/dicom/PacsClient.h"

#include <QDialog>

#include <functional>
#include <memory>

class QCheckBox;
class QComboBox;
class QGroupBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;
class QTreeWidget;
class QTreeWidgetItem;

namespace vsim::gui {

/// File > Query/Retrieve (PACS), as Horos's and Slicer's DICOM query/retrieve windows: the PACS nodes (saved in the
/// settings, PacsNodes.h; Echo tests one; DICOM TLS with the trusted certificates and ours), the DICOM UID root of
/// the results sent back, a C-FIND with filters (patient name with wildcards, patient ID, a date range, modality)
/// listing studies, or patients whose studies open below them; a study opens onto its series (a series-level
/// C-FIND when expanded). Retrieve accepts the dialog with the chosen study or series; the main window then fetches
/// it (C-GET) and imports it in the background, with progress and Cancel in the status bar. Echo and the queries
/// run off the GUI thread, one at a time; Cancel stops a query at its next answer (C-CANCEL) and gives the dialog
/// back at once (a node that does not answer is left to its timeout in the background).
class PacsDialog : public QDialog
{
    Q_OBJECT
public:
    /// What Search lists at the top of the tree.
    enum class Level
    {
        Studies,
        Patients
    };
    /// The kind of a row (Qt::UserRole of its column 0).
    enum class Row
    {
        Patient,
        Study,
        Series,
        Placeholder ///< "..." under a patient or study whose children are not loaded yet
    };

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
    /// C-FIND with the filters at the level chosen, in the background; searchFinished() when the tree is filled.
    void search();
    void setFilters(const QString& patientName, const QString& patientId, const QString& dateFrom = {},
                    const QString& dateTo = {}, const QString& modality = {});
    void setLevel(Level level);
    /// Loads the children of a patient (its studies, with the date and modality filters) or of a study (its
    /// series) in the background; childrenLoaded() when done. Expanding the row does this.
    void loadChildren(QTreeWidgetItem* item);
    /// Stops the running echo or query: the dialog is free at once, the status line says "Cancelled".
    void cancel();
    bool isBusy() const;
    QTreeWidget* results() const { return m_results; }
    QString statusText() const;
    /// The study or series of the selected row (a patient's row, or none: an empty study UID).
    dicom::RetrieveTarget selectedTarget() const;
    /// The description of the selected row, for the task's title.
    QString selectedLabel() const;

signals:
    void echoFinished();
    void searchFinished();
    void childrenLoaded();

private:
    struct Job;
    QWidget* createNodeBox();
    QGroupBox* createTlsBox(QWidget* parent);
    QWidget* createFilterBox();
    void fillSavedNodes(const QString& current);
    void chooseSaved(int index);
    void removeNode();
    /// Runs `work` off the GUI thread; `done` gets the error message ("" for success) unless cancelled.
    void runInBackground(std::function<void(const Progress&)> work, std::function<void(const QString& error)> done);
    dicom::StudyQuery studyQuery(const std::string& patientId) const;
    void updateButtons();

    QComboBox* m_saved = nullptr;
    QLineEdit* m_name = nullptr;
    QLineEdit* m_aeTitle = nullptr;
    QLineEdit* m_host = nullptr;
    QSpinBox* m_port = nullptr;
    QLineEdit* m_callingAeTitle = nullptr;
    QSpinBox* m_timeout = nullptr;
    QGroupBox* m_tls = nullptr;
    QLineEdit* m_trusted = nullptr;
    QLineEdit* m_certificate = nullptr;
    QLineEdit* m_privateKey = nullptr;
    QLineEdit* m_uidRoot = nullptr;
    QComboBox* m_level = nullptr;
    QLineEdit* m_patientName = nullptr;
    QLineEdit* m_patientId = nullptr;
    QLineEdit* m_dateFrom = nullptr;
    QLineEdit* m_dateTo = nullptr;
    QComboBox* m_modality = nullptr;
    QPushButton* m_echo = nullptr;
    QPushButton* m_search = nullptr;
    QPushButton* m_cancel = nullptr;
    QPushButton* m_retrieve = nullptr;
    QTreeWidget* m_results = nullptr;
    QLabel* m_status = nullptr;
    std::shared_ptr<Job> m_job; ///< the running one; null when idle
};

} // namespace vsim::gui
