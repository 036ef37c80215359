#pragma once

#include "DrugDeliveryPanel.h"
#include "ParameterForm.h"
#include "ReportExportDialog.h"
#include "SceneCache.h"
#include "StudyDocument.h"
#include "TaskRunner.h"
#include "ViewCapture.h"
#include "ViewState.h"
#include "WorkflowChecklist.h"
#include "vsim/app/NetworkPipeline.h"
#include "vsim/core/Hounsfield.h"
#include "vsim/core/ImageVolume.h"
#include "vsim/core/Parameters.h"
#include "vsim/core/RunStatus.h"
#include "vsim/core/SolverRun.h"
#include "vsim/core/TetMesh.h"
#include "vsim/core/TriangleMesh.h"
#include "vsim/dicom/DicomScan.h"
#include "vsim/dicom/PacsClient.h"
#include "vsim/imaging/GuidedSegmentation.h"
#include "vsim/viz/BrushMode.h"

#include <QMainWindow>

#include <Eigen/Core>

#include <functional>
#include <memory>
#include <optional>
#include <set>

class QComboBox;
class QDockWidget;
class QDoubleSpinBox;
class QLabel;
class QMenu;
class QProgressBar;
class QPushButton;
class QTableWidget;
class QToolBar;
class QTreeWidget;

namespace vsim::imaging {
struct VesselMeasurements;
}
namespace vsim::sim::network {
struct NetworkRunResult;
}

namespace vsim::gui {

class EndoscopePanel;
class HelpWindow;
class InteractiveWall;
class LinePlot;
class RunPlayer;
class LabelEditSession;
struct PacsSendRequest;
class SegmentationPointsPanel;
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
    /// Opens a study in this window, for writing; read-only when another program here writes it (the status bar
    /// says who); for a holder on another host the user chooses read-only or a confirmed break of its lock.
    bool openStudy(const QString& bundle);
    /// Creates an empty study at `bundle` and saves it.
    bool newStudy(const QString& bundle);
    /// Imports a NIfTI / NRRD / MetaImage file in the background and shows it; undoable.
    bool importVolume(const QString& file);
    /// Imports a mask (NIfTI / NRRD / MetaImage file, a DICOM SEG, or a slice of a DICOM mask series: its folder's
    /// series) as a label on the newest image's grid in the background
    /// (study::maskOnImageGrid: refused with a message when the grids do not match); undoable, shown in the MPRs.
    bool importLabel(const QString& file);
    /// Imports a DICOM series in the background (scanning `path` first unless `scan` is given) and shows it;
    /// `seriesKey` empty picks the CT with most slices. Undoable; progress and Cancel in the status bar.
    bool importDicom(const QString& path, const QString& seriesKey = {},
                     std::shared_ptr<const dicom::DicomScanResult> scan = {});
    /// Opens the Import DICOM dialog and imports what the user picks.
    void showDicomImportDialog();
    /// Opens File > Query/Retrieve (PACS); Retrieve runs retrieveFromPacs on the chosen study.
    void showPacsDialog();
    /// Fetches the study from the node (C-GET) into VascuSim's PACS folder, then imports its CT like importDicom; in
    /// the background with progress and Cancel (a cancelled or failed fetch leaves no files). False when refused
    /// (no study open, busy).
    bool retrieveFromPacs(const dicom::PacsNode& node, const dicom::RetrieveTarget& target, const QString& label = {});
    /// Opens File > Send to PACS; Send runs sendToPacs.
    void showPacsSendDialog();
    /// Writes the chosen report (Encapsulated PDF) and label (SEG) into VascuSim's outbox folder and stores them on
    /// the node (C-STORE) in the background, with progress and Cancel; the outbox files are removed afterwards.
    /// False when refused (no study open, nothing chosen, busy).
    bool sendToPacs(const PacsSendRequest& request);
    /// Runs a step of the workflow checklist as its menu entry does; false when refused (no study, busy, missing
    /// input: the message says which).
    bool runWorkflowStep(app::WorkflowStep step);

