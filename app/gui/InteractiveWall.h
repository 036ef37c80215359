#pragma once

#include "vsim/core/TriangleMesh.h"
#include "vsim/sim/fem/WallSimulation.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <memory>

namespace vsim::viz {
class VolumeView3D;
}

namespace vsim::gui {

/// The interactive wall protocol: a WallSimulation stepped on a timer (play / pause) while the user drags a point
/// of the wall in the 3D view (a spring to the cursor) and sets the lumen pressure; each frame shows the deformed
/// wall coloured by von Mises stress with its legend, and torn elements leave gaps.
class InteractiveWall : public QObject
{
    Q_OBJECT
public:
    /// Takes the wall (mm, with wall_layer / end_set) and the view to draw in. Throws vsim::Error for a bad wall.
    InteractiveWall(const TetMesh& wall, const sim::fem::ElasticMaterial& material,
                    const sim::fem::BackwardEulerSettings& settings, viz::VolumeView3D* view, QObject* parent = nullptr);
    ~InteractiveWall() override;

    void play();
    void pause();
    bool isPlaying() const { return m_timer.isActive(); }
    void setPressureMmHg(double mmHg);
    /// Tears at `strengthMpa` (0: off).
    void setTearStrengthMpa(double strengthMpa);
    /// Grab / drag / release as the view's signals do (mm); the spring is `kDragStiffness`.
    void grab(const Eigen::Vector3d& pointMm);
    void dragTo(const Eigen::Vector3d& pointMm);
    void release();
    /// Steps and draws one frame now (the timer calls this).
    void advance();
    /// Frames per second over the last second (steps + drawing).
    double framesPerSecond() const { return m_fps; }
    const sim::fem::WallSimulation& simulation() const { return *m_simulation; }
    /// The surface of the last frame (deformed, mm) with its von Mises point field (kPa).
    const TriangleMesh& lastSurface() const { return m_surface; }

    static constexpr double kDragStiffness = 200.0; ///< N/m: a firm pull on a wall of a few MPa

signals:
    void frameShown(double framesPerSecond, double peakVonMisesKpa);
    /// A guard undid a step (the message says why); the player pauses.
    void stopped(const QString& reason);

private:
    void draw();

    std::unique_ptr<sim::fem::WallSimulation> m_simulation;
    viz::VolumeView3D* m_view;
    QTimer m_timer;
    QElapsedTimer m_clock;
    int m_framesThisSecond = 0;
    double m_fps = 0.0;
    TriangleMesh m_surface;
    std::vector<std::size_t> m_owners;     // element of each surface triangle
    std::size_t m_meshElements = 0;        // the element count the cached boundary belongs to (tearing changes it)
};

} // namespace vsim::gui
