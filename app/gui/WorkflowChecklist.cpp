#include "WorkflowChecklist.h"

#include "vsim/study/Study.h"
#include "vsim/core/StoredText.h"

#include <QPainter>
#include <QPixmap>

namespace vsim::gui {
namespace {

constexpr int kStateRole = Qt::UserRole + 1;

QString stepHelp(app::WorkflowStep step)
{
    switch (step)
    {
    case app::WorkflowStep::Import: return WorkflowChecklist::tr("Import a CT angiography series (DICOM folder or volume file).");
    case app::WorkflowStep::Segment: return WorkflowChecklist::tr("Segment the contrast-filled vessel lumen (automatic seed).");
    case app::WorkflowStep::Centerlines: return WorkflowChecklist::tr("Skeleton (VDSM) and centerlines of the lumen, with diameters in mm.");
    case app::WorkflowStep::WallMesh: return WorkflowChecklist::tr("Tetrahedral wall mesh around the lumen (wall and thrombus thickness in mm).");
    case app::WorkflowStep::WallStress: return WorkflowChecklist::tr("Wall stress (kPa) at physiological blood pressure, converged or marked so.");
    case app::WorkflowStep::Flow: return WorkflowChecklist::tr("Blood flow (SPH): velocity ratios and wall pressure along the centerline.");
    case app::WorkflowStep::Drug: return WorkflowChecklist::tr("Drug delivery: perfused territory, tumour coverage and feeders for the catheter tip of the Drug Delivery dock.");
    case app::WorkflowStep::Smoke: return WorkflowChecklist::tr("Surgical smoke (illustrative): the liver-ablation scene with its suction and the endoscope's obscuration over time; Flow > Surgical Smoke has the other scenes.");
    case app::WorkflowStep::Report: return WorkflowChecklist::tr("Export the PDF report of the study's results.");
    }
    return {};
}

QIcon stateIcon(app::StepState state)
{
    QPixmap pixmap(14, 14);
    pixmap.fill(Qt::transparent);
    QPainter painter(&pixmap);
    painter.setRenderHint(QPainter::Antialiasing);
    const QColor colour = state == app::StepState::Done    ? QColor(60, 170, 75)
                          : state == app::StepState::Stale ? QColor(230, 150, 30)
                                                           : QColor(150, 150, 150);
    painter.setPen(colour.darker(130));
    painter.setBrush(state == app::StepState::NotRun ? Qt::NoBrush : QBrush(colour));
    painter.drawEllipse(QRectF(1.5, 1.5, 11, 11));
    return QIcon(pixmap);
}

} // namespace

WorkflowChecklist::WorkflowChecklist(QWidget* parent) : QListWidget(parent)
{
    setObjectName("workflow");
    for (app::WorkflowStep step : app::kWorkflowSteps)
    {
        auto* line = new QListWidgetItem(stepName(step), this);
        line->setData(Qt::UserRole, int(step));
    }
    connect(this, &QListWidget::itemClicked, this, [this](QListWidgetItem* line) {
        emit stepClicked(app::WorkflowStep(line->data(Qt::UserRole).toInt()));
    });
    refresh(nullptr);
}

QString WorkflowChecklist::stepName(app::WorkflowStep step)
{
    switch (step)
    {
    case app::WorkflowStep::Import: return tr("Import");
    case app::WorkflowStep::Segment: return tr("Segment", "verb: segment the vessels");
    case app::WorkflowStep::Centerlines: return tr("Skeleton & Centerlines");
    case app::WorkflowStep::WallMesh: return tr("Wall Mesh");
    case app::WorkflowStep::WallStress: return tr("Wall Stress");
    case app::WorkflowStep::Flow: return tr("Blood Flow");
    case app::WorkflowStep::Drug: return tr("Drug Delivery");
    case app::WorkflowStep::Smoke: return tr("Surgical Smoke");
    case app::WorkflowStep::Report: return tr("Report");
    }
    return {};
}

void WorkflowChecklist::refresh(const study::Study* study)
{
    for (app::WorkflowStep step : app::kWorkflowSteps)
    {
        const app::StepStatus status = study ? app::stepStatus(*study, step) : app::StepStatus{};
        const auto name = [&](const std::string& id) {
            return study && study->hasArtifact(id) ? QString::fromStdString(storedTextForPeople(study->artifact(id).name))
                                                   : QString::fromStdString(id);
        };
        QString state;
        switch (status.state)
        {
        case app::StepState::NotRun: state = tr("not run"); break;
        case app::StepState::Done: state = tr("done: %1").arg(name(status.artifactId)); break;
        case app::StepState::Stale:
            state = tr("stale: %1 was made from %2, which %3 has replaced since; run the step again")
                        .arg(name(status.artifactId), name(status.supersededInput), name(status.supersededBy));
            break;
        }
        QListWidgetItem* line = itemOf(step);
        const QString word = status.state == app::StepState::Done    ? tr("done")
                             : status.state == app::StepState::Stale ? tr("stale")
                                                                     : QString();
        line->setText(word.isEmpty() ? stepName(step) : tr("%1  (%2)").arg(stepName(step), word));
        line->setIcon(stateIcon(status.state));
        line->setData(kStateRole, int(status.state));
        line->setToolTip(stepHelp(step) + "\n" + tr("State: %1").arg(state) + "\n" + tr("Click to run."));
    }
}

app::StepState WorkflowChecklist::state(app::WorkflowStep step) const
{
    return app::StepState(itemOf(step)->data(kStateRole).toInt());
}

} // namespace vsim::gui
