#include "PlotPainter.h"

#include "vsim/core/Localized.h"

#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace vsim::report::detail {
namespace {

/// Tick positions: a 1, 2 or 5 times a power of ten step giving about `count` ticks over [low, high].
std::vector<double> ticks(double low, double high, int count)
{
    const double span = high - low;
    const double raw = span / std::max(1, count);
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    double step = power;
    for (double factor : {1.0, 2.0, 5.0, 10.0})
        if (factor * power >= raw)
        {
            step = factor * power;
            break;
        }
    std::vector<double> result;
    for (double t = std::ceil(low / step) * step; t <= high + 1e-9 * span; t += step)
        result.push_back(std::abs(t) < 1e-12 * span ? 0.0 : t);
    return result;
}

QString tickText(double value)
{
    return QString::fromStdString(localizedNumber(QString::number(value, 'g', 5).toStdString()));
}

const QColor kSeriesColours[] = {QColor(31, 119, 180), QColor(214, 39, 40), QColor(44, 160, 44), QColor(148, 103, 189),
                                 QColor(255, 127, 14)};

} // namespace

void paintPlot(QPainter& painter, const QRectF& area, const Plot& plot)
{
    double xLow = 1e300, xHigh = -1e300, yLow = 1e300, yHigh = -1e300;
    for (const PlotSeries& series : plot.series)
        for (const auto& [x, y] : series.points)
            xLow = std::min(xLow, x), xHigh = std::max(xHigh, x), yLow = std::min(yLow, y), yHigh = std::max(yHigh, y);
    for (const ReferenceLine& line : plot.references)
        yLow = std::min(yLow, line.y), yHigh = std::max(yHigh, line.y);
    if (!(xHigh > xLow))
        xLow -= 1.0, xHigh += 1.0;
    if (!(yHigh > yLow))
        yLow -= 1.0, yHigh += 1.0;
    const double yPad = 0.05 * (yHigh - yLow);
    yLow = yLow >= 0.0 && yLow - yPad < 0.0 ? 0.0 : yLow - yPad, yHigh += yPad;

    const QFontMetricsF metrics(painter.font());
    const double line = metrics.height();
    const QRectF frame(area.left() + 4.5 * line, area.top() + 0.5 * line, area.width() - 5.0 * line,
                       area.height() - 3.2 * line);
    auto toX = [&](double x) { return frame.left() + (x - xLow) / (xHigh - xLow) * frame.width(); };
    auto toY = [&](double y) { return frame.bottom() - (y - yLow) / (yHigh - yLow) * frame.height(); };

    painter.save();
    QPen axisPen(Qt::black, 0.0);
    QPen gridPen(QColor(220, 220, 220), 0.0);
    for (double t : ticks(xLow, xHigh, 8))
    {
        painter.setPen(gridPen);
        painter.drawLine(QPointF(toX(t), frame.top()), QPointF(toX(t), frame.bottom()));
        painter.setPen(axisPen);
        painter.drawText(QRectF(toX(t) - 3 * line, frame.bottom() + 0.2 * line, 6 * line, line), Qt::AlignCenter,
                         tickText(t));
    }
    for (double t : ticks(yLow, yHigh, 6))
    {
        painter.setPen(gridPen);
        painter.drawLine(QPointF(frame.left(), toY(t)), QPointF(frame.right(), toY(t)));
        painter.setPen(axisPen);
        painter.drawText(QRectF(frame.left() - 4.3 * line, toY(t) - 0.5 * line, 4.0 * line, line),
                         Qt::AlignRight | Qt::AlignVCenter, tickText(t));
    }
    painter.setPen(axisPen);
    painter.drawRect(frame);
    painter.drawText(QRectF(frame.left(), frame.bottom() + 1.3 * line, frame.width(), line), Qt::AlignCenter,
                     QString::fromStdString(plot.xLabel));
    painter.save();
    painter.translate(area.left() + 0.1 * line, frame.center().y());
    painter.rotate(-90.0);
    painter.drawText(QRectF(-frame.height() / 2, 0, frame.height(), line), Qt::AlignCenter,
                     QString::fromStdString(plot.yLabel));
    painter.restore();

    painter.setClipRect(frame);
    for (const ReferenceLine& reference : plot.references)
    {
        QPen dashed(QColor(120, 120, 120), 0.8 * line / 10.0, Qt::DashLine);
        painter.setPen(dashed);
        painter.drawLine(QPointF(frame.left(), toY(reference.y)), QPointF(frame.right(), toY(reference.y)));
        painter.drawText(QRectF(frame.left() + 0.3 * line, toY(reference.y) - 1.05 * line, frame.width(), line),
                         Qt::AlignLeft | Qt::AlignBottom, QString::fromStdString(reference.label));
    }
    for (std::size_t s = 0; s < plot.series.size(); ++s)
    {
        const PlotSeries& series = plot.series[s];
        if (series.points.empty())
            continue;
        QPainterPath path(QPointF(toX(series.points.front().first), toY(series.points.front().second)));
        for (const auto& [x, y] : series.points)
            path.lineTo(toX(x), toY(y));
        painter.setPen(QPen(kSeriesColours[s % std::size(kSeriesColours)], 1.6 * line / 10.0));
        painter.setBrush(Qt::NoBrush);
        if (series.points.size() == 1)
            painter.drawEllipse(path.currentPosition(), 0.2 * line, 0.2 * line);
        else
            painter.drawPath(path);
    }
    painter.setClipping(false);
    // Legend, top right inside the frame.
    double y = frame.top() + 0.3 * line;
    for (std::size_t s = 0; s < plot.series.size() && plot.series.size() > 1; ++s)
    {
        const QString name = QString::fromStdString(plot.series[s].name);
        const double width = metrics.horizontalAdvance(name);
        const double x = frame.right() - width - 2.5 * line;
        painter.setPen(QPen(kSeriesColours[s % std::size(kSeriesColours)], 1.6 * line / 10.0));
        painter.drawLine(QPointF(x, y + 0.5 * line), QPointF(x + 1.5 * line, y + 0.5 * line));
        painter.setPen(axisPen);
        painter.drawText(QRectF(x + 1.8 * line, y, width + line, line), Qt::AlignLeft | Qt::AlignVCenter, name);
        y += 1.1 * line;
    }
    painter.restore();
}

} // namespace vsim::report::detail
