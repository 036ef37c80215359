#pragma once

#include <QOpenGLWidget>

#include <memory>

class vtkGenericOpenGLRenderWindow;
class vtkGenericRenderWindowInteractor;
class vtkRenderer;

namespace vsim::viz {

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