    /// Saves a PNG of `view` (the whole window when null) into the capture folder; its path, or "" (the error shown).
    QString saveScreenshot(QWidget* view);
    enum class MovieSource
    {
        Rotation,  ///< the 3D view turning once around (72 frames of 5 degrees)
        PlayedRun, ///< every frame of the run in the Run Player, as the 3D view shows it
    };
    /// Writes a movie into a new folder in the capture folder, with progress and Cancel.
    MovieResult saveMovie(MovieSource source);
    /// Where captures go: the folder chosen in View > Capture > Capture Folder, else "VascuSim captures" in the
    /// user's documents.
    QString captureFolder() const;

    /// Measures a drawing of a slice view (viz::SliceView::measurementDrawn) on the shown CT and adds it to the study
    /// as a measurement artifact, undoable; its id, or "" when refused (the message says why).
    std::string addMeasurement(const ViewMeasurement& drawn);
    /// The user guide (Help), at an anchor of it ("keys", "aaa", "tace", ...; empty: the top).
    HelpWindow* showHelp(const QString& section);
    /// The "3D + CPR" layout on the newest centerlines (false, with a message, without them).
    bool showVesselView();
    /// The virtual endoscope (Vessels > Virtual Endoscope) in its dock, inside the lumen of the label the newest
    /// centerlines were made from; its surface is made in the background when the scene has none. False, with a
    /// message, without centerlines.
    bool showEndoscope();
    EndoscopePanel* endoscope() const { return m_endoscope; }
    /// Marks a measurement artifact for the report's measurements section (undoable).
    void setMeasurementInReport(const std::string& id, bool inReport);
    /// Segments the vessels of the newest image in the background (segmentationParameters(); automatic seed
    /// unless `seedMm`), adds the label (undoable), overlays it in the MPRs and shows its surface in 3D.
    bool segmentVessels(const std::optional<Eigen::Vector3d>& seedMm = std::nullopt);
    /// The guided segmentation (Vessels > Segment from Points: the Segmentation Points dock) of the newest image in
    /// the background: the label is added (undoable), named after the target, with the request in its provenance;
    /// a re-run replaces the label of the panel's run before while that is the newest label and unused (one undo
    /// step). False without a study or image, without an include point (hepatic, all) or while a task runs.
    bool segmentFromPoints(const imaging::SegmentationRequest& request);
    /// Shows the Segmentation Points dock; an empty one starts from the points of the newest guided label.
    void showSegmentationPoints();
    SegmentationPointsPanel* segmentationPointsPanel() const { return m_pointsPanel; }
    /// Skeleton and centerlines of the newest vessel label in the background; both added (one undo step) and drawn
    /// over the lumen surface in the 3D view.
    bool extractSkeletonAndCenterlines();
    /// The AAA sac of the newest lumen label (outer contour, thrombus, assumed-thickness wall) in the background,
    /// added as an undoable label; its figures head the measurement dock with their definitions.
    bool measureSac();
    /// Builds the wall mesh (Wall > Build Wall Mesh) in the background; undoable.
    bool buildWallMesh();
    /// Runs a wall protocol ("physiological" or "thesis-rupture") on the newest wall; the last frame is added
    /// (undoable) and shown in 3D coloured by von Mises stress with a legend.
    bool simulateWall(const std::string& protocol);
    /// Starts the interactive wall protocol on the newest wall (Wall > Interactive Protocol): a dock with play /
    /// pause, the pressure slider and tearing; drag the wall in the 3D view. False without a wall.
    bool startInteractiveWall();
    void stopInteractiveWall();
    InteractiveWall* interactiveWall() const { return m_interactiveWall; }
    /// Runs the drug delivery from the newest centerlines in the background (Drug > Drug Delivery runs from the root;
    /// the Drug Delivery dock's Run with its tip, tumour and control points, typed or picked on the tree); the
    /// solved network is added (undoable) and shown: the tree coloured by drug flow in 3D, the dock with the figures,
    /// the outlets and the filling player. False without centerlines or for malformed input.
    bool simulateDrugDelivery(const DrugDeliveryRequest& request);
    /// Drug > Liver from Points: a liver label grown from the segmentation points panel's include points
    /// (imaging::growOrgan), added to the study (undoable). False (with a message) without points.
    bool growLiverFromPoints();
    /// Drug > Tumour from Points: a lesion grown from the include points within the dock's liver label.
    bool growTumourFromPoints();
    DrugDeliveryPanel* drugDeliveryPanel() const { return m_drugPanel; }
    /// Runs the blood flow (SPH) through the vessels of the newest centerlines in the background (Flow > Blood Flow)
    /// with the Flow > Blood Flow Parameters; the run is added (undoable) and played, its stenosis figures in the
    /// status bar. False without centerlines.
    bool simulateBloodFlow();
    /// Runs thesis scenario (a), the needle injection (app/InjectionPipeline.h), on the newest centerlines in the
    /// background (Flow > Needle Injection) with the Flow > Blood Flow Parameters' "Needle injection" page and the SPH
    /// solver's; the run is added (undoable) and played, the fill in the status bar.
    bool simulateNeedleInjection();
    /// Runs a smoke scenario ("ball-drop", "evh", "liver-ablation"; app/SmokePipeline.h) in the background (Flow >
    /// Surgical Smoke); the run is added (undoable) and played, the endoscope's obscuration times in the status bar.
    /// False without a study, or for evh without centerlines.
    bool simulateSmoke(const std::string& scenario);
    /// The parameters each smoke scenario runs with (Flow > Surgical Smoke > Smoke Parameters...).
    ParameterSet& smokeParameters(const std::string& scenario) { return m_smokeParameters.at(scenario); }
    ParameterSet& injectionSetup() { return m_injectionSetup; }
    /// Colours the played (else the newest) blood-flow run's wall loads (Flow > Wall Loads: field "tawss_pa", "osi" or
    /// "wall_pressure_pa") on the lumen surface in 3D, its legend on the left naming the field, the unit, the time
    /// window and the run's status; grey where the run has no value (past an open end). While the Run Player plays
    /// particles the surface stays, translucent, around them. False without a wall-loads surface or for another field.
    bool showWallLoads(const std::string& field);
    ParameterSet& bloodFlowSetup() { return m_bloodFlowSetup; }
    ParameterSet& sphParameters() { return m_sphParameters; }
    /// The SPH solver parameters the blood flow and the needle injection choose for the vessel (every one at first;
    /// Flow > Blood Flow Parameters' "Automatic" ticks); the others of sphParameters() are given as they stand.
    AutomaticParameters& sphAutomatic() { return m_sphAutomatic; }
    /// Loads Run artifact `id` in the background (double-click in the study tree) and plays it in the Run Player
    /// dock: each frame drawn in 3D coloured by the player's field, its legend naming the field, the frame, and the
    /// run's status when it did not converge or stopped early. False without a study or for another kind.
    bool openRunPlayer(const std::string& id);
    RunPlayer* runPlayer() const { return m_runPlayer; }
    /// The Run Player's plot: the played field's peak and median per frame, its cursor on the current frame.
    LinePlot* runPlot() const { return m_runPlot; }
    /// Writes the study's report in the background (File > Export Report): the PDF, and beside it the DICOM
    /// Encapsulated PDF and the metrics when asked; 3D snapshots are rendered on the GUI thread. False without a
    /// study, without a path, or while a task runs.
    bool exportReport(const ReportExportRequest& request);
    /// File > Export Report: the dialog, then exportReport().
    void showReportExportDialog();
    /// Opens a report artifact (double-click in the study tree) in the desktop's PDF viewer, from a copy in the
    /// temporary folder (the artifact may not be saved yet).
    void openReportArtifact(const std::string& id);
    ParameterSet& networkParameters() { return m_networkParameters; }
    ParameterSet& wallMeshParameters() { return m_wallMeshParameters; }
    ParameterSet& femParameters() { return m_femParameters; }
    /// The parameters the vessel steps use (Vessels > Parameters edits them; defaults from the declarations).
    ParameterSet& segmentationParameters() { return m_segmentationParameters; }
    ParameterSet& guidedSegmentationParameters() { return m_guidedParameters; }
    ParameterSet& skeletonParameters() { return m_skeletonParameters; }
    ParameterSet& centerlineParameters() { return m_centerlineParameters; }

