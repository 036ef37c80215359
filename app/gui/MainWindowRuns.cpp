// The Run Player dock (issue 17): any Run artifact of the study played frame by frame. Every view follows the frame:
// the 3D view colours a wall run's surface by a cell field, a drug run's tree by a segment field or a blood-flow
// run's particles by a particle field; the three slice views show the frame cut by their planes (a grid's too, and
// the particles within the slice's thickness); the dock's plot draws the field's peak and median over the run with a
// cursor on the frame (a click in it scrubs). One player for every solver; the legend's range is the run's (fixed
// while playing) or each frame's.

#include "EndoscopePanel.h"
#include "LinePlot.h"
#include "MainWindow.h"
#include "RunPlayer.h"
#include "ViewLayout.h"
#include "vsim/app/BloodFlowPipeline.h"
#include "vsim/app/WallPipeline.h"
#include "vsim/viz/SliceView.h"
#include "vsim/viz/VolumeView3D.h"
#include "vsim/core/StoredText.h"

#include <QCoreApplication>
#include <QDockWidget>
#include <QVBoxLayout>
#include <QStatusBar>

#include <algorithm>
#include <limits>

namespace vsim::gui {
namespace {

/// A run's axis ("time", "pressure": stored in English) in the reader's language.
QString axisQuantityText(const std::string& quantity)
{
    if (quantity == "time")
        return QCoreApplication::translate("vsim::gui::RunPlayer", "time");
    if (quantity == "pressure")
        return QCoreApplication::translate("vsim::gui::RunPlayer", "pressure");
    return QString::fromStdString(quantity);
}

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
    else if (const auto* particles = std::get_if<ParticleSet>(&data))
        add(particles->fields);
    else
        add(std::get<GridFields>(data).fields);
    // The figures people look for first.
    for (const char* first : {"von_mises_kpa", "filled_fraction", "speed_m_s"})
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
    if (const auto* particles = std::get_if<ParticleSet>(&data))
    {
        const auto found = particles->fields.find(field);
        return found == particles->fields.end() ? std::vector<double>() : found->second;
    }
    const auto& fields = std::get<GridFields>(data).fields;
    const auto found = fields.find(field);
    if (found == fields.end())
        return {};
    return std::vector<double>(found->second.data(), found->second.data() + found->second.size());
}

double median(std::vector<double> values)
{
    if (values.empty())
        return std::numeric_limits<double>::quiet_NaN();
    const auto middle = values.begin() + std::ptrdiff_t(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

constexpr viz::SliceOrientation kSliceOrientations[] = {viz::SliceOrientation::Axial, viz::SliceOrientation::Coronal,
                                                        viz::SliceOrientation::Sagittal};

/// The frame as the views show it: a particle frame's blood alone (its wall particles, field "wall" 1, are the
/// vessel's boundary, not the flow); other frames as they are.
SimulationData shownPart(const SimulationData& data)
{
    const auto* particles = std::get_if<ParticleSet>(&data);
    if (!particles || !particles->fields.count("wall"))
        return data;
    const std::vector<double>& wall = particles->fields.at("wall");
    ParticleSet fluid;
    for (const auto& entry : particles->fields)
        fluid.fields[entry.first];
    for (std::size_t i = 0; i < particles->size(); ++i)
        if (wall[i] < 0.5)
        {
            fluid.positionsMm.push_back(particles->positionsMm[i]);
            for (const auto& [name, values] : particles->fields)
                fluid.fields[name].push_back(values[i]);
        }
    return fluid;
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
                               auto* panel = new QWidget(this);
                               m_runPlayer = new RunPlayer(panel);
                               m_runPlot = new LinePlot(panel);
                               m_runPlot->setObjectName("runPlot");
                               m_runPlot->setToolTip(tr("Click or drag to go to a frame"));
                               m_flowVelocityPlot = new LinePlot(panel);
                               m_flowVelocityPlot->setObjectName("flowVelocityPlot");
                               m_flowPressurePlot = new LinePlot(panel);
                               m_flowPressurePlot->setObjectName("flowPressurePlot");
                               auto* layout = new QVBoxLayout(panel);
                               layout->setContentsMargins(0, 0, 0, 0);
                               layout->addWidget(m_runPlayer);
                               layout->addWidget(m_runPlot, 1);
                               layout->addWidget(m_flowVelocityPlot, 1);
                               layout->addWidget(m_flowPressurePlot, 1);
                               connect(m_runPlayer, &RunPlayer::frameChanged, this, [this] { drawRunFrame(); });
                               connect(m_runPlayer, &RunPlayer::appearanceChanged, this, [this] {
                                   plotRunHistory();
                                   drawRunFrame();
                               });
                               connect(m_runPlot, &LinePlot::clicked, this,
                                       [this](double x) { m_runPlayer->setFrame(m_runPlayer->frameNearest(x)); });
                               m_runDock = new QDockWidget(tr("Run Player"), this);
                               m_runDock->setObjectName("runPlayerDock");
                               m_runDock->setWidget(panel);
                               addDockWidget(Qt::BottomDockWidgetArea, m_runDock);
                               connect(m_runDock, &QDockWidget::visibilityChanged, this, [this](bool visible) {
                                   if (!visible)
                                       closeRunPlayer();
                               });
                           }
                           if (id != m_playedRunId) // another run's wall loads do not belong around it
                               m_wallLoads.reset();
                           m_playedRun = run;
                           m_playedRunId = id;
                           std::vector<double> positions;
                           for (const RunFrame& frame : run->frames)
                               positions.push_back(frame.position);
                           if (m_drugDock)
                               m_drugDock->hide();
                           m_runDock->setWindowTitle(
                               tr("Run Player: %1")
                                   .arg(QString::fromStdString(storedTextForPeople(m_document.study().artifact(id).name))));
                           m_runDock->show();
                           m_runPlayer->setFrames(positions, axisQuantityText(run->axis.quantity),
                                                  QString::fromStdString(run->axis.unit),
                                                  run->frames.empty() ? QStringList() : fieldsOf(run->frames.front().data));
                           plotRunHistory();
                           plotFlowAlongCenterline();
                           drawRunFrame();
                       });
}

