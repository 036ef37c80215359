// The drug-delivery step of the workflow (Drug menu, Drug Delivery dock): the study's vessel network from the newest
// centerlines, a run from a catheter tip with an optional tumour and control points in the task runner, the solved
// network added to the study (undoable), and the dock with the next run's inputs, the figures, the outlets and the
// filling player.

#include "ArtifactCommands.h"
#include "DrugDeliveryPanel.h"
#include "MainWindow.h"
#include "ParameterForm.h"
#include "SegmentationPointsPanel.h"
#include "ViewLayout.h"
#include "vsim/app/NetworkPipeline.h"
#include "vsim/core/StoredText.h"
#include "vsim/core/Units.h"
#include "vsim/imaging/LesionGrowing.h"
#include "vsim/imaging/OrganGrowing.h"
#include "vsim/sim/network/NetworkBuild.h"
#include "vsim/viz/DecimalText.h"
#include "vsim/viz/SliceView.h"

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
    m_documentActions << drug->addAction(tr("&Liver from Points"), this, [this] { growLiverFromPoints(); });
    m_documentActions << drug->addAction(tr("&Tumour from Points"), this, [this] { growTumourFromPoints(); });
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
    if (!request.tumourLabel.isEmpty() && request.liverLabel.isEmpty())
    {
        showError(tr("Drug delivery"), tr("The tumour label is read with a liver label: choose the liver too."));
        return false;
    }
    if (!request.liverLabel.isEmpty())
        source["liver_label"] = request.liverLabel.toStdString();
    if (!request.tumourLabel.isEmpty())
        source["tumour_label"] = request.tumourLabel.toStdString();
    for (const auto& [key, text] : {std::pair{"inlet", request.inlet}, std::pair{"feeders_added", request.feedersAdded},
                                    std::pair{"feeders_removed", request.feedersRemoved}})
        if (!text.isEmpty())
            source[key] = text.toStdString();
    if (!(request.feedersAdded.isEmpty() && request.feedersRemoved.isEmpty()) && request.liverLabel.isEmpty())
    {
        showError(tr("Drug delivery"), tr("Feeders are corrected on a run with a liver label: choose the liver too."));
        return false;
    }
    m_drugRequest = request;
    auto run = std::make_shared<sim::network::NetworkRunResult>();
    auto warnings = std::make_shared<std::vector<std::string>>();
    const std::string labelId = app::labelOfCenterlines(m_document.study(), centerlinesId);
    return m_tasks.run(
        tr("Drug delivery"),
        [this, setup, centerlinesId, run, warnings, request, source](const Progress& progress) mutable {
            const study::Study& study = m_document.study();
            if (!request.liverLabel.isEmpty())
                setup.liver = app::sharedLabel(study, request.liverLabel.toStdString(), 0, "liver");
            if (!request.tumourLabel.isEmpty())
            {
                setup.tumourLabel = app::sharedLabel(study, request.tumourLabel.toStdString(), 0, "tumour");
                setup.tumour = app::volumeRegion(study, request.tumourLabel.toStdString(), 0);
            }
            setup.network = app::buildStudyNetwork(study, centerlinesId, *warnings, progress.subRange(0.0, 0.4));
            app::applyRecordedChoices(setup, source);
            *run = sim::network::runNetwork(setup, progress.subRange(0.4, 1.0));
            run->warnings.insert(run->warnings.begin(), warnings->begin(), warnings->end());
        },
        [this, run, centerlinesId, labelId, source] {
            std::vector<std::string> inputs{centerlinesId};
            if (!labelId.empty())
                inputs.push_back(labelId);
            // One drug run replaces the one before (made in this window) unless the user kept it or something uses it.
            study::Study& study = m_document.study();
            const app::NetworkRunIds previous = m_lastDrugRun;
            const bool replaces = !previous.network.empty() && study.hasArtifact(previous.network) &&
                                  study.hasArtifact(previous.run) && !(m_drugPanel && m_drugPanel->keepsRun()) &&
                                  isUnusedArtifact(study, previous.network) && isUnusedArtifact(study, previous.run);
            const app::NetworkRunIds ids = app::addNetworkRun(study, *run, m_networkParameters, inputs, source);
            m_lastDrugRun = ids;
            m_scene.networkRuns[ids.network] = run;
            m_scene.networkRequests[ids.network] = m_drugRequest;
            m_document.undoStack()->beginMacro(tr("Drug flow"));
            if (replaces)
                for (const std::string& id : {previous.network, previous.run})
                    m_document.undoStack()->push(new RemoveArtifactCommand(m_document, id));
            m_document.undoStack()->push(
                new AddedArtifactCommand(m_document, std::vector<std::string>{ids.run, ids.network}, tr("Drug flow")));
            m_document.undoStack()->endMacro();
            if (m_drugPanel)
                m_drugPanel->clearKeep();
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
    std::vector<std::pair<QString, QString>> labels;
    for (const study::Artifact& artifact : m_document.study().artifacts())
        if (artifact.kind == study::ArtifactKind::Label && !artifact.damaged)
            labels.emplace_back(QString::fromStdString(artifact.id),
                                QString::fromStdString(storedTextForPeople(artifact.name)));
    m_drugPanel->setLabelChoices(labels);
    m_drugPanel->setRequest(m_drugRequest);
    showTerritory(*run);
    m_drugPanel->setRun(run, int(m_networkParameters.get("filling_steps")));
    statusBar()->showMessage(tr("Drug delivery: %1 outlets, last reached after %2 s")
                                 .arg(run->twoPhase.orientation.outlets.size())
                                 .arg(viz::decimalText(run->filling.lastArrival, 1)),
                             8000);
}

bool MainWindow::growLiverFromPoints() { return growOrganFromPoints(false); }

bool MainWindow::growTumourFromPoints() { return growOrganFromPoints(true); }

bool MainWindow::growOrganFromPoints(bool tumour)
{
    if (!m_document.hasStudy())
        return false;
    const QString title = tumour ? tr("Tumour from points") : tr("Liver from points");
    const std::string imageId = newestArtifact(study::ArtifactKind::Image);
    const std::vector<Eigen::Vector3d> points =
        m_pointsPanel ? m_pointsPanel->request().includeMm : std::vector<Eigen::Vector3d>{};
    if (imageId.empty() || points.empty())
    {
        showError(title, tr("Place include points inside the %1 first (Vessels > Segment from Points, on the MPR "
                            "views), then grow it from them.")
                             .arg(tumour ? tr("tumour") : tr("liver")));
        return false;
    }
    // A tumour grows within the liver label chosen in the Drug Delivery dock (LesionGrowing.h).
    const std::string liverId = tumour ? (m_drugPanel ? m_drugPanel->request() : m_drugRequest).liverLabel.toStdString() : std::string();
    if (tumour && liverId.empty())
    {
        showError(title, tr("A tumour grows within the liver: choose the liver label in the Drug Delivery dock first "
                            "(or grow it: Drug > Liver from Points)."));
        return false;
    }
    auto grown = std::make_shared<imaging::OrganGrowing>();
    const ParameterSet parameters(tumour ? imaging::lesionGrowingParameters() : imaging::organGrowingParameters());
    return m_tasks.run(
        title,
        [this, imageId, liverId, points, grown, parameters](const Progress& progress) {
            const CtVolume ct = m_document.study().loadImage(imageId);
            if (liverId.empty())
            {
                *grown = imaging::growOrgan(ct, points, parameters, progress);
                return;
            }
            imaging::LesionGrowing lesion = imaging::growLesion(ct, points, m_document.study().loadLabel(liverId), parameters, progress);
            grown->label = std::move(lesion.label);
            grown->figures = lesion.figures;
            grown->warnings = lesion.warnings;
        },
        [this, imageId, liverId, points, grown, parameters, title] {
            const std::string organ = liverId.empty() ? storedText("liver") : storedText("tumour");
            study::Provenance provenance;
            provenance.command = "segment-organ";
            provenance.inputs = {imageId};
            if (!liverId.empty())
                provenance.inputs.push_back(liverId);
            provenance.parameters = parameters.valuesAsText();
            provenance.parameters["organ"] = organ;
            std::string text;
            for (const Eigen::Vector3d& p : points)
                text += (text.empty() ? "" : "; ") + std::to_string(p.x()) + "," + std::to_string(p.y()) + "," + std::to_string(p.z());
            provenance.parameters["points_mm"] = text;
            const std::string id = m_document.study().addLabel(
                grown->label,
                points.size() == 1 ? storedText(Pattern{"%1 (grown from one point)", {organ}})
                                   : storedText(Pattern{"%1 (grown from %2 points)", {organ, std::to_string(points.size())}}),
                provenance, grown->warnings);
            m_scene.labels[id] = grown->label;
            m_document.undoStack()->push(new AddedArtifactCommand(m_document, id, title));
            statusBar()->showMessage(tr("%1 grown from %2 point(s): %3 ml; choose it as the %4 label in the Drug "
                                        "Delivery dock")
                                         .arg(QString::fromStdString(storedTextForPeople(organ)))
                                         .arg(points.size())
                                         .arg(viz::decimalText(grown->figures.at("volume_ml"), 1))
                                         .arg(QString::fromStdString(storedTextForPeople(organ))),
                                     8000);
        });
}

void MainWindow::showTerritory(const sim::network::NetworkRunResult& run)
{
    if (!run.territories || !run.perfused)
        return;
    const LabelVolume territory = sim::network::territoryLabel(*run.territories, *run.perfused, run.lesions);
    std::vector<viz::SliceMarker> markers; // negative ids: not the guided segmentation's points (a drag moves nothing)
    const auto& tip = run.network.nodes[std::size_t(run.tipNode)].positionMm;
    markers.push_back({-1, tip, {0.2, 1.0, 0.3}, tr("tip").toStdString()});
    for (std::size_t l = 0; l < run.lesions.size() && l < sim::network::kLesionsReported; ++l)
        markers.push_back({-2 - int(l), run.lesions[l].centreMm, {1.0, 0.3, 0.2}, tr("lesion %1").arg(l + 1).toStdString()});
    for (const sim::network::Feeder& f : run.feeders)
        markers.push_back({-100 - f.segment, sim::network::segmentMiddle(run.network, f.segment), {1.0, 0.9, 0.2},
                           tr("feeder %1").arg(f.segment).toStdString()});
    for (viz::SliceOrientation orientation : kOrientations)
    {
        m_views->sliceView(orientation)->setLabel(territory, viz::SliceView::LabelPalette::Territory);
        m_views->sliceView(orientation)->setMarkers(markers);
    }
    if (run.coverage && !run.lesions.empty())
        statusBar()->showMessage(tr("Chemoembolization from the tip: coverage grade %1, territory %2 ml, %3 feeder(s)")
                                     .arg(QChar(run.coverage->grade))
                                     .arg(viz::decimalText(run.perfused->volumeMl, 1))
                                     .arg(run.feeders.size()),
                                 8000);
}

} // namespace vsim::gui