    /// Starts correcting the newest vessel label with the brush (`brush` in every MPR, radius in mm); false
    /// without a label or while a task runs.
    bool startLabelEditing(viz::BrushMode brush = viz::BrushMode::Paint, double radiusMm = 3.0);
    /// The running edit session, or nullptr.
    LabelEditSession* labelEditSession() const { return m_labelEdit; }
    /// Adds the edited label as a new artifact (undoable; the original stays) and ends the session; false
    /// when there is no session or nothing was edited.
    bool applyLabelEdits();
    /// Ends the session without adding anything (its strokes stay in the undo history, harmless).
    void discardLabelEdits();
    /// Label Editing > Remove Island: erases the connected piece of the working label at the MPR cursor (one undo
    /// step); false without a session or with no labelled voxel within 3 mm.
    bool removeIslandAtCursor();
    /// The Measurements dock's table: one row per centerline (length, radii, diameters, stenosis) and a first row for
    /// the maximum diameter; clicking a row moves the MPR cursor to its narrowest (or widest) section.
    QTableWidget* measurementTable() const { return m_measurementTable; }
    /// Saves in the background; false if there is no study or a task is running.
    bool saveStudy();
    /// Saves to a new bundle in the background.
    bool saveStudyAs(const QString& bundle);
    /// Shows the image artifact `id` in the views.
    void showImageArtifact(const std::string& id);
    /// Shows or hides an artifact's picture (the study tree's check boxes); the views are redrawn.
    void setArtifactShown(const std::string& id, bool shown);
    bool isArtifactShown(const std::string& id) const;
    /// Shows this artifact in its role (a double-click in the study tree): newer ones of its kind and step are hidden.
    void showOnly(const std::string& id);
    /// The view state as it would be saved with the study now (hidden artifacts, cursor, window/level, camera).
    ViewState captureViewState() const;

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    /// Liver from Points and Tumour from Points: the organ window, or a lesion within the dock's liver label.
    bool growOrganFromPoints(bool tumour);
    /// Redraws the views from the study (MainWindowScene.cpp): after steps, undo, visibility changes, reopening.
    void refreshScene();
    /// Loads what the scene lacks in the background, then redraws (and applies a pending view state).
    void prepareScene(const SceneContent& content);
    void applyViewState(const ViewState& state);
    /// A study was opened or created: its saved view state and a fresh scene.
    void restoreScene();
    /// Puts the current view state into the study's metadata, to be saved with it.
    void keepViewStateInStudy();
    /// Write access when nobody holds the study's lock; otherwise as the header of openStudy() says. Throws
    /// vsim::Cancelled when the user cancels.
    study::Access askHowToOpenLockedStudy(const QString& bundle, bool& breakLock);
    /// Runs `add` (an import into the study); when it refuses values that are not HU, asks the user for the rescale
    /// and runs it again with it. Returns the new artifact's id, or "" (the error shown, or the user cancelled).
    std::string addWithRescaleIfAsked(const QString& title,
                                      const std::function<std::string(const std::optional<HounsfieldRescale>&)>& add);
    void createMenus();
    void createVesselMenu();
    void createMeasurementDock();
    void createSegmentationPointsDock();
    void createLabelEditToolBar();
    void createWallMenu();
    void createDrugMenu();
    void createFlowMenu();
    void createSmokeMenu(QMenu* flow);
    void createLayoutAndCaptureMenus(QMenu* view);
    /// View > Language: the system's, English, Deutsch, 简体中文 (Languages.h).
    void createLanguageMenu(QMenu* view);
    void createMeasureMenu();
    /// The study's shown measurement artifacts drawn in the slice views.
    void refreshViewMeasurements();
    void showDrugDeliveryRun(std::shared_ptr<const sim::network::NetworkRunResult> run);
    /// The player's current frame of the played run in the 3D view (MainWindowRuns.cpp).
    void drawRunFrame();
    /// A blood-flow run's velocities and pressures along the centerline (its time-averaged sections) under the Run
    /// Player's plot; hidden for other runs.
    void plotFlowAlongCenterline();
    void plotRunHistory();
    void closeRunPlayer();
    /// The wall-stress frame of run artifact `run` in the 3D view: its legend says when it did not converge, the
    /// sac's PWS and PWRI are called out.
    void showWallStress(const TetMesh& frame, const study::Artifact& run);
    void editVesselParameters();
    /// Overlays a label in the three MPRs (an empty one clears them).
    void showLabelOverlay(const LabelVolume& label);
    /// A drug run with a liver: its perfused territory over the MPR views (the territory palette), the tip, the
    /// lesions' centres and the feeders as markers, the coverage grade in the status bar.
    void showTerritory(const sim::network::NetworkRunResult& run);