void MainWindow::plotFlowAlongCenterline()
{
    const std::vector<app::SectionAlongCenterline> sections =
        m_playedRunId.empty() ? std::vector<app::SectionAlongCenterline>{}
                              : app::sectionsAlongCenterline(m_document.study().artifact(m_playedRunId));
    m_flowVelocityPlot->setVisible(!sections.empty());
    m_flowPressurePlot->setVisible(!sections.empty());
    if (sections.empty())
        return;
    LinePlot::Curve peak{tr("peak (fastest 5 %)"), QColor(200, 40, 30), {}, {}},
        mean{tr("mean (flow rate / area)"), QColor(40, 90, 200), {}, {}},
        pressure{tr("mean pressure"), QColor(30, 140, 60), {}, {}};
    for (const app::SectionAlongCenterline& s : sections)
    {
        peak.x.push_back(s.arcMm), mean.x.push_back(s.arcMm), pressure.x.push_back(s.arcMm);
        peak.y.push_back(s.peakVelocityMS), mean.y.push_back(s.meanVelocityMS), pressure.y.push_back(s.meanPressurePa);
    }
    const QString along = tr("along the centerline from the inlet (mm)");
    m_flowVelocityPlot->setAxes(along, tr("velocity (m/s), time-averaged sections"));
    m_flowVelocityPlot->setCurves({peak, mean});
    m_flowPressurePlot->setAxes(along, tr("pressure (Pa, gauge), time-averaged"));
    m_flowPressurePlot->setCurves({pressure});
}

void MainWindow::plotRunHistory()
{
    // The played field over the run: its peak and median per frame (the plot) and its range (the fixed legend).
    if (!m_playedRun || !m_runPlot)
        return;
    const std::string field = m_runPlayer->field().toStdString();
    LinePlot::Curve peak{tr("peak"), QColor(200, 40, 30), {}, {}}, middle{tr("median"), QColor(40, 90, 200), {}, {}};
    m_playedRange = {std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest()};
    for (const RunFrame& frame : m_playedRun->frames)
    {
        const std::vector<double> values = valuesOf(shownPart(frame.data), field);
        widen(m_playedRange, values);
        peak.x.push_back(frame.position), middle.x.push_back(frame.position);
        peak.y.push_back(values.empty() ? std::numeric_limits<double>::quiet_NaN()
                                        : *std::max_element(values.begin(), values.end()));
        middle.y.push_back(median(values));
    }
    const SimulationData& first = m_playedRun->frames.front().data;
    const QString over = std::holds_alternative<VesselNetwork>(first) ? tr("segments")
                         : std::holds_alternative<ParticleSet>(first) ? tr("blood particles")
                         : std::holds_alternative<GridFields>(first)  ? tr("voxels")
                                                                      : tr("cells");
    m_runPlot->setAxes(m_runPlayer->axisTitle(), tr("%1 over the %2 of each frame").arg(m_runPlayer->fieldText(), over));
    m_runPlot->setCurves({peak, middle});
}

