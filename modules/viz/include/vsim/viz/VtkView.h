#pragma once

#include <QOpenGLWidget>

#include <array>
#include <memory>

class vtkGenericOpenGLRenderWindow;
class vtkGenericRenderWindowInteractor;
class vtkRenderer;

namespace vsim::viz {

/// Where a view's camera is (mm, LPS): kept with a study so that a reopened study looks as it was left.
struct CameraState
{
    std::array<double, 3> position{}, focalPoint{}, viewUp{};
    double parallelScale = 1.0; ///< half the view's height (mm) in parallel projection
    double viewAngle = 30.0;    ///< degrees, in perspective projection
    bool parallel = true;
};

/// The Qt 6 <-> VTK bridge: a QOpenGLWidget that renders a vtkGenericOpenGLRenderWindow into its framebuffer
/// (VTK's own Qt module is built against Qt 5 in Debian and is never linked). Sizes are in device pixels (HiDPI),
/// mouse, wheel and key events go to a vtkGenericRenderWindowInteractor (y flipped), and VTK timers run on
/// QTimer. Subclasses build their scene in renderer() and may take the input events themselves.
class VtkView : public QOpenGLWidget
{
    Q_OBJECT
public:
    explicit VtkView(QWidget* parent = nullptr);
    ~VtkView() override;

    vtkRenderer* renderer() const;
    vtkGenericOpenGLRenderWindow* renderWindow() const;
    vtkGenericRenderWindowInteractor* interactor() const;
    /// The renderer's camera, and setting it (the view is redrawn).
    CameraState cameraState() const;
    void setCameraState(const CameraState& state);
    /// Turns the camera `degrees` about the view-up axis through the focal point (a rotation movie's step).
    void orbit(double degrees);
    /// Whether mouse and key events are forwarded to the VTK interactor (the 3D view's camera); default true.
    void setForwardEventsToVtk(bool forward) { m_forwardEvents = forward; }

protected:
    void initializeGL() override;
    void resizeGL(int width, int height) override;
    void paintGL() override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void keyReleaseEvent(QKeyEvent* event) override;

private:
    struct Private;
    std::unique_ptr<Private> d;
    bool m_forwardEvents = true;
};

} // namespace vsim::viz
