// Flow > Surgical Smoke (issue 21): a scenario (the thesis's ball drop, endoscopic vessel harvesting around the
// study's vessel, liver ablation over its liver label or a box phantom) run in the background with progress and
// Cancel (app/SmokePipeline.h), the run added to the study (undoable) and played in the Run Player, the endoscope's
// obscuration times in the status bar. The scenes are illustrative; each scenario's parameters (its own defaults)
// are edited in Smoke Parameters... (a page per scenario), as `vascusim-cli simulate smoke --param` sets them. The
// GPU runs it when one is present (the backend `auto`).

#include "ArtifactCommands.h"
#include "MainWindow.h"
#include "ParameterForm.h"
#include "vsim/app/RunRecord.h"
#include "vsim/app/SmokePipeline.h"
#include "vsim/viz/DecimalText.h"

#include <QMenu>
#include <QStatusBar>

#include <memory>

namespace vsim::gui {

void MainWindow::createSmokeMenu(QMenu* flow)
{
    QMenu* smoke = flow->addMenu(tr("Surgical &Smoke (Illustrative)"));
    smoke->setObjectName("smokeMenu");
    m_documentActions << smoke->menuAction();
    smoke->addAction(tr("&Ball Drop (Thesis Demo)"), this, [this] { simulateSmoke("ball-drop"); });
    smoke->addAction(tr("&Endoscopic Vessel Harvesting"), this, [this] { simulateSmoke("evh"); });
    smoke->addAction(tr("&Liver Ablation with Suction"), this, [this] { simulateSmoke("liver-ablation"); });
    for (const std::string& scenario : sim::smoke::smokeScenarios())
        m_smokeParameters.emplace(scenario, ParameterSet(sim::smoke::smokeParameters(scenario)));
    smoke->addSeparator();
    smoke->addAction(tr("Smoke &Parameters..."), this, [this] {
        editParametersInDialog(this, tr("Surgical smoke parameters"),
                               {{tr("Ball drop"), &m_smokeParameters.at("ball-drop")},
                                {tr("Vessel harvesting"), &m_smokeParameters.at("evh")},
                                {tr("Liver ablation"), &m_smokeParameters.at("liver-ablation")}});
    });
}

bool MainWindow::simulateSmoke(const std::string& scenario)
{
    if (!m_document.hasStudy())
        return false;
    if (scenario == "evh" && m_document.study().newestArtifact(study::ArtifactKind::Skeleton, "centerline").empty())
    {
        showError(tr("Surgical smoke"), tr("The EVH tunnel is drawn around a vessel's centerline: run Skeleton && "
                                           "Centerlines first."));
        return false;
    }
    app::SmokeSetup setup = app::smokeSetup(scenario);
    setup.parameters = m_smokeParameters.at(scenario);
    auto run = std::make_shared<app::SmokeRun>();
    return m_tasks.run(
        tr("Surgical smoke"), [this, setup, run](const Progress& progress) { *run = app::runSmoke(m_document.study(), setup, progress); },
        [this, run]
        {
            const std::string id = app::addSmokeRun(m_document.study(), *run);
            m_document.undoStack()->push(new AddedArtifactCommand(m_document, {id}, tr("Surgical smoke")));
            openRunPlayer(id);
            if (const std::string warning = app::runStatusWarning(run->run.status); !warning.empty())
            {
                showError(tr("Surgical smoke"), tr("Read these results with care: %1").arg(QString::fromStdString(warning)));
                return;
            }
            const auto metric = [&](const char* key) {
                const auto found = run->run.metrics.find(key);
                return found == run->run.metrics.end() ? -1.0 : found->second;
            };
            const auto when = [&](double seconds) {
                return seconds < 0.0 ? tr("not reached") : tr("after %1 s").arg(viz::decimalText(seconds, 1));
            };
            statusBar()->showMessage(tr("Surgical smoke (illustrative): the endoscope's view 50 % obscured %1, 90 % %2; "
                                        "at most %3 % obscured")
                                         .arg(when(metric("time_to_50_percent_obscuration_s")))
                                         .arg(when(metric("time_to_90_percent_obscuration_s")))
                                         .arg(viz::decimalText(100.0 * metric("peak_obscured_fraction"), 0)),
                                     10000);
        });
}

} // namespace vsim::gui
