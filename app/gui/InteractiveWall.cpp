#include "InteractiveWall.h"

#include "vsim/core/TetMesh.h"
#include "vsim/core/Units.h"
#include "vsim/viz/VolumeView3D.h"

#include <algorithm>

namespace vsim::gui {

InteractiveWall::InteractiveWall(const TetMesh& wall, const sim::fem::ElasticMaterial& material,
                                 const sim::fem::BackwardEulerSettings& settings, viz::VolumeView3D* view, QObject* parent)
    : QObject(parent), m_simulation(std::make_unique<sim::fem::WallSimulation>(wall, material, settings)), m_view(view)
{
    m_timer.setInterval(0); // as fast as the steps go; the GUI stays responsive between frames
    connect(&m_timer, &QTimer::timeout, this, &InteractiveWall::advance);
    m_clock.start();
    draw();
}

InteractiveWall::~InteractiveWall() = default;

void InteractiveWall::play() { m_timer.start(); }
void InteractiveWall::pause() { m_timer.stop(); }

void InteractiveWall::setPressureMmHg(double mmHg) { m_simulation->setPressure(units::mmHgToPa(mmHg)); }

void InteractiveWall::setTearStrengthMpa(double strengthMpa) { m_simulation->setTearStrength(units::mpaToPa(strengthMpa)); }

void InteractiveWall::grab(const Eigen::Vector3d& pointMm) { m_simulation->grab(pointMm, kDragStiffness); }
void InteractiveWall::dragTo(const Eigen::Vector3d& pointMm) { m_simulation->dragTo(pointMm); }
void InteractiveWall::release() { m_simulation->release(); }

void InteractiveWall::advance()
{
    const sim::fem::WallSimulation::StepOutcome outcome = m_simulation->step();
    if (!outcome.guard.empty())
    {
        pause();
        emit stopped(QString::fromStdString(outcome.guard));
    }
    draw();
    ++m_framesThisSecond;
    if (m_clock.elapsed() >= 1000)
    {
        m_fps = 1000.0 * m_framesThisSecond / double(m_clock.restart());
        m_framesThisSecond = 0;
    }
}

void InteractiveWall::draw()
{
    // The boundary of the current (deformed) wall, coloured by each face's element stress averaged at its points.
    const sim::fem::CorotationalFem& model = m_simulation->model();
    if (m_meshElements != model.elementCount()) // the boundary only changes when elements tear
    {
        m_surface.triangles = boundaryFaces(model.tets(), &m_owners);
        m_meshElements = model.elementCount();
    }
    const std::vector<std::size_t>& owners = m_owners;
    m_surface.points.resize(model.nodeCount());
    for (std::size_t n = 0; n < model.nodeCount(); ++n)
        m_surface.points[n] = units::mToMm(1.0) * model.positions().segment<3>(Eigen::Index(3 * n));
    const std::vector<double> vonMises = model.elementVonMises();
    std::vector<double> sum(model.nodeCount(), 0.0), count(model.nodeCount(), 0.0);
    for (std::size_t f = 0; f < m_surface.triangles.size(); ++f)
        for (int node : m_surface.triangles[f])
            sum[std::size_t(node)] += 1e-3 * vonMises[owners[f]], count[std::size_t(node)] += 1.0;
    std::vector<double> field(model.nodeCount(), 0.0);
    double peak = 0.0;
    for (std::size_t n = 0; n < field.size(); ++n)
        if (count[n] > 0.0)
            peak = std::max(peak, field[n] = sum[n] / count[n]);
    m_surface.pointFields["von_mises_kpa"] = field;
    m_view->showFieldSurface(m_surface, "von_mises_kpa", 0.0, std::max(peak, 1e-3), tr("von Mises (kPa)"));
    emit frameShown(m_fps, peak);
}

} // namespace vsim::gui
