// Manual correction of the vessel label: the label overlay in the MPRs, the brush tool bar (Paint / Erase /
// radius / Sphere / the value painted / Remove Island / Apply / Discard), one undo step per stroke, and the edited label added as a new artifact.

#include "ArtifactCommands.h"
#include "LabelEditSession.h"
#include "MainWindow.h"
#include "ViewLayout.h"
#include "vsim/mesh/VesselSurface.h"
#include "vsim/viz/SliceView.h"
#include "vsim/viz/VolumeView3D.h"

#include <QActionGroup>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QStatusBar>
#include <QToolBar>

namespace vsim::gui {
void MainWindow::createLabelEditToolBar()
{
    m_editToolBar = addToolBar(tr("Label Editing"));
    m_editToolBar->setObjectName("labelEditToolBar");
    auto* modes = new QActionGroup(this);
    m_paintAction = m_editToolBar->addAction(tr("Paint"));
    m_eraseAction = m_editToolBar->addAction(tr("Erase"));
    for (QAction* action : {m_paintAction, m_eraseAction})
    {
        action->setCheckable(true);
        modes->addAction(action);
    }
    m_paintAction->setToolTip(tr("Paint vessel voxels with the left button in any MPR view (one undo step per stroke)"));
    m_eraseAction->setToolTip(tr("Erase vessel voxels with the left button in any MPR view"));
    m_editToolBar->addWidget(new QLabel(tr(" Radius "), this));
    m_brushRadius = new QDoubleSpinBox(this);
    m_brushRadius->setObjectName("brushRadius");
    m_brushRadius->setRange(0.5, 25.0);
    m_brushRadius->setValue(3.0);
    m_brushRadius->setSuffix(" mm");
    m_editToolBar->addWidget(m_brushRadius);
    m_sphereAction = m_editToolBar->addAction(tr("Sphere"));
    m_sphereAction->setCheckable(true);
    m_sphereAction->setToolTip(tr("3D brush: paint or erase a ball of the radius through the slices, not a disc in the "
                                  "view's plane"));
    m_editToolBar->addWidget(new QLabel(tr(" Paint as "), this));
    m_paintValue = new QComboBox(this);
    m_paintValue->setObjectName("paintValue");
    // The label values of the AAA sac (imaging::AneurysmSac): lumen 1, thrombus 4, wall 5.
    m_paintValue->addItem(tr("Lumen"), 1);
    m_paintValue->addItem(tr("Thrombus"), 4);
    m_paintValue->addItem(tr("Wall"), 5);
    m_paintValue->setToolTip(tr("The label value the brush paints: the lumen, or the thrombus and wall of an AAA sac label"));
    m_editToolBar->addWidget(m_paintValue);
    QAction* island = m_editToolBar->addAction(tr("Remove Island"), this, [this] { removeIslandAtCursor(); });
    island->setToolTip(tr("Remove the connected piece of the label at the cursor (click it in an MPR view first)"));
    QAction* apply = m_editToolBar->addAction(tr("Apply Edits"), this, [this] { applyLabelEdits(); });
    m_editToolBar->addAction(tr("Discard Edits"), this, [this] { discardLabelEdits(); });
    apply->setToolTip(tr("Add the edited label to the study as a new artifact (the original stays)"));
    m_editToolBar->hide();

    auto applyBrush = [this] {
        const viz::BrushMode mode = m_eraseAction->isChecked() ? viz::BrushMode::Erase : viz::BrushMode::Paint;
        for (viz::SliceOrientation orientation : kOrientations)
            m_views->sliceView(orientation)->setBrush(m_labelEdit ? mode : viz::BrushMode::Off, m_brushRadius->value());
    };
    connect(modes, &QActionGroup::triggered, this, applyBrush);
    connect(m_brushRadius, &QDoubleSpinBox::valueChanged, this, applyBrush);

    for (viz::SliceOrientation orientation : kOrientations)
    {
        viz::SliceView* view = m_views->sliceView(orientation);
        connect(view, &viz::SliceView::brushDab, this, [this, view](const Eigen::Vector3d& centre, const Eigen::Vector3d& normal) {
            if (!m_labelEdit)
                return;
            const bool erase = view->brush() == viz::BrushMode::Erase;
            m_labelEdit->dab(centre, normal, view->brushRadius(),
                             erase ? std::uint8_t(0) : std::uint8_t(m_paintValue->currentData().toInt()),
                             m_sphereAction->isChecked());
        });
        connect(view, &viz::SliceView::brushStrokeFinished, this, [this] {
            if (!m_labelEdit)
                return;
            if (QUndoCommand* stroke = m_labelEdit->finishStroke())
                m_document.undoStack()->push(stroke);
            statusBar()->showMessage(tr("Label edits: %1 voxels painted, %2 erased")
                                         .arg(m_labelEdit->paintedVoxels())
                                         .arg(m_labelEdit->erasedVoxels()),
                                     5000);
        });
    }
}

void MainWindow::showLabelOverlay(const LabelVolume& label)
{
    for (viz::SliceOrientation orientation : kOrientations)
        m_views->sliceView(orientation)->setLabel(label);
}

bool MainWindow::startLabelEditing(viz::BrushMode brush, double radiusMm)
{
    if (!m_document.hasStudy() || m_tasks.isBusy())
        return false;
    const std::string labelId = newestArtifact(study::ArtifactKind::Label);
    if (labelId.empty())
    {
        showError(tr("Edit label"), tr("The study has no vessel label: segment the vessels first."));
        return false;
    }
    LabelVolume source;
    try
    {
        source = m_document.study().loadLabel(labelId);
    }
    catch (const std::exception& error)
    {
        showError(tr("Edit label"), QString::fromStdString(textForPeople(error)));
        return false;
    }
    discardLabelEdits();
    m_labelEdit = new LabelEditSession(labelId, source, this);
    m_drawnScene.clear(); // the session overlays its working copy: the study's scene is drawn again after it
    connect(m_labelEdit, &LabelEditSession::labelChanged, this, [this] {
        for (viz::SliceOrientation orientation : kOrientations)
            m_views->sliceView(orientation)->refreshLabel();
    });
    showLabelOverlay(m_labelEdit->label());
    (brush == viz::BrushMode::Erase ? m_eraseAction : m_paintAction)->setChecked(true);
    m_brushRadius->setValue(radiusMm);
    for (viz::SliceOrientation orientation : kOrientations)
        m_views->sliceView(orientation)->setBrush(brush == viz::BrushMode::Off ? viz::BrushMode::Paint : brush, radiusMm);
    m_editToolBar->show();
    return true;
}

bool MainWindow::removeIslandAtCursor()
{
    if (!m_labelEdit)
        return false;
    const Eigen::Vector3d cursor = m_views->sliceView(viz::SliceOrientation::Axial)->cursor();
    QUndoCommand* island = m_labelEdit->removeIsland(cursor);
    if (!island)
    {
        statusBar()->showMessage(tr("No labelled voxel within 3 mm of the cursor"), 5000);
        return false;
    }
    m_document.undoStack()->push(island);
    statusBar()->showMessage(tr("Island removed: %1 voxels erased in all").arg(m_labelEdit->erasedVoxels()), 5000);
    return true;
}

void MainWindow::discardLabelEdits()
{
    if (!m_labelEdit)
        return;
    m_labelEdit->deleteLater();
    m_labelEdit = nullptr;
    for (viz::SliceOrientation orientation : kOrientations)
        m_views->sliceView(orientation)->setBrush(viz::BrushMode::Off, m_brushRadius->value());
    m_editToolBar->hide();
    refreshScene(); // the overlay shows the study's label again
}

bool MainWindow::applyLabelEdits()
{
    if (!m_labelEdit || !m_labelEdit->hasEdits() || !m_document.hasStudy() || m_tasks.isBusy())
        return false;
    study::Provenance provenance;
    provenance.command = "edit-label";
    provenance.inputs = {m_labelEdit->sourceId()};
    provenance.parameters["painted_voxels"] = std::to_string(m_labelEdit->paintedVoxels());
    provenance.parameters["erased_voxels"] = std::to_string(m_labelEdit->erasedVoxels());
    const LabelVolume edited = m_labelEdit->label().clone();
    std::string name = m_document.study().artifact(m_labelEdit->sourceId()).name;
    if (name.size() < 9 || name.compare(name.size() - 9, 9, " (edited)") != 0)
        name += " (edited)";
    const std::string id = m_document.study().addLabel(edited, name, provenance);
    m_scene.labels[id] = edited;
    m_labelEdit->deleteLater();
    m_labelEdit = nullptr;
    for (viz::SliceOrientation orientation : kOrientations)
        m_views->sliceView(orientation)->setBrush(viz::BrushMode::Off, m_brushRadius->value());
    m_editToolBar->hide();
    m_document.undoStack()->push(new AddedArtifactCommand(m_document, id, tr("Apply label edits"))); // redraws
    return true;
}

} // namespace vsim::gui
