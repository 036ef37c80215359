// What the views show is worked out from the study, never left over from a step: refreshScene() draws the roles of
// sceneContent() (the newest shown label in the MPRs, the newest shown 3D content, the measurements) from the scene
// cache, after every step, undo, visibility change and on opening a study; what the cache lacks is loaded in the
// background first. The view state (hidden artifacts, cursor, window/level, fields of view, camera) is saved in the
// study and applied when it is opened again.

#include "MainWindow.h"
#include "SegmentationPointsPanel.h"
#include "vsim/app/SacRecord.h"
#include "vsim/app/SegmentNames.h"
#include "ViewLayout.h"
#include "ViewState.h"
#include "vsim/app/RunRecord.h"
#include "vsim/viz/SliceView.h"
#include "vsim/viz/VolumeView3D.h"

#include <QDockWidget>
#include <QSignalBlocker>
#include <QTableWidget>
#include <QTreeWidget>

namespace vsim::gui {
namespace {

constexpr viz::SliceOrientation kSliceOrientations[] = {viz::SliceOrientation::Axial, viz::SliceOrientation::Coronal,
                                                        viz::SliceOrientation::Sagittal};
const QColor kLumenColour(220, 60, 50);
const QColor kSkeletonColour(250, 210, 40);
const QColor kCenterlineColour(60, 220, 90);

} // namespace

void MainWindow::refreshScene()
{
    refreshViewMeasurements();
    if (!m_document.hasStudy())
        return;
    const SceneContent content = sceneContent(m_document.study(), m_hiddenArtifacts);
    const bool complete = m_scene.holds(content);
    if (!complete && !m_tasks.isBusy())
    {
        prepareScene(content);
        return; // drawn when the missing pieces are in
    }
    // Drawn already (a save, a rename): drawing again would reset what the user did since, e.g. the camera.
    const std::string drawn = content.image + "|" + content.label + "|" + content.skeleton + "|" + content.centerlines +
                              "|" + content.wallRun + "|" + content.networkRun + "|" + content.measuredCenterlines +
                              "|" + std::to_string(int(content.main)) + (complete ? "|complete" : "|partial");
    if (drawn == m_drawnScene)
        return;
    m_drawnScene = drawn;
    // The MPR overlay: the newest shown label (the label being edited stays while its session runs).
    if (!m_labelEdit)
    {
        const auto label = m_scene.labels.find(content.label);
        showLabelOverlay(label == m_scene.labels.end() ? LabelVolume() : label->second);
    }
    const auto measured = m_scene.measurements.find(content.measuredCenterlines);
    if (measured != m_scene.measurements.end())
    {
        const auto& study = m_document.study();
        showMeasurements(measured->second,
                         app::segmentNames(study, content.measuredCenterlines, study.loadSkeleton(content.measuredCenterlines)),
                         content.measuredCenterlines);
    }
    else if (!app::newestSacFigures(m_document.study()).empty())
        showMeasurements({}, {}, {}); // the sac's figures alone
    else
        m_measurementTable->setRowCount(0);
    if (m_interactiveWall)
        return; // the interactive protocol owns the 3D view until it is closed

    viz::VolumeView3D* view = m_views->volumeView();
    if (m_drugDock && content.main != SceneContent::Main::NetworkRun)
    {
        m_drugDock->hide();
        for (viz::SliceOrientation orientation : kOrientations) // the territory's markers (negative ids) go with it
        {
            std::vector<viz::SliceMarker> kept;
            for (const viz::SliceMarker& marker : m_views->sliceView(orientation)->markers())
                if (marker.id >= 0)
                    kept.push_back(marker);
            m_views->sliceView(orientation)->setMarkers(kept);
        }
    }
    if (content.main != SceneContent::Main::NetworkRun)
    {
        view->clearFieldLines();
        view->showTubelets({}, 1.0, QColor());
    }
    view->clearSurfaces();
    view->clearLines();
    view->setSurfaceOpacity(1.0);
    view->setVolumeStyle(viz::VolumeView3D::VolumeStyle::Rendered); // a drug run's tree sets its MIP
    bool volume = !content.image.empty();
    switch (content.main)
    {
    case SceneContent::Main::WallRun:
        if (const auto frame = m_scene.wallFrames.find(content.wallRun); frame != m_scene.wallFrames.end())
            showWallStress(frame->second, m_document.study().artifact(content.wallRun));
        volume = false;
        break;
    case SceneContent::Main::NetworkRun:
        if (const auto run = m_scene.networkRuns.find(content.networkRun); run != m_scene.networkRuns.end())
        {
            m_drugRequest = m_scene.networkRequests[content.networkRun];
            showDrugDeliveryRun(run->second);
        }
        break; // the tree over the CT's maximum intensity projection
    case SceneContent::Main::Vessels:
    {
        if (const auto surface = m_scene.lumenSurfaces.find(content.label); surface != m_scene.lumenSurfaces.end())
            view->addSurface(surface->second, kLumenColour);
        bool lines = false;
        for (const auto& [id, colour, width] : {std::tuple{content.skeleton, kSkeletonColour, 1.0},
                                                std::tuple{content.centerlines, kCenterlineColour, 3.0}})
            if (const auto graph = m_scene.skeletons.find(id); graph != m_scene.skeletons.end())
            {
                view->addLines(graph->second, colour, width);
                lines = true;
            }
        if (lines) // the lines run inside the lumen; the rendered contrast blood would hide them
        {
            view->setSurfaceOpacity(0.35);
            volume = false;
        }
        break;
    }
    case SceneContent::Main::Nothing: break;
    }
    view->setVolumeVisible(volume);
}

void MainWindow::prepareScene(const SceneContent& content)
{
    auto more = std::make_shared<SceneCache>();
    m_tasks.run(
        tr("Preparing the views"),
        [this, content, more, cache = m_scene](const Progress& progress) {
            *more = fillSceneCache(m_document.study(), content, cache, progress);
        },
        [this, more] {
            mergeSceneCache(m_scene, std::move(*more));
            refreshScene();
            if (m_pendingViewState)
            {
                applyViewState(*m_pendingViewState);
                m_pendingViewState.reset();
            }
        });
}

ViewState MainWindow::captureViewState() const
{
    ViewState state;
    state.hiddenArtifacts = m_hiddenArtifacts;
    const viz::SliceView* axial = m_views->sliceView(viz::SliceOrientation::Axial);
    if (axial->hasImage())
    {
        state.cursorMm = axial->cursor();
        state.windowLevel = axial->windowLevel();
        std::array<double, 3> fields{};
        std::array<Eigen::Vector3d, 3> centres;
        for (std::size_t i = 0; i < 3; ++i)
        {
            fields[i] = m_views->sliceView(kSliceOrientations[i])->fieldOfView();
            centres[i] = m_views->sliceView(kSliceOrientations[i])->viewCentre();
        }
        state.sliceFieldsOfViewMm = fields;
        state.sliceViewCentresMm = centres;
    }
    state.camera3d = m_views->volumeView()->cameraState();
    return state;
}

void MainWindow::applyViewState(const ViewState& state)
{
    if (state.windowLevel)
        m_views->applyWindowLevel(*state.windowLevel);
    for (std::size_t i = 0; i < 3; ++i)
    {
        viz::SliceView* slice = m_views->sliceView(kSliceOrientations[i]);
        if (!slice->hasImage())
            continue;
        if (state.sliceFieldsOfViewMm)
            slice->setFieldOfView((*state.sliceFieldsOfViewMm)[i]);
        if (state.cursorMm)
            slice->setCursor(*state.cursorMm);
        if (state.sliceViewCentresMm)
            slice->setViewCentre((*state.sliceViewCentresMm)[i]);
    }
    if (state.camera3d)
        m_views->volumeView()->setCameraState(*state.camera3d);
}

void MainWindow::setArtifactShown(const std::string& id, bool shown)
{
    if (shown == !m_hiddenArtifacts.count(id))
        return;
    shown ? void(m_hiddenArtifacts.erase(id)) : void(m_hiddenArtifacts.insert(id));
    const QSignalBlocker quiet(m_artifactTree); // the tree may be what called: its items stay, their boxes follow
    for (int i = 0; i < m_artifactTree->topLevelItemCount(); ++i)
        if (QTreeWidgetItem* item = m_artifactTree->topLevelItem(i); item->data(0, Qt::UserRole).toString().toStdString() == id)
            item->setCheckState(0, shown ? Qt::Checked : Qt::Unchecked);
    refreshScene();
}

void MainWindow::showOnly(const std::string& id)
{
    // The newest shown artifact of a role is drawn: hide the newer ones of the same kind and step, show this one.
    const study::Artifact& chosen = m_document.study().artifact(id);
    bool after = false;
    for (const study::Artifact& artifact : m_document.study().artifacts())
    {
        if (after && artifact.kind == chosen.kind && artifact.provenance.command == chosen.provenance.command)
            setArtifactShown(artifact.id, false);
        after = after || artifact.id == id;
    }
    setArtifactShown(id, true);
}

bool MainWindow::isArtifactShown(const std::string& id) const { return !m_hiddenArtifacts.count(id); }

void MainWindow::restoreScene()
{
    m_scene = SceneCache();
    m_drawnScene.clear();
    if (m_endoscopeDock)
        m_endoscopeDock->hide(); // inside the study before; Vessels > Virtual Endoscope enters this one's lumen
    m_guidedLabelId.clear(); // a new study starts without points; its guided label's points come back on request
    imaging::SegmentationRequest noPoints;
    noPoints.target = imaging::SegmentationTarget::Aorta;
    m_pointsPanel->setRequest(noPoints);
    const ViewState state = ViewState::fromJson(
        m_document.hasStudy() && m_document.study().metadata().count(kViewStateKey)
            ? m_document.study().metadata().at(kViewStateKey)
            : std::string());
    m_hiddenArtifacts = state.hiddenArtifacts;
    m_pendingViewState = state;
    refreshArtifactTree();
    refreshScene();
    if (m_pendingViewState && !m_tasks.isBusy()) // nothing to prepare: apply now
    {
        applyViewState(*m_pendingViewState);
        m_pendingViewState.reset();
    }
}

void MainWindow::keepViewStateInStudy()
{
    if (m_document.hasStudy() && !m_document.study().isReadOnly())
        m_document.study().setMetadata(kViewStateKey, captureViewState().toJson());
}

} // namespace vsim::gui
