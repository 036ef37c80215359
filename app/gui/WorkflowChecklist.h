#pragma once

#include "vsim/app/WorkflowState.h"

#include <QListWidget>

namespace vsim::study {
class Study;
}

namespace vsim::gui {

/// The workflow dock as a checklist: one line per step (app::kWorkflowSteps) with its state drawn as a coloured
/// disc and said in words (done, stale: an input changed since, not run) and a tooltip of what the step does and
/// what it made; a single click asks for the step (stepClicked).
class WorkflowChecklist : public QListWidget
{
    Q_OBJECT
public:
    explicit WorkflowChecklist(QWidget* parent = nullptr);

    /// Reads the steps' states from `study` (none: every step not run).
    void refresh(const study::Study* study);
    app::StepState state(app::WorkflowStep step) const;
    QListWidgetItem* itemOf(app::WorkflowStep step) const { return item(int(step)); }
    /// The step's name as shown ("Skeleton & Centerlines").
    static QString stepName(app::WorkflowStep step);

signals:
    void stepClicked(app::WorkflowStep step);
};

} // namespace vsim::gui
