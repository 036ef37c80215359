#pragma once

// A small line plot for the workstation's docks: curves of (x, y) with the axes' quantities and units, a
// cursor (the played frame's position) and a click that reports where on the x axis it fell, so that a plot
// can scrub a run. Used by the Run Player (a field's peak and mean over the run); blood-flow profiles along
// the centerline come next.

#include <QColor>
#include <QString>
#include <QWidget>

#include <optional>
#include <vector>

namespace vsim::gui {

class LinePlot : public QWidget
{
    Q_OBJECT
public:
    struct Curve
    {
        QString name;
        QColor colour;
        std::vector<double> x, y;
    };

    explicit LinePlot(QWidget* parent = nullptr);

    /// The axes' titles, e.g. "pressure (kPa)" and "von_mises_kpa".
    void setAxes(const QString& xTitle, const QString& yTitle);
    void setCurves(std::vector<Curve> curves);
    const std::vector<Curve>& curves() const { return m_curves; }
    /// The vertical cursor at `x` (none: hidden).
    void setCursor(std::optional<double> x);
    std::optional<double> cursor() const { return m_cursor; }
    /// The x value under a widget position (within the plotted range).
    double xAt(double widgetX) const;
    /// The widget x of a value on the x axis.
    double widgetXOf(double x) const;

    QSize sizeHint() const override { return {360, 160}; }

signals:
    /// The user clicked or dragged in the plot at `x` (x axis units).
    void clicked(double x);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;

private:
    QRectF plotArea() const;
    void dataRange(double& x0, double& x1, double& y0, double& y1) const;

    QString m_xTitle, m_yTitle;
    std::vector<Curve> m_curves;
    std::optional<double> m_cursor;
};

} // namespace vsim::gui
