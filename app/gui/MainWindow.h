#pragma once

#include "StudyDocument.h"
#include "TaskRunner.h"
#include "vsim/dicom/DicomScan.h"

#include <QMainWindow>

#include <Eigen/Core>

#include <memory>
#include <optional>

class QLabel;
class QListWidget;
class QMenu;
class QProgressBar;
class QPushButton;
class QTableWidget;
class QTreeWidget;

namespace vsim::imaging {
struct VesselMeasurements;
}

namespace vsim::gui {

class ViewLayout;

/// One study per window (document-oriented): artifact tree, workflow dock, 4-up views, status bar with progress
/// and Cancel for background tasks. File New / Open / Save / Save As / Recent / Import volume, Edit Undo / Redo,
/// View presets, Help / About. Errors are shown in non-blocking message boxes; the window stays usable.
class MainWindow : public QMainWindow
{
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    StudyDocument& document() { return m_document; }
    ViewLayout* views() const { return m_views; }
    TaskRunner& tasks() { return m_tasks; }

    /// Opens a bundle in the background (checksums, then the first image); false if a task is running.
    bool openStudy(const QString& bundle);
    /// Creates an empty study at `bundle` and saves it.
    bool newStudy(const QString& bundle);
    /// Imports a NIfTI / NRRD / MetaImage file in the background and shows it; undoable.
    bool importVolume(const QString& file);
    /// Imports a DICOM series in the background (scanning `path` first unless `scan` is given) and shows it;
    /// `seriesKey` empty picks the CT with most slices. Undoable; progress and Cancel in the status bar.
    bool importDicom(const QString& path, const QString& seriesKey = {},
                     std::shared_ptr<const dicom::DicomScanResult> scan = {});
    /// Opens the Import DICOM dialog and imports what the user picks.
    void showDicomImportDialog();
    /// Segments the vessels of the newest image in the background (default parameters; automatic seed unless
    /// `seedMm`), adds the label (undoable) and shows its lumen surface in the 3D view.
    bool segmentVessels(const std::optional<Eigen::Vector3d>& seedMm = std::nullopt);
    /// Skeleton and centerlines of the newest vessel label in the background; both added (one undo step).
    bool extractSkeletonAndCenterlines();
    /// The Measurements dock's table: one row per centerline (length, radii, diameters, stenosis) and a first row for
    /// the maximum diameter; clicking a row moves the MPR cursor to its narrowest (or widest) section.
    QTableWidget* measurementTable() const { return m_measurementTable; }
    /// Saves in the background; false if there is no study or a task is running.
    bool saveStudy();
    /// Saves to a new bundle in the background.
    bool saveStudyAs(const QString& bundle);
    /// Shows the image artifact `id` in the views.
    void showImageArtifact(const std::string& id);

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    void createMenus();
    void createVesselMenu();
    void createMeasurementDock();
    /// Fills the Measurements dock; each row keeps the patient position (mm) it jumps to.
    void showMeasurements(const imaging::VesselMeasurements& measurements);
    /// The newest undamaged artifact of a kind, or an empty string.
    std::string newestArtifact(study::ArtifactKind kind) const;
    void createDocks();
    void createStatusBar();
    void refreshArtifactTree();
    void refreshTitle();
    void rememberRecent(const QString& bundle);
    void rebuildRecentMenu();
    void showError(const QString& title, const QString& message);
    void showAbout();
    void setBusy(bool busy);
    /// A window for a new document: this one when it holds none, else a new window.
    MainWindow* windowForNewDocument();

    StudyDocument m_document;
    TaskRunner m_tasks;
    ViewLayout* m_views = nullptr;
    QTreeWidget* m_artifactTree = nullptr;
    QTableWidget* m_measurementTable = nullptr;
    QListWidget* m_workflow = nullptr;
    QProgressBar* m_progress = nullptr;
    QPushButton* m_cancel = nullptr;
    QLabel* m_statusText = nullptr;
    QMenu* m_recentMenu = nullptr;
    QList<QAction*> m_documentActions; // disabled while a task runs or without a study
    QAction* m_undoAction = nullptr;    // also disabled while a task runs: the task may be reading the study
    QAction* m_redoAction = nullptr;
};

} // namespace vsim::gui
