#include "vsim/viz/VtkView.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QTimer>
#include <QWheelEvent>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkOpenGLState.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

namespace vsim::viz {

struct VtkView::Private
{
    vtkSmartPointer<vtkGenericOpenGLRenderWindow> window = vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New();
    vtkSmartPointer<vtkRenderer> renderer = vtkSmartPointer<vtkRenderer>::New();
    vtkSmartPointer<vtkGenericRenderWindowInteractor> interactor =
        vtkSmartPointer<vtkGenericRenderWindowInteractor>::New();
    QTimer vtkTimer; // backs the interactor's timers (animations, joystick styles)
};

VtkView::VtkView(QWidget* parent) : QOpenGLWidget(parent), d(std::make_unique<Private>())
{
    d->window->AddRenderer(d->renderer);
    d->interactor->SetRenderWindow(d->window);
    d->interactor->SetInteractorStyle(vtkSmartPointer<vtkInteractorStyleTrackballCamera>::New());
    d->interactor->EnableRenderOff(); // paintGL renders; the interactor only asks for an update
    auto requestUpdate = vtkSmartPointer<vtkCallbackCommand>::New();
    requestUpdate->SetClientData(this);
    requestUpdate->SetCallback([](vtkObject*, unsigned long, void* view, void*) { static_cast<VtkView*>(view)->update(); });
    d->interactor->AddObserver(vtkCommand::RenderEvent, requestUpdate);

    d->vtkTimer.setInterval(10);
    connect(&d->vtkTimer, &QTimer::timeout, this, [this] { d->interactor->TimerEvent(); });
    auto createTimer = vtkSmartPointer<vtkCallbackCommand>::New();
    createTimer->SetClientData(&d->vtkTimer);
    createTimer->SetCallback([](vtkObject*, unsigned long, void* timer, void*) { static_cast<QTimer*>(timer)->start(); });
    d->interactor->AddObserver(vtkCommand::CreateTimerEvent, createTimer);
    auto destroyTimer = vtkSmartPointer<vtkCallbackCommand>::New();
    destroyTimer->SetClientData(&d->vtkTimer);
    destroyTimer->SetCallback([](vtkObject*, unsigned long, void* timer, void*) { static_cast<QTimer*>(timer)->stop(); });
    d->interactor->AddObserver(vtkCommand::DestroyTimerEvent, destroyTimer);

    setFocusPolicy(Qt::StrongFocus);
    setMinimumSize(160, 160);
}

VtkView::~VtkView()
{
    makeCurrent();
    d->window->Finalize(); // releases VTK's GL resources while the context is current
    doneCurrent();
}

vtkRenderer* VtkView::renderer() const { return d->renderer; }
vtkGenericOpenGLRenderWindow* VtkView::renderWindow() const { return d->window; }
vtkGenericRenderWindowInteractor* VtkView::interactor() const { return d->interactor; }

void VtkView::initializeGL()
{
    d->window->SetOwnContext(false);
    d->window->SetFrameBlitModeToBlitToCurrent();
    d->window->SetMapped(1);
    d->window->SetIsCurrent(true);
    d->window->OpenGLInitContext();
    d->interactor->Initialize();
}

void VtkView::resizeGL(int width, int height)
{
    const double ratio = devicePixelRatioF();
    const int pixelWidth = static_cast<int>(width * ratio);
    const int pixelHeight = static_cast<int>(height * ratio);
    d->window->SetSize(pixelWidth, pixelHeight);
    d->interactor->UpdateSize(pixelWidth, pixelHeight);
}

void VtkView::paintGL()
{
    vtkOpenGLState* state = d->window->GetState();
    state->Reset();
    state->Push();
    d->window->SetReadyForRendering(true);
    d->window->Render();
    state->Pop();
    d->window->SetReadyForRendering(false);
}

namespace {

void setEventPosition(vtkGenericRenderWindowInteractor* interactor, const QPointF& position, Qt::KeyboardModifiers modifiers,
                      double ratio)
{
    interactor->SetEventInformationFlipY(static_cast<int>(position.x() * ratio), static_cast<int>(position.y() * ratio),
                                         modifiers & Qt::ControlModifier ? 1 : 0, modifiers & Qt::ShiftModifier ? 1 : 0);
}

/// The VTK event for a mouse button going down (`pressed`) or up; NoEvent for other buttons.
unsigned long buttonEventFor(Qt::MouseButton button, bool pressed)
{
    switch (button)
    {
    case Qt::LeftButton: return pressed ? vtkCommand::LeftButtonPressEvent : vtkCommand::LeftButtonReleaseEvent;
    case Qt::MiddleButton: return pressed ? vtkCommand::MiddleButtonPressEvent : vtkCommand::MiddleButtonReleaseEvent;
    case Qt::RightButton: return pressed ? vtkCommand::RightButtonPressEvent : vtkCommand::RightButtonReleaseEvent;
    default: return vtkCommand::NoEvent;
    }
}

} // namespace

void VtkView::mousePressEvent(QMouseEvent* event)
{
    if (!m_forwardEvents)
        return;
    setEventPosition(d->interactor, event->position(), event->modifiers(), devicePixelRatioF());
    d->interactor->InvokeEvent(buttonEventFor(event->button(), true));
}

void VtkView::mouseMoveEvent(QMouseEvent* event)
{
    if (!m_forwardEvents)
        return;
    setEventPosition(d->interactor, event->position(), event->modifiers(), devicePixelRatioF());
    d->interactor->InvokeEvent(vtkCommand::MouseMoveEvent);
}

void VtkView::mouseReleaseEvent(QMouseEvent* event)
{
    if (!m_forwardEvents)
        return;
    setEventPosition(d->interactor, event->position(), event->modifiers(), devicePixelRatioF());
    d->interactor->InvokeEvent(buttonEventFor(event->button(), false));
}

void VtkView::wheelEvent(QWheelEvent* event)
{
    if (!m_forwardEvents)
        return;
    setEventPosition(d->interactor, event->position(), event->modifiers(), devicePixelRatioF());
    d->interactor->InvokeEvent(event->angleDelta().y() > 0 ? vtkCommand::MouseWheelForwardEvent
                                                            : vtkCommand::MouseWheelBackwardEvent);
}

void VtkView::keyPressEvent(QKeyEvent* event)
{
    if (!m_forwardEvents || event->text().isEmpty())
        return QOpenGLWidget::keyPressEvent(event);
    d->interactor->SetKeyCode(event->text().at(0).toLatin1());
    d->interactor->InvokeEvent(vtkCommand::KeyPressEvent);
    d->interactor->InvokeEvent(vtkCommand::CharEvent);
}

void VtkView::keyReleaseEvent(QKeyEvent* event)
{
    if (!m_forwardEvents || event->text().isEmpty())
        return QOpenGLWidget::keyReleaseEvent(event);
    d->interactor->SetKeyCode(event->text().at(0).toLatin1());
    d->interactor->InvokeEvent(vtkCommand::KeyReleaseEvent);
}

CameraState VtkView::cameraState() const
{
    vtkCamera* camera = renderer()->GetActiveCamera();
    CameraState state;
    camera->GetPosition(state.position.data());
    camera->GetFocalPoint(state.focalPoint.data());
    camera->GetViewUp(state.viewUp.data());
    state.parallelScale = camera->GetParallelScale();
    state.viewAngle = camera->GetViewAngle();
    state.parallel = camera->GetParallelProjection() != 0;
    return state;
}

void VtkView::setCameraState(const CameraState& state)
{
    vtkCamera* camera = renderer()->GetActiveCamera();
    camera->SetPosition(state.position.data());
    camera->SetFocalPoint(state.focalPoint.data());
    camera->SetViewUp(state.viewUp.data());
    camera->SetParallelScale(state.parallelScale);
    camera->SetViewAngle(state.viewAngle);
    camera->SetParallelProjection(state.parallel ? 1 : 0);
    renderer()->ResetCameraClippingRange();
    update();
}

void VtkView::orbit(double degrees)
{
    renderer()->GetActiveCamera()->Azimuth(degrees);
    renderer()->ResetCameraClippingRange();
    update();
}

} // namespace vsim::viz
