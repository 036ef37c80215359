#include "LinePlot.h"

#include "vsim/viz/DecimalText.h"

#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>
#include <limits>

namespace vsim::gui {
namespace {

/// "12.5", "0.0031", "1647", "1.2e+05": short tick labels, in the reader's decimal mark.
QString tickText(double value)
{
    return viz::significantText(value, 3);
}

} // namespace

LinePlot::LinePlot(QWidget* parent) : QWidget(parent)
{
    setMinimumHeight(120);
    setMouseTracking(false);
}

void LinePlot::setAxes(const QString& xTitle, const QString& yTitle)
{
    m_xTitle = xTitle, m_yTitle = yTitle;
    update();
}

void LinePlot::setCurves(std::vector<Curve> curves)
{
    m_curves = std::move(curves);
    update();
}

void LinePlot::setCursor(std::optional<double> x)
{
    m_cursor = x;
    update();
}

QRectF LinePlot::plotArea() const
{
    // Room for the y ticks on the left, the x ticks and title below, the y title above, half a tick label right.
    return QRectF(56.0, 22.0, std::max(10.0, width() - 96.0), std::max(10.0, height() - 60.0));
}

void LinePlot::dataRange(double& x0, double& x1, double& y0, double& y1) const
{
    x0 = y0 = std::numeric_limits<double>::max();
    x1 = y1 = std::numeric_limits<double>::lowest();
    for (const Curve& curve : m_curves)
        for (std::size_t i = 0; i < std::min(curve.x.size(), curve.y.size()); ++i)
            if (std::isfinite(curve.x[i]) && std::isfinite(curve.y[i]))
            {
                x0 = std::min(x0, curve.x[i]), x1 = std::max(x1, curve.x[i]);
                y0 = std::min(y0, curve.y[i]), y1 = std::max(y1, curve.y[i]);
            }
    if (x0 > x1)
        x0 = 0.0, x1 = 1.0, y0 = 0.0, y1 = 1.0;
    if (x1 - x0 <= 0.0)
        x1 = x0 + 1.0;
    if (y1 - y0 <= 0.0)
        y0 -= 0.5, y1 += 0.5;
    const double margin = 0.05 * (y1 - y0);
    y0 = y0 >= 0.0 ? std::max(0.0, y0 - margin) : y0 - margin; // data that cannot be negative keeps 0 as its floor
    y1 += margin;
}

double LinePlot::widgetXOf(double x) const
{
    double x0, x1, y0, y1;
    dataRange(x0, x1, y0, y1);
    const QRectF area = plotArea();
    return area.left() + (x - x0) / (x1 - x0) * area.width();
}

double LinePlot::xAt(double widgetX) const
{
    double x0, x1, y0, y1;
    dataRange(x0, x1, y0, y1);
    const QRectF area = plotArea();
    return x0 + std::clamp((widgetX - area.left()) / area.width(), 0.0, 1.0) * (x1 - x0);
}

void LinePlot::paintEvent(QPaintEvent*)
{
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.fillRect(rect(), palette().base());
    double x0, x1, y0, y1;
    dataRange(x0, x1, y0, y1);
    const QRectF area = plotArea();
    auto toWidget = [&](double x, double y)
    {
        return QPointF(area.left() + (x - x0) / (x1 - x0) * area.width(),
                       area.bottom() - (y - y0) / (y1 - y0) * area.height());
    };
    const QColor text = palette().text().color();
    painter.setPen(QPen(text, 1.0));
    painter.drawRect(area);
    const QFontMetrics metrics(font());
    for (int t = 0; t <= 4; ++t) // ticks: five on each axis
    {
        const double fx = x0 + t * (x1 - x0) / 4.0, fy = y0 + t * (y1 - y0) / 4.0;
        const QPointF px = toWidget(fx, y0), py = toWidget(x0, fy);
        painter.drawLine(px, px + QPointF(0, 4));
        painter.drawText(QRectF(px.x() - 40, area.bottom() + 5, 80, metrics.height()), Qt::AlignHCenter,
                         tickText(fx));
        painter.drawLine(py, py - QPointF(4, 0));
        painter.drawText(QRectF(0, py.y() - metrics.height() / 2.0, area.left() - 6, metrics.height()),
                         Qt::AlignRight, tickText(fy));
    }
    painter.drawText(
        QRectF(area.left(), area.bottom() + 5 + metrics.height(), area.width(), metrics.height()),
        Qt::AlignHCenter, m_xTitle);
    painter.drawText(QRectF(4, 2, width() - 8, metrics.height()), Qt::AlignLeft, m_yTitle);
    // The legend inside the plot's top left corner, on the plot's background.
    double legendWidth = 0.0;
    for (const Curve& curve : m_curves)
        legendWidth += metrics.horizontalAdvance(curve.name) + 26;
    const QRectF legend(area.left() + 4, area.top() + 4, legendWidth, metrics.height() + 4);
    if (!m_curves.empty())
    {
        QColor background = palette().base().color();
        background.setAlpha(220);
        painter.fillRect(legend, background);
    }
    double legendX = legend.left() + 4;
    const double legendY = legend.center().y();
    for (const Curve& curve : m_curves)
    {
        painter.setPen(QPen(curve.colour, 2.0));
        painter.drawLine(QPointF(legendX, legendY), QPointF(legendX + 14, legendY));
        painter.setPen(text);
        painter.drawText(QPointF(legendX + 18, legendY + metrics.ascent() / 2.0 - 1), curve.name);
        legendX += metrics.horizontalAdvance(curve.name) + 26;
    }
    painter.setClipRect(area.adjusted(-1, -1, 1, 1));
    for (const Curve& curve : m_curves)
    {
        QPainterPath path;
        bool started = false;
        for (std::size_t i = 0; i < std::min(curve.x.size(), curve.y.size()); ++i)
        {
            if (!std::isfinite(curve.x[i]) || !std::isfinite(curve.y[i]))
            {
                started = false; // a gap where a value is missing
                continue;
            }
            const QPointF p = toWidget(curve.x[i], curve.y[i]);
            started ? path.lineTo(p) : path.moveTo(p);
            started = true;
        }
        painter.setPen(QPen(curve.colour, 2.0));
        painter.drawPath(path);
    }
    if (m_cursor)
    {
        painter.setPen(QPen(QColor(230, 160, 0), 1.5, Qt::DashLine));
        const double cx = toWidget(*m_cursor, y0).x();
        painter.drawLine(QPointF(cx, area.top()), QPointF(cx, area.bottom()));
    }
}

void LinePlot::mousePressEvent(QMouseEvent* event)
{
    if (event->button() == Qt::LeftButton && plotArea().adjusted(-4, 0, 4, 0).contains(event->position()))
        emit clicked(xAt(event->position().x()));
}

void LinePlot::mouseMoveEvent(QMouseEvent* event)
{
    if ((event->buttons() & Qt::LeftButton) && plotArea().adjusted(-4, 0, 4, 0).contains(event->position()))
        emit clicked(xAt(event->position().x()));
}

} // namespace vsim::gui
