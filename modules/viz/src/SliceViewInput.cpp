// A SliceView's input: the left button (cursor, brush dabs, marker drags, placed points, measurement drawing), the
// middle (pan) and right (window/level or zoom) buttons, the wheel (slices; zoom with Ctrl) and the keys (slices,
// presets, reset, Escape). The slice and its state are SliceView.cpp's.
#include "SliceViewPipeline.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QWheelEvent>

#include <cmath>

namespace vsim::viz {

bool SliceView::measurePress(const QPointF& widgetPosition)
{
    if (m_measureTool == MeasureTool::Off)
        return false;
    const Eigen::Vector3d at = patientAt(widgetPosition);
    if (m_pending.pointsMm.empty())
    {
        const ScreenAxes axes = screenAxes(m_orientation);
        m_pending = ViewMeasurement{};
        m_pending.kind = m_measureTool == MeasureTool::Ruler  ? ViewMeasurement::Kind::Ruler
                         : m_measureTool == MeasureTool::Angle ? ViewMeasurement::Kind::Angle
                                                               : ViewMeasurement::Kind::Roi;
        m_pending.planeRight = axes.right;
        m_pending.planeUp = axes.up;
        m_pending.pointsMm = {at, at}; // the second follows the mouse
    }
    else // an angle's next click: the point that followed the mouse stays, a new one follows
    {
        m_pending.pointsMm.back() = at;
        if (int(m_pending.pointsMm.size()) == pointCount(m_pending.kind))
        {
            const ViewMeasurement done = m_pending;
            m_pending.pointsMm.clear();
            m_pipeline->measurements->clearPending();
            updateMarkers();
            emit measurementDrawn(done);
            return true;
        }
        m_pending.pointsMm.push_back(at);
    }
    m_pipeline->measurements->setPending(m_pending);
    updateMarkers();
    return true;
}

void SliceView::measureMove(const QPointF& widgetPosition)
{
    if (m_measureTool == MeasureTool::Off || m_pending.pointsMm.empty())
        return;
    m_pending.pointsMm.back() = patientAt(widgetPosition);
    m_pipeline->measurements->setPending(m_pending);
    updateMarkers();
}

bool SliceView::measureRelease(const QPointF& widgetPosition)
{
    if (m_measureTool == MeasureTool::Off || m_pending.pointsMm.empty())
        return false;
    if (m_pending.kind == ViewMeasurement::Kind::Angle)
        return true; // an angle is clicked, not dragged
    m_pending.pointsMm.back() = patientAt(widgetPosition);
    const ViewMeasurement done = m_pending;
    m_pending.pointsMm.clear();
    m_pipeline->measurements->clearPending();
    updateMarkers();
    constexpr double kLeastPixels = 3.0; // a click without a drag draws nothing
    if ((done.pointsMm[1] - done.pointsMm[0]).norm() >= kLeastPixels * millimetresPerPixel())
        emit measurementDrawn(done);
    return true;
}

void SliceView::mousePressEvent(QMouseEvent* event)
{
    m_dragStart = event->position();
    m_dragStartWindowLevel = m_windowLevel;
    m_dragStartCentre = m_viewCentre;
    m_dragStartField = m_fieldOfView;
    if (event->button() != Qt::LeftButton || !hasImage())
        return;
    if (measurePress(event->position()))
        return;
    if (m_brush != BrushMode::Off && hasLabel())
    {
        m_stroking = true;
        emit brushDab(patientAt(event->position()), screenAxes(m_orientation).normal());
        return;
    }
    constexpr double kPickPixels = 9.0;
    m_draggedMarker = m_pipeline->markers->pick(patientAt(event->position()), kPickPixels * millimetresPerPixel());
    if (m_draggedMarker)
        return;
    if (m_placing)
    {
        emit pointPlaced(patientAt(event->position()));
        return;
    }
    setCursor(patientAt(event->position()));
}

void SliceView::mouseMoveEvent(QMouseEvent* event)
{
    if (!hasImage())
        return;
    const QPointF delta = event->position() - m_dragStart;
    measureMove(event->position()); // the point of the measurement being drawn follows the mouse
    if ((event->buttons() & Qt::LeftButton) && m_measureTool != MeasureTool::Off)
    {
        // the measurement tool has the left button
    }
    else if ((event->buttons() & Qt::LeftButton) && m_stroking)
        emit brushDab(patientAt(event->position()), screenAxes(m_orientation).normal());
    else if ((event->buttons() & Qt::LeftButton) && m_draggedMarker)
    {
        m_pipeline->markers->moveMarker(*m_draggedMarker, patientAt(event->position()));
        updateMarkers();
    }
    else if ((event->buttons() & Qt::LeftButton) && !m_placing)
        setCursor(patientAt(event->position()));
    else if (event->buttons() & Qt::MiddleButton)
    {
        // The image follows the mouse: the centre moves the other way (mm per pixel at the drag's start).
        const ScreenAxes axes = screenAxes(m_orientation);
        const double mmPerPixel = m_dragStartField / std::max(1, height());
        setViewCentre(m_dragStartCentre - delta.x() * mmPerPixel * axes.right + delta.y() * mmPerPixel * axes.up);
    }
    else if ((event->buttons() & Qt::RightButton) && m_rightDragZooms)
    {
        setFieldOfView(m_dragStartField * std::exp(0.01 * delta.y())); // drag down: zoom out
    }
    else if (event->buttons() & Qt::RightButton)
        setWindowLevel({m_dragStartWindowLevel.window + 4.0 * delta.x(), m_dragStartWindowLevel.level - 2.0 * delta.y()});
    updateMouseReadout(event->position());
}

void SliceView::mouseReleaseEvent(QMouseEvent* event)
{
    if (event->button() == Qt::LeftButton && measureRelease(event->position()))
        return;
    if (event->button() == Qt::LeftButton && m_stroking)
    {
        m_stroking = false;
        emit brushStrokeFinished();
    }
    if (event->button() == Qt::LeftButton && m_draggedMarker)
    {
        const int id = *m_draggedMarker;
        m_draggedMarker.reset();
        emit markerMoved(id, patientAt(event->position()));
    }
}

void SliceView::leaveEvent(QEvent* event)
{
    updateMouseReadout(std::nullopt);
    VtkView::leaveEvent(event);
}

void SliceView::wheelEvent(QWheelEvent* event)
{
    if (!hasImage())
        return;
    constexpr int kNotch = 120; // eighths of a degree per wheel notch
    m_wheelRemainder += event->angleDelta().y();
    const int notches = m_wheelRemainder / kNotch;
    m_wheelRemainder -= notches * kNotch;
    if (notches == 0)
        return;
    if (event->modifiers() & Qt::ControlModifier)
        zoomBy(std::pow(1.1, notches), event->position());
    else
        stepSlices(notches);
    updateMouseReadout(event->position());
}

void SliceView::keyPressEvent(QKeyEvent* event)
{
    if (!hasImage())
        return VtkView::keyPressEvent(event);
    switch (event->key())
    {
    case Qt::Key_Up: return stepSlices(1);
    case Qt::Key_Down: return stepSlices(-1);
    case Qt::Key_PageUp: return stepSlices(10);
    case Qt::Key_PageDown: return stepSlices(-10);
    case Qt::Key_Home: return stepSlices(-sliceCount());
    case Qt::Key_End: return stepSlices(sliceCount());
    case Qt::Key_1: return setWindowLevel(kCtaPreset);
    case Qt::Key_2: return setWindowLevel(kSoftTissuePreset);
    case Qt::Key_3: return setWindowLevel(kBonePreset);
    case Qt::Key_4: return setWindowLevel(kLungPreset);
    case Qt::Key_R: return resetView();
    case Qt::Key_Escape:
        m_pending.pointsMm.clear();
        m_pipeline->measurements->clearPending();
        return updateMarkers();
    default: return VtkView::keyPressEvent(event);
    }
}

} // namespace vsim::viz
