// The blood-flow step of the workflow (Flow menu): SPH through the vessels of the newest centerlines in the task
// runner (progress and Cancel), the run added to the study (undoable) and played in the Run Player, the stenosis
// figures in the status bar, or why there are none; Flow > Wall Loads colours the run's wall loads on the lumen surface.

#include "ArtifactCommands.h"
#include "MainWindow.h"
#include "ParameterForm.h"
#include "ViewLayout.h"
#include "vsim/app/BloodFlowPipeline.h"
#include "vsim/app/InjectionPipeline.h"
#include "vsim/app/RunRecord.h"
#include "vsim/core/StoredText.h"
#include "vsim/core/Units.h"
#include "vsim/viz/DecimalText.h"
#include "vsim/viz/VolumeView3D.h"

#include <QMenu>
#include <QMenuBar>
#include <QStatusBar>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <variant>

namespace vsim::gui {

void MainWindow::createFlowMenu()
{
    m_bloodFlowSetup = ParameterSet(app::bloodFlowSetupParameters());
    m_injectionSetup = ParameterSet(app::injectionSetupParameters());
    m_sphParameters = ParameterSet(sim::sph::sphParameters());
    for (const auto* chosen : {&app::bloodFlowChosenParameters(), &app::injectionChosenParameters()})
        for (const std::string& key : *chosen)
            if (m_sphAutomatic.ticked.insert(key).second)
                m_sphAutomatic.keys.push_back(key);
    QMenu* flow = menuBar()->addMenu(tr("F&low"));
    m_documentActions << flow->addAction(tr("Blood &Flow (SPH)"), this, [this] { simulateBloodFlow(); });
    m_documentActions << flow->addAction(tr("Needle &Injection (SPH, Thesis Scenario a)"), this,
                                         [this] { simulateNeedleInjection(); });
    QMenu* loads = flow->addMenu(tr("&Wall Loads"));
    m_documentActions << loads->menuAction();
    loads->addAction(tr("Time-Averaged Wall &Shear Stress"), this, [this] { showWallLoads("tawss_pa"); });
    loads->addAction(tr("&Oscillatory Shear Index"), this, [this] { showWallLoads("osi"); });
    loads->addAction(tr("Mean Wall &Pressure"), this, [this] { showWallLoads("wall_pressure_pa"); });
    createSmokeMenu(flow);
    m_documentActions << flow->addAction(tr("Blood Flow &Parameters..."), this, [this] {
        editParametersInDialog(this, tr("Blood flow parameters"),
                               {{tr("Inlet, outlets, figures"), &m_bloodFlowSetup},
                                {tr("Needle injection"), &m_injectionSetup},
                                {tr("SPH solver"), &m_sphParameters, &m_sphAutomatic}});
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
    app::BloodFlowSetup setup = app::bloodFlowSetupFrom(m_bloodFlowSetup, m_sphParameters, m_sphAutomatic.ticked);
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
                        .arg(viz::decimalText(flow->stenosis->peakRatio, 2))
                        .arg(viz::decimalText(flow->stenosis->distanceMm, 0))
                        .arg(viz::decimalText(flow->stenosis->meanRatio, 2))
                        .arg(viz::decimalText(units::paToMmHg(flow->stenosis->pressureDropPa), 1)),
                    10000);
            else
                statusBar()->showMessage(tr("Blood flow: no stenosis figures (%1)")
                                             .arg(QString::fromStdString(
                                                 flow->warnings.empty() ? "" : storedTextForPeople(flow->warnings.back()))),
                                         10000);
        });
}

