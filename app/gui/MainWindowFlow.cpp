// The blood-flow step of the workflow (Flow menu): SPH through the vessels of the newest centerlines in the task
// runner (progress and Cancel), the run added to the study (undoable) and played in the Run Player, the stenosis
// figures in the status bar, or why there are none.

#include "ArtifactCommands.h"
#include "MainWindow.h"
#include "ParameterForm.h"
#include "vsim/app/BloodFlowPipeline.h"
#include "vsim/app/RunRecord.h"
#include "vsim/core/Units.h"

#include <QMenu>
#include <QMenuBar>
#include <QStatusBar>

namespace vsim::gui {

void MainWindow::createFlowMenu()
{
    m_bloodFlowSetup = ParameterSet(app::bloodFlowSetupParameters());
    m_sphParameters = ParameterSet(sim::sph::sphParameters());
    QMenu* flow = menuBar()->addMenu(tr("F&low"));
    m_documentActions << flow->addAction(tr("Blood &Flow (SPH)"), this, [this] { simulateBloodFlow(); });
    m_documentActions << flow->addAction(tr("Blood Flow &Parameters..."), this, [this] {
        editParametersInDialog(this, tr("Blood flow parameters"),
                               {{tr("Inlet, outlets, figures"), &m_bloodFlowSetup}, {tr("SPH solver"), &m_sphParameters}});
    });
}

bool MainWindow::simulateBloodFlow()
{
    if (!m_document.hasStudy())
        return false;
    const std::string centerlinesId = m_document.study().newestArtifact(study::ArtifactKind::Skeleton, "centerline");
    if (centerlinesId.empty())
    {
        showError(tr("Blood flow"), tr("The vessel ends come from the centerlines: run Skeleton && Centerlines first."));
        return false;
    }
    app::BloodFlowSetup setup = app::bloodFlowSetupFrom(m_bloodFlowSetup, m_sphParameters);
    setup.centerlinesId = centerlinesId;
    auto flow = std::make_shared<app::BloodFlowRun>();
    return m_tasks.run(
        tr("Blood flow"),
        [this, setup, flow](const Progress& progress) { *flow = app::runBloodFlow(m_document.study(), setup, {}, progress); },
        [this, setup, flow, centerlinesId] {
            const app::BloodFlowArtifacts added = app::addBloodFlowRun(m_document.study(), *flow, setup, {centerlinesId});
            m_document.undoStack()->push(new AddedArtifactCommand(m_document, added.ids(), tr("Blood flow")));
            openRunPlayer(added.run);
            if (const std::string warning = app::runStatusWarning(flow->run.status); !warning.empty())
                showError(tr("Blood flow"), tr("Read these results with care: %1").arg(QString::fromStdString(warning)));
            else if (flow->stenosis)
                statusBar()->showMessage(
                    tr("Blood flow: peak velocity ratio %1 at %2 mm along the centerline (mean ratio %3), pressure drop %4 mmHg")
                        .arg(flow->stenosis->peakRatio, 0, 'f', 2)
                        .arg(flow->stenosis->distanceMm, 0, 'f', 0)
                        .arg(flow->stenosis->meanRatio, 0, 'f', 2)
                        .arg(units::paToMmHg(flow->stenosis->pressureDropPa), 0, 'f', 1),
                    10000);
            else
                statusBar()->showMessage(tr("Blood flow: no stenosis figures (%1)")
                                             .arg(QString::fromStdString(flow->warnings.empty() ? "" : flow->warnings.back())),
                                         10000);
        });
}

} // namespace vsim::gui
