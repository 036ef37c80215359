#include "NetworkProjectionView.h"

#include "vsim/sim/network/WorkingAngle.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace vsim::gui {
namespace {

QColor valueColour(double value, double low, double high)
{
    if (!std::isfinite(value))
        return QColor(110, 110, 110); // grey: no drug, as the 3D view
    const double t = high > low ? std::clamp((value - low) / (high - low), 0.0, 1.0) : 0.5;
    return QColor::fromHsvF(float(0.667 * (1.0 - t)), 0.9f, 0.9f); // blue (low) -> red (high), as the 3D legend
}

} // namespace

NetworkProjectionView::NetworkProjectionView(QWidget* parent) : QWidget(parent)
{
    setMinimumSize(240, 240);
    setAutoFillBackground(true);
    QPalette p = palette();
    p.setColor(QPalette::Window, Qt::black);
    setPalette(p);
}

void NetworkProjectionView::setNetwork(const VesselNetwork& network, const std::vector<double>& values, double low,
                                       double high)
{
    m_network = network;
    m_values = values;
    m_low = low, m_high = high;
    fitBounds();
}

void NetworkProjectionView::setViewDirection(const Eigen::Vector3d& direction)
{
    std::tie(m_right, m_up) = sim::network::imageAxes(direction);
    fitBounds();
}

void NetworkProjectionView::fitBounds()
{
    m_min = Eigen::Vector2d::Constant(1e300), m_max = Eigen::Vector2d::Constant(-1e300);
    for (const VesselNetwork::Node& node : m_network.nodes)
    {
        const Eigen::Vector2d p(node.positionMm.dot(m_right), node.positionMm.dot(m_up));
        m_min = m_min.cwiseMin(p), m_max = m_max.cwiseMax(p);
    }
    m_min -= Eigen::Vector2d::Constant(5.0), m_max += Eigen::Vector2d::Constant(5.0);
    update();
}

void NetworkProjectionView::setDsaPicture(const QImage& picture)
{
    m_dsa = picture;
    update();
}

void NetworkProjectionView::setShowDsa(bool show)
{
    m_showDsa = show;
    update();
}

void NetworkProjectionView::setTrails(std::vector<std::vector<Eigen::Vector3d>> trails)
{
    m_trails = std::move(trails);
    update();
}

QPointF NetworkProjectionView::project(const Eigen::Vector3d& p) const
{
    const Eigen::Vector2d size = m_max - m_min;
    const double scale = std::min(width() / std::max(size.x(), 1.0), height() / std::max(size.y(), 1.0));
    const double x0 = 0.5 * (width() - scale * size.x()), y0 = 0.5 * (height() - scale * size.y());
    // The image's right and up (the front view: patient left (+x) to the right, superior (+z) up).
    return {x0 + scale * (p.dot(m_right) - m_min.x()), y0 + scale * (m_max.y() - p.dot(m_up))};
}

void NetworkProjectionView::paintEvent(QPaintEvent*)
{
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    if (showsDsa()) // the picture fitted to the view, its aspect kept
    {
        const QImage fitted = m_dsa.scaled(size(), Qt::KeepAspectRatio, Qt::SmoothTransformation);
        painter.drawImage(QPointF(0.5 * (width() - fitted.width()), 0.5 * (height() - fitted.height())), fitted);
        return;
    }
    const Eigen::Vector2d size = m_max - m_min;
    const double pixelsPerMm = std::min(width() / std::max(size.x(), 1.0), height() / std::max(size.y(), 1.0));
    for (std::size_t s = 0; s < m_network.segments.size(); ++s)
    {
        const auto& segment = m_network.segments[s];
        std::vector<Eigen::Vector3d> path = segment.pathMm;
        if (path.size() < 2)
            path = {m_network.nodes[std::size_t(segment.from)].positionMm, m_network.nodes[std::size_t(segment.to)].positionMm};
        QPainterPath line(project(path.front()));
        for (std::size_t i = 1; i < path.size(); ++i)
            line.lineTo(project(path[i]));
        const double value = s < m_values.size() ? m_values[s] : m_low;
        painter.setPen(QPen(valueColour(value, m_low, m_high),
                            std::max(1.0, pixelsPerMm * (segment.startRadiusMm + segment.endRadiusMm)), Qt::SolidLine,
                            Qt::RoundCap, Qt::RoundJoin));
        painter.drawPath(line);
    }
    // Tubelets: quads along each trail, pale yellow, opaque at the head, fading to the tail.
    painter.setPen(Qt::NoPen);
    for (const auto& trail : m_trails)
        for (std::size_t i = 0; i + 1 < trail.size(); ++i)
        {
            const QPointF a = project(trail[i]), b = project(trail[i + 1]);
            QPointF side(b.y() - a.y(), a.x() - b.x());
            const double length = std::hypot(side.x(), side.y());
            if (length <= 0.0)
                continue;
            side *= 0.6 * pixelsPerMm / length; // 1.2 mm wide
            const double alpha = 1.0 - double(i) / double(trail.size() - 1);
            painter.setBrush(QColor(255, 235, 90, int(235 * alpha)));
            painter.drawPolygon(QPolygonF{a - side, a + side, b + side, b - side});
        }
}

} // namespace vsim::gui