bool MainWindow::simulateNeedleInjection()
{
    if (!m_document.hasStudy())
        return false;
    const std::string centerlinesId = m_document.study().newestArtifact(study::ArtifactKind::Skeleton, "centerline");
    if (centerlinesId.empty())
    {
        showError(tr("Needle injection"), tr("The vessel ends come from the centerlines: run Skeleton && Centerlines first."));
        return false;
    }
    app::InjectionSetup setup = app::injectionSetupFrom(m_injectionSetup, m_sphParameters, m_sphAutomatic.ticked);
    setup.centerlinesId = centerlinesId;
    auto injection = std::make_shared<app::InjectionRun>();
    return m_tasks.run(
        tr("Needle injection"),
        [this, setup, injection](const Progress& progress)
        { *injection = app::runInjection(m_document.study(), setup, {}, progress); },
        [this, setup, injection]
        {
            const std::string id = app::addInjectionRun(m_document.study(), *injection, setup);
            m_document.undoStack()->push(new AddedArtifactCommand(m_document, {id}, tr("Needle injection")));
            openRunPlayer(id);
            if (const std::string warning = app::runStatusWarning(injection->run.status); !warning.empty())
                showError(tr("Needle injection"), tr("Read these results with care: %1").arg(QString::fromStdString(warning)));
            else if (!injection->fill.empty())
                statusBar()->showMessage(tr("Needle injection: %1 ml in the vessel, %2 ml collected in the box at %3 s")
                                             .arg(viz::significantText(injection->fill.back().inVesselMl, 3))
                                             .arg(viz::significantText(injection->fill.back().collectedMl, 3))
                                             .arg(viz::decimalText(injection->fill.back().timeS, 3)),
                                         10000);
        });
}

bool MainWindow::showWallLoads(const std::string& field)
{
    static const std::map<std::string, QString> names{
        {"tawss_pa", tr("TAWSS (Pa)")}, {"osi", tr("OSI (0-0.5)")}, {"wall_pressure_pa", tr("mean wall pressure (Pa)")}};
    if (!m_document.hasStudy() || !names.count(field))
        return false;
    const study::Study& study = m_document.study();
    // The played run's wall loads, else the newest run's.
    std::string id = study.newestArtifact(study::ArtifactKind::Surface, "simulate sph");
    for (const study::Artifact& a : study.artifacts())
        if (a.kind == study::ArtifactKind::Surface && a.provenance.command == "simulate sph" && !m_playedRunId.empty() &&
            std::count(a.provenance.inputs.begin(), a.provenance.inputs.end(), m_playedRunId))
            id = a.id;
    if (id.empty())
    {
        showError(tr("Wall loads"), tr("No wall loads yet: run Flow > Blood Flow (SPH) long enough to reach its "
                                       "averaging window."));
        return false;
    }
    FieldSurface shown{study.loadSurface(id), field, 0.0, 1.0, names.at(field)};
    double low = std::numeric_limits<double>::max(), high = std::numeric_limits<double>::lowest();
    for (double v : shown.surface.pointFields.at(field))
        if (std::isfinite(v))
            low = std::min(low, v), high = std::max(high, v);
    if (!(high >= low))
        low = 0.0, high = 1.0;
    shown.low = field == "wall_pressure_pa" ? low : 0.0; // stresses and the index from 0, pressures as they are
    shown.high = std::max(high, shown.low + 1e-6);
    // The run it was averaged in: its status goes into the title, as on every figure of it.
    const study::Artifact& surface = study.artifact(id);
    if (!surface.provenance.inputs.empty() && study.hasArtifact(surface.provenance.inputs.front()))
    {
        const RunStatus status = app::runStatusOf(study.artifact(surface.provenance.inputs.front()));
        if (!status.converged())
            shown.title += tr(", NOT CONVERGED");
        else if (!status.complete())
            shown.title += tr(", STOPPED EARLY");
    }
    const auto& parameters = surface.provenance.parameters;
    const auto from = parameters.find("averaged_from_s"), over = parameters.find("averaged_over_s");
    if (from != parameters.end() && over != parameters.end())
    {
        const double start = std::atof(from->second.c_str()), length = std::atof(over->second.c_str());
        shown.title += tr(", averaged over %1-%2 ms")
            .arg(viz::decimalText(1e3 * start, 1))
            .arg(viz::decimalText(1e3 * (start + length), 1));
    }
    else
        shown.title += tr(", time-averaged");
    shown.title += tr("; grey: no value");
    statusBar()->clearMessage(); // an earlier "Wall loads failed" (none yet) no longer holds
    viz::VolumeView3D* view = m_views->volumeView();
    if (m_playedRun && !m_playedRun->frames.empty() &&
        std::holds_alternative<ParticleSet>(m_playedRun->frames.front().data))
    {
        m_wallLoads = std::move(shown);
        drawRunFrame();
        return true;
    }
    view->clearSurfaces();
    view->clearLines();
    view->setVolumeVisible(false);
    view->showFieldSurface(shown.surface, field, shown.low, shown.high, shown.title);
    return true;
}

} // namespace vsim::gui
