// The drug-delivery step of the workflow (Drug menu, Drug Delivery dock): the study's vessel network from the newest
// centerlines, a run from a catheter tip with an optional tumour and control points in the task runner, the solved
// network added to the study (undoable), and the dock with the next run's inputs, the figures, the outlets and the
// filling player.

#include "ArtifactCommands.h"
#include "DrugDeliveryPanel.h"
#include "MainWindow.h"
#include "ParameterForm.h"
#include "ViewLayout.h"
#include "vsim/app/NetworkPipeline.h"
#include "vsim/core/Units.h"

#include <QDockWidget>
#include <QMenu>
#include <QMenuBar>
#include <QStatusBar>


namespace vsim::gui {

void MainWindow::createDrugMenu()
{
    m_networkParameters = ParameterSet(sim::network::networkParameters());
    QMenu* drug = menuBar()->addMenu(tr("&Drug"));
    m_documentActions << drug->addAction(tr("Drug &Delivery"), this, [this] {
        simulateDrugDelivery(m_drugPanel ? m_drugPanel->request() : m_drugRequest);
    });
    m_documentActions << drug->addAction(tr("Drug &Parameters..."), this, [this] {
        editParametersInDialog(this, tr("Drug delivery parameters"), {{tr("Drug delivery"), &m_networkParameters}});
    });
}

bool MainWindow::simulateDrugDelivery(const DrugDeliveryRequest& request)
{
    if (!m_document.hasStudy())
        return false;
    const std::string centerlinesId = m_document.study().newestArtifact(study::ArtifactKind::Skeleton, "centerline");
    if (centerlinesId.empty())
    {
        showError(tr("Drug delivery"), tr("The network needs centerlines: run Skeleton && Centerlines first."));
        return false;
    }
    sim::network::NetworkRunSetup setup;
    setup.parameters = m_networkParameters;
    std::map<std::string, std::string> source;
    const auto tip = numbersInText(request.tip, 3), tumour = numbersInText(request.tumour, 4);
    if (!tip || !tumour)
    {
        showError(tr("Drug delivery"), tr("The tip needs three numbers (mm) and the tumour four (centre and radius)."));
        return false;
    }
    if (!tip->empty())
        setup.tipPointMm = Eigen::Vector3d((*tip)[0], (*tip)[1], (*tip)[2]), source["tip"] = request.tip.toStdString();
    if (!tumour->empty())
    {
        if (!((*tumour)[3] > 0.0))
        {
            showError(tr("Drug delivery"), tr("The tumour's radius must be positive."));
            return false;
        }
        setup.tumour = sim::network::TumourSphere{Eigen::Vector3d((*tumour)[0], (*tumour)[1], (*tumour)[2]), (*tumour)[3]}.region();
        source["tumour_mm"] = request.tumour.toStdString();
    }
    for (const QString& point : request.controls.split(';', Qt::SkipEmptyParts))
    {
        const auto xyz = numbersInText(point, 3);
        if (!xyz || xyz->empty())
        {
            showError(tr("Drug delivery"), tr("Control points are x, y, z in mm, separated by ';'."));
            return false;
        }
        setup.controlPointsMm.emplace_back((*xyz)[0], (*xyz)[1], (*xyz)[2]);
    }
    if (!request.controls.trimmed().isEmpty())
        source["control_points"] = request.controls.toStdString(); // what a reopened study runs again
    m_drugRequest = request;
    auto run = std::make_shared<sim::network::NetworkRunResult>();
    auto warnings = std::make_shared<std::vector<std::string>>();
    const std::string labelId = app::labelOfCenterlines(m_document.study(), centerlinesId);
    return m_tasks.run(
        tr("Drug delivery"),
        [this, setup, centerlinesId, run, warnings](const Progress& progress) mutable {
            setup.network = app::buildStudyNetwork(m_document.study(), centerlinesId, *warnings, progress.subRange(0.0, 0.4));
            *run = sim::network::runNetwork(setup, progress.subRange(0.4, 1.0));
            run->warnings.insert(run->warnings.begin(), warnings->begin(), warnings->end());
        },
        [this, run, centerlinesId, labelId, source] {
            std::vector<std::string> inputs{centerlinesId};
            if (!labelId.empty())
                inputs.push_back(labelId);
            const app::NetworkRunIds ids = app::addNetworkRun(m_document.study(), *run, m_networkParameters, inputs, source);
            m_scene.networkRuns[ids.network] = run;
            m_scene.networkRequests[ids.network] = m_drugRequest;
            m_document.undoStack()->push(
                new AddedArtifactCommand(m_document, std::vector<std::string>{ids.run, ids.network}, tr("Drug flow")));
        });
}

void MainWindow::showDrugDeliveryRun(std::shared_ptr<const sim::network::NetworkRunResult> run)
{
    if (!m_drugPanel)
    {
        m_drugPanel = new DrugDeliveryPanel(m_views->volumeView(), this);
        m_drugPanel->setRequest(m_drugRequest);
        connect(m_drugPanel, &DrugDeliveryPanel::runRequested, this,
                [this](const DrugDeliveryRequest& request) { simulateDrugDelivery(request); });
        m_drugDock = new QDockWidget(tr("Drug Delivery"), this);
        m_drugDock->setObjectName("drugDeliveryDock");
        m_drugDock->setWidget(m_drugPanel);
        addDockWidget(Qt::RightDockWidgetArea, m_drugDock);
    }
    m_drugDock->show();
    m_drugPanel->setRequest(m_drugRequest);
    m_drugPanel->setRun(run, int(m_networkParameters.get("filling_steps")));
    statusBar()->showMessage(tr("Drug delivery: %1 outlets, last reached after %2 s")
                                 .arg(run->twoPhase.orientation.outlets.size())
                                 .arg(run->filling.lastArrival, 0, 'f', 1),
                             8000);
}

} // namespace vsim::gui
