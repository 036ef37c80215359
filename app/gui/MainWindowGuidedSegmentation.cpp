// The guided segmentation in the workstation: the Segmentation Points dock (SegmentationPointsPanel), its points as
// markers on the three MPRs (placed with a click, dragged to move), and the run from points in the background with
// progress and Cancel; a re-run replaces the label of the run before (one undo step) while nothing uses that label.

#include "ArtifactCommands.h"
#include "MainWindow.h"
#include "SegmentationPointsPanel.h"
#include "ViewLayout.h"
#include "vsim/app/GuidedSegmentationRecord.h"
#include "vsim/app/SacRecord.h"
#include "vsim/viz/DecimalText.h"
#include "vsim/viz/SliceView.h"

#include <QDockWidget>
#include <QStatusBar>

namespace vsim::gui {
void MainWindow::createSegmentationPointsDock()
{
    m_pointsPanel = new SegmentationPointsPanel(this);
    m_pointsDock = new QDockWidget(tr("Segmentation Points"), this);
    m_pointsDock->setObjectName("segmentationPointsDock");
    m_pointsDock->setWidget(m_pointsPanel);
    addDockWidget(Qt::RightDockWidgetArea, m_pointsDock);
    m_pointsDock->hide();
    connect(m_pointsPanel, &SegmentationPointsPanel::pointsChanged, this, [this] {
        for (viz::SliceOrientation orientation : kOrientations)
            m_views->sliceView(orientation)->setMarkers(m_pointsPanel->markers());
    });
    connect(m_pointsPanel, &SegmentationPointsPanel::placingChanged, this,
            [this](SegmentationPointsPanel::Placing placing) {
                for (viz::SliceOrientation orientation : kOrientations)
                    m_views->sliceView(orientation)->setPlacing(placing != SegmentationPointsPanel::Placing::None);
            });
    connect(m_pointsPanel, &SegmentationPointsPanel::runRequested, this,
            [this] { segmentFromPoints(m_pointsPanel->request()); });
    for (viz::SliceOrientation orientation : kOrientations)
    {
        viz::SliceView* view = m_views->sliceView(orientation);
        connect(view, &viz::SliceView::pointPlaced, this, [this, orientation](const Eigen::Vector3d& point) {
            if (m_pointsPanel->placing() == SegmentationPointsPanel::Placing::Stop)
                m_pointsPanel->addStop(point, viz::screenAxes(orientation).normal()); // the view's plane
            else
                m_pointsPanel->addPoint(point, m_pointsPanel->placing() == SegmentationPointsPanel::Placing::Include);
            m_pointsPanel->setPlacing(SegmentationPointsPanel::Placing::None); // one click, one point (as Slicer)
        });
        connect(view, &viz::SliceView::markerMoved, this,
                [this](int id, const Eigen::Vector3d& point) { m_pointsPanel->movePoint(id, point); });
    }
}

void MainWindow::showSegmentationPoints()
{
    if (!m_document.hasStudy())
        return;
    // An empty panel starts from the points of the newest guided label (e.g. of a reopened study).
    if (m_pointsPanel->request().includeMm.empty() && m_pointsPanel->request().excludeMm.empty())
        for (const study::Artifact& artifact : m_document.study().artifacts())
            if (!artifact.damaged)
                if (const auto request = app::guidedRequestOf(artifact))
                    m_pointsPanel->setRequest(*request);
    m_pointsDock->show();
    m_pointsDock->raise();
}

bool MainWindow::segmentFromPoints(const imaging::SegmentationRequest& request)
{
    const std::string imageId = newestImageOrSay(tr("Segment from points"));
    if (imageId.empty())
        return false;
    if (request.includeMm.empty() && request.target != imaging::SegmentationTarget::Aorta)
    {
        showError(tr("Segment from points"),
                  tr("Place at least one include point inside the vessel (Place Include, then click in a slice view)."));
        return false;
    }
    struct Outcome
    {
        imaging::SegmentationResult segmentation;
        TriangleMesh surface;
    };
    auto outcome = std::make_shared<Outcome>();
    discardLabelEdits();
    return m_tasks.run(
        tr("Segment from points"),
        [this, imageId, request, outcome, parameters = m_guidedParameters](const Progress& progress) {
            const CtVolume ct = m_document.study().loadImage(imageId); // the study is not edited while a task runs
            outcome->segmentation = imaging::segmentFromPoints(ct, parameters, request, progress.subRange(0.0, 0.85));
            outcome->surface = displaySurface(outcome->segmentation.label, progress.subRange(0.85, 1.0));
        },
        [this, imageId, request, outcome, parameters = m_guidedParameters] {
            study::Study& study = m_document.study();
            const std::string previous = m_guidedLabelId;
            // A re-run replaces the label of the run before while it is the newest label and nothing uses it.
            const bool replaces = !previous.empty() && study.hasArtifact(previous) &&
                                  app::newestLumenLabel(study) == previous && isUnusedArtifact(study, previous);
            const std::string id =
                app::recordGuidedSegmentation(study, outcome->segmentation, request, parameters, imageId);
            m_guidedLabelId = id;
            m_scene.labels[id] = outcome->segmentation.label;
            m_scene.lumenSurfaces[id] = outcome->surface;
            m_document.undoStack()->beginMacro(tr("Segment from points"));
            if (replaces)
                m_document.undoStack()->push(new RemoveArtifactCommand(m_document, previous));
            m_document.undoStack()->push(new AddedArtifactCommand(m_document, id, tr("Segment from points")));
            m_document.undoStack()->endMacro();
            const auto& f = outcome->segmentation.figures;
            statusBar()->showMessage(tr("Segmented %1 ml (%2 leak(s) cut)%3")
                                         .arg(viz::decimalText(f.at("volume_ml"), 1))
                                         .arg(int(f.at("leaks_cut")))
                                         .arg(replaces ? tr(", replacing the label of the run before") : QString()),
                                     8000);
        });
}

} // namespace vsim::gui