    /// Fills the Measurements dock; each row keeps the patient position (mm) it jumps to.
    /// The measurement dock: one row per segment titled by its anatomical name (`names`, one per segment) of the
    /// centerlines `centerlinesId`; double-clicking a name renames the segment (undoable).
    void showMeasurements(const imaging::VesselMeasurements& measurements, const std::vector<std::string>& names,
                          const std::string& centerlinesId);
    /// The newest undamaged artifact of a kind, or an empty string.
    std::string newestArtifact(study::ArtifactKind kind) const;
    /// The newest image for a step; "" without a study, or (saying so to the user) without an image.
    std::string newestImageOrSay(const QString& step);
    void createDocks();
    void createStatusBar();
    void refreshArtifactTree();
    /// An artifact kind as the study tree names it, in the chosen language.
    static QString artifactKindText(study::ArtifactKind kind);
    void refreshTitle();
    /// Patient, study and series in the slice views' corner.
    void refreshPatientOverlay();
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
    std::string m_measuredCenterlines; // the centerlines the measurement dock shows
    WorkflowChecklist* m_workflow = nullptr;
    QProgressBar* m_progress = nullptr;
    QPushButton* m_cancel = nullptr;
    QLabel* m_statusText = nullptr;
    QMenu* m_recentMenu = nullptr;
    QList<QAction*> m_documentActions; // disabled while a task runs or without a study
    QAction* m_undoAction = nullptr;    // also disabled while a task runs: the task may be reading the study
    QAction* m_redoAction = nullptr;

