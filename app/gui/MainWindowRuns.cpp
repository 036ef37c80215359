// The Run Player dock (issue 17): any Run artifact of the study played frame by frame in the 3D view: a wall run's
// surface coloured by a cell field, a drug run's tree coloured by a segment field. One player for every solver; the
// legend's range is the run's (fixed while playing) or each frame's.

#include "MainWindow.h"
#include "RunPlayer.h"
#include "ViewLayout.h"
#include "vsim/app/WallPipeline.h"
#include "vsim/viz/VolumeView3D.h"

#include <QDockWidget>
#include <QStatusBar>

#include <algorithm>
#include <limits>

namespace vsim::gui {
namespace {

/// The fields a frame can be coloured by: a tet mesh's cell fields, a network's segment fields, a grid's fields.
QStringList fieldsOf(const SimulationData& data)
{
    QStringList fields;
    auto add = [&](const auto& map) {
        for (const auto& entry : map)
            fields << QString::fromStdString(entry.first);
    };
    if (const auto* mesh = std::get_if<TetMesh>(&data))
        add(mesh->cellFields);
    else if (const auto* network = std::get_if<VesselNetwork>(&data))
        add(network->segmentFields);
    else
        add(std::get<GridFields>(data).fields);
    // The figures people look for first.
    for (const char* first : {"von_mises_kpa", "filled_fraction"})
        if (fields.removeAll(first) > 0)
            fields.prepend(first);
    return fields;
}

/// The values of `field` in a frame (empty when it has none).
std::vector<double> valuesOf(const SimulationData& data, const std::string& field)
{
    if (const auto* mesh = std::get_if<TetMesh>(&data))
    {
        const auto found = mesh->cellFields.find(field);
        return found == mesh->cellFields.end() ? std::vector<double>() : found->second;
    }
    if (const auto* network = std::get_if<VesselNetwork>(&data))
    {
        const auto found = network->segmentFields.find(field);
        return found == network->segmentFields.end() ? std::vector<double>() : found->second;
    }
    const auto& fields = std::get<GridFields>(data).fields;
    const auto found = fields.find(field);
    if (found == fields.end())
        return {};
    return std::vector<double>(found->second.data(), found->second.data() + found->second.size());
}

void widen(std::pair<double, double>& range, const std::vector<double>& values)
{
    for (double v : values)
        range.first = std::min(range.first, v), range.second = std::max(range.second, v);
}

} // namespace

bool MainWindow::openRunPlayer(const std::string& id)
{
    if (!m_document.hasStudy() || m_document.study().artifact(id).kind != study::ArtifactKind::Run)
        return false;
    auto run = std::make_shared<SolverRun>();
    return m_tasks.run(tr("Loading run"),
                       [this, id, run](const Progress&) { *run = m_document.study().loadRun(id); },
                       [this, id, run] {
                           if (!m_runPlayer)
                           {
                               m_runPlayer = new RunPlayer(this);
                               connect(m_runPlayer, &RunPlayer::frameChanged, this, [this] { drawRunFrame(); });
                               connect(m_runPlayer, &RunPlayer::appearanceChanged, this, [this] { drawRunFrame(); });
                               m_runDock = new QDockWidget(tr("Run Player"), this);
                               m_runDock->setObjectName("runPlayerDock");
                               m_runDock->setWidget(m_runPlayer);
                               addDockWidget(Qt::BottomDockWidgetArea, m_runDock);
                               connect(m_runDock, &QDockWidget::visibilityChanged, this, [this](bool visible) {
                                   if (!visible)
                                       closeRunPlayer();
                               });
                           }
                           m_playedRun = run;
                           m_playedRunId = id;
                           std::vector<double> positions;
                           for (const RunFrame& frame : run->frames)
                               positions.push_back(frame.position);
                           if (m_drugDock)
                               m_drugDock->hide();
                           m_runDock->setWindowTitle(
                               tr("Run Player: %1").arg(QString::fromStdString(m_document.study().artifact(id).name)));
                           m_runDock->show();
                           m_runPlayer->setFrames(positions, QString::fromStdString(run->axis.quantity),
                                                  QString::fromStdString(run->axis.unit),
                                                  run->frames.empty() ? QStringList() : fieldsOf(run->frames.front().data));
                           drawRunFrame();
                       });
}

void MainWindow::drawRunFrame()
{
    if (!m_playedRun || m_playedRun->frames.empty() || !m_runPlayer)
        return;
    const RunFrame& frame = m_playedRun->frames[std::size_t(m_runPlayer->frame())];
    const std::string field = m_runPlayer->field().toStdString();
    // The legend's range: over the whole run (so that colours compare between frames) or this frame's.
    std::pair<double, double> range{std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest()};
    if (m_runPlayer->rangePerFrame())
        widen(range, valuesOf(frame.data, field));
    else
        for (const RunFrame& each : m_playedRun->frames)
            widen(range, valuesOf(each.data, field));
    if (!(range.second >= range.first))
        range = {0.0, 1.0};
    if (range.second - range.first < 1e-12)
        range.second = range.first + 1e-6;
    const RunStatus& status = m_playedRun->status;
    QString title = QString::fromStdString(field) + ", " + m_runPlayer->frameText();
    if (!status.converged())
        title += tr(", NOT CONVERGED");
    else if (!status.complete())
        title += tr(", STOPPED EARLY");

    viz::VolumeView3D* view = m_views->volumeView();
    view->clearSurfaces();
    view->clearLines();
    view->clearFieldLines();
    view->setVolumeVisible(false);
    if (const auto* mesh = std::get_if<TetMesh>(&frame.data))
    {
        if (mesh->cellFields.count(field))
            view->showFieldSurface(app::frameSurface(*mesh, field), field, range.first, range.second, title);
    }
    else if (const auto* network = std::get_if<VesselNetwork>(&frame.data))
    {
        std::vector<std::vector<Eigen::Vector3d>> lines;
        std::vector<std::array<double, 2>> radii;
        for (const VesselNetwork::Segment& segment : network->segments)
        {
            lines.push_back(segment.pathMm.size() >= 2
                                ? segment.pathMm
                                : std::vector<Eigen::Vector3d>{network->nodes[std::size_t(segment.from)].positionMm,
                                                               network->nodes[std::size_t(segment.to)].positionMm});
            radii.push_back({segment.startRadiusMm, segment.endRadiusMm});
        }
        view->showFieldLines(lines, valuesOf(frame.data, field), range.first, range.second, 3.0, title, radii);
    }
    else
        statusBar()->showMessage(tr("Voxel-grid frames are not drawn here: open the run's series.pvd in ParaView"), 8000);
}

void MainWindow::closeRunPlayer()
{
    if (!m_playedRun)
        return;
    m_runPlayer->pause();
    m_playedRun.reset();
    m_playedRunId.clear();
    m_views->volumeView()->clearFieldLines();
    m_drawnScene.clear(); // the study's own 3D content again
    refreshScene();
}

} // namespace vsim::gui
