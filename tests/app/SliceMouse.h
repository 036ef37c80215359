#pragma once

// Mouse input on a slice view at patient points (mm), for GUI tests: a press, move or release sent to the
// view, a drag and a click.
#include "vsim/viz/SliceView.h"

#include <QApplication>
#include <QMouseEvent>

#include <Eigen/Core>

namespace vsim::test {

inline void sliceMouse(viz::SliceView* view, QEvent::Type type, const Eigen::Vector3d& atMm,
                       Qt::MouseButtons buttons)
{
    const QPointF at = view->widgetAt(atMm);
    QMouseEvent event(type, at, view->mapToGlobal(at), Qt::LeftButton, buttons, Qt::NoModifier);
    QApplication::sendEvent(view, &event);
}

inline void sliceDrag(viz::SliceView* view, const Eigen::Vector3d& from, const Eigen::Vector3d& to)
{
    sliceMouse(view, QEvent::MouseButtonPress, from, Qt::LeftButton);
    sliceMouse(view, QEvent::MouseMove, 0.5 * (from + to), Qt::LeftButton);
    sliceMouse(view, QEvent::MouseMove, to, Qt::LeftButton);
    sliceMouse(view, QEvent::MouseButtonRelease, to, Qt::NoButton);
}

inline void sliceClick(viz::SliceView* view, const Eigen::Vector3d& at)
{
    sliceMouse(view, QEvent::MouseButtonPress, at, Qt::LeftButton);
    sliceMouse(view, QEvent::MouseButtonRelease, at, Qt::NoButton);
}

} // namespace vsim::test