void MainWindow::drawRunFrame()
{
    if (!m_playedRun || m_playedRun->frames.empty() || !m_runPlayer)
        return;
    const RunFrame& played = m_playedRun->frames[std::size_t(m_runPlayer->frame())];
    const std::string field = m_runPlayer->field().toStdString();
    const RunFrame frame{played.number, played.step, played.position, shownPart(played.data)};
    // The legend's range: over the whole run (so that colours compare between frames) or this frame's.
    std::pair<double, double> range = m_playedRange; // the run's, found with its history
    if (m_runPlayer->rangePerFrame())
    {
        range = {std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest()};
        widen(range, valuesOf(frame.data, field));
    }
    if (!(range.second >= range.first))
        range = {0.0, 1.0};
    if (range.second - range.first < 1e-12)
        range.second = range.first + 1e-6;
    const RunStatus& status = m_playedRun->status;
    QString title = m_runPlayer->fieldText() + ", " + m_runPlayer->frameText();
    if (!status.converged())
        title += tr(", NOT CONVERGED");
    else if (!status.complete())
        title += tr(", STOPPED EARLY");

    m_runPlot->setCursor(frame.position);
    for (viz::SliceOrientation orientation : kSliceOrientations)
    {
        viz::SliceView* slice = m_views->sliceView(orientation);
        if (valuesOf(frame.data, field).empty())
            slice->clearField();
        else
            slice->setField(frame.data, field, range.first, range.second);
    }

    viz::VolumeView3D* view = m_views->volumeView();
    view->clearSurfaces();
    view->clearLines();
    view->clearFieldLines();
    view->setVolumeVisible(false);
    if (const auto* grid = std::get_if<GridFields>(&frame.data))
    {
        // A field on a grid (a smoke run's density): volume-rendered; clear where not chosen.
        const auto found = grid->fields.find(field);
        if (found != grid->fields.end())
            view->showFieldVolume(found->second, range.first, range.second, title);
        else
            view->clearFieldVolume();
    }
    else
        view->clearFieldVolume();
    if (const auto* mesh = std::get_if<TetMesh>(&frame.data))
    {
        if (mesh->cellFields.count(field))
            view->showFieldSurface(app::frameSurface(*mesh, field), field, range.first, range.second, title);
    }
    else if (const auto* network = std::get_if<VesselNetwork>(&frame.data))
    {
        std::vector<std::vector<Eigen::Vector3d>> lines;
        std::vector<std::array<double, 2>> radii;
        for (std::size_t s = 0; s < network->segments.size(); ++s)
        {
            lines.push_back(network->segmentPath(s));
            radii.push_back({network->segments[s].startRadiusMm, network->segments[s].endRadiusMm});
        }
        view->showFieldLines(lines, valuesOf(frame.data, field), range.first, range.second, 3.0, title, radii);
    }
    else if (const auto* particles = std::get_if<ParticleSet>(&frame.data))
    {
        // With the wall loads around them (see-through) the particles are drawn smaller: 4-pixel sprites of the
        // particles next to the wall reach through the surface in front of them and hide it.
        if (m_endoscope)
            m_endoscope->setParticles(particles->positionsMm);
        if (particles->fields.count(field))
            view->showFieldPoints(particles->positionsMm, particles->fields.at(field), range.first, range.second,
                                  m_wallLoads ? 2.0 : 4.0, title);
        if (m_wallLoads)
        {
            view->showFieldSurface(m_wallLoads->surface, m_wallLoads->field, m_wallLoads->low, m_wallLoads->high,
                                   m_wallLoads->title);
            view->setFieldSurfaceOpacity(0.5);
        }
    }
}

void MainWindow::closeRunPlayer()
{
    if (!m_playedRun)
        return;
    m_runPlayer->pause();
    m_playedRun.reset();
    m_playedRunId.clear();
    m_wallLoads.reset();
    m_views->volumeView()->clearFieldLines();
    m_views->volumeView()->clearFieldVolume();
    for (viz::SliceOrientation orientation : kSliceOrientations)
        m_views->sliceView(orientation)->clearField();
    m_drawnScene.clear(); // the study's own 3D content again
    refreshScene();
}

} // namespace vsim::gui