    ParameterSet m_segmentationParameters;
    ParameterSet m_guidedParameters;
    SegmentationPointsPanel* m_pointsPanel = nullptr;
    QDockWidget* m_pointsDock = nullptr;
    std::string m_guidedLabelId; // the label of the panel's last run (replaced by a re-run)
    ParameterSet m_skeletonParameters;
    ParameterSet m_centerlineParameters;
    ParameterSet m_wallMeshParameters;
    ParameterSet m_femParameters;
    ParameterSet m_networkParameters;
    ParameterSet m_bloodFlowSetup, m_injectionSetup, m_sphParameters;
    AutomaticParameters m_sphAutomatic;
    std::map<std::string, ParameterSet> m_smokeParameters; ///< per scenario
    DrugDeliveryRequest m_drugRequest;
    app::NetworkRunIds m_lastDrugRun; ///< the drug run this window made last: the next replaces it unless kept
    DrugDeliveryPanel* m_drugPanel = nullptr;
    QDockWidget* m_drugDock = nullptr;
    InteractiveWall* m_interactiveWall = nullptr;
    QDockWidget* m_interactiveDock = nullptr;
    RunPlayer* m_runPlayer = nullptr;
    LinePlot* m_runPlot = nullptr;
    LinePlot *m_flowVelocityPlot = nullptr, *m_flowPressurePlot = nullptr; // a blood-flow run's sections
    QDockWidget* m_runDock = nullptr;
    std::shared_ptr<const SolverRun> m_playedRun; // the Run artifact the player plays, all its kept frames
    std::string m_playedRunId;
    std::pair<double, double> m_playedRange{0.0, 1.0}; // the played field's range over the run
    struct FieldSurface
    {
        TriangleMesh surface;
        std::string field;
        double low = 0.0, high = 1.0;
        QString title;
    };
    std::optional<FieldSurface> m_wallLoads; // drawn with the played particles (showWallLoads)
    SceneCache m_scene;
    std::string m_drawnScene; // what refreshScene() drew last (roles, completeness), not drawn twice
    std::set<std::string> m_hiddenArtifacts;
    QAction* m_measurementInReport = nullptr;
    bool m_vesselViewConnected = false;
    EndoscopePanel* m_endoscope = nullptr;
    QDockWidget* m_endoscopeDock = nullptr;
    HelpWindow* m_help = nullptr;
    std::optional<ViewState> m_pendingViewState; // applied once a reopened study's views are prepared
    LabelEditSession* m_labelEdit = nullptr;
    QToolBar* m_editToolBar = nullptr;
    QAction* m_paintAction = nullptr;
    QAction* m_eraseAction = nullptr;
    QDoubleSpinBox* m_brushRadius = nullptr;
    QAction* m_sphereAction = nullptr; // the 3D ball brush instead of the in-plane disc
    QComboBox* m_paintValue = nullptr;  // the label value painted: lumen 1, thrombus 4, wall 5
};

} // namespace vsim::gui
