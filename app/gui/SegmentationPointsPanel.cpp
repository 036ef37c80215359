#include "SegmentationPointsPanel.h"
#include "vsim/viz/DecimalText.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace vsim::gui {
namespace {

constexpr std::array<double, 3> kIncludeRgb{0.2, 1.0, 0.3};
constexpr std::array<double, 3> kExcludeRgb{1.0, 0.3, 0.3};
constexpr std::array<double, 3> kStopRgb{1.0, 0.85, 0.2};

/// The point's tag as drawn and listed: "+2" for the second include point, "x1" for the first exclude point.
QString tagOf(bool include, int number) { return QString("%1%2").arg(include ? "+" : "x").arg(number); }
/// A stop plane's tag: "|1" for the first.
QString stopTag(int number) { return QString("|%1").arg(number); }

} // namespace

SegmentationPointsPanel::SegmentationPointsPanel(QWidget* parent) : QWidget(parent)
{
    auto* layout = new QVBoxLayout(this);
    auto* form = new QFormLayout;
    m_target = new QComboBox(this);
    m_target->setObjectName("segmentationTarget");
    m_target->addItem(tr("Aorta (with its branches)"), int(imaging::SegmentationTarget::Aorta));
    m_target->addItem(tr("Hepatic arteries"), int(imaging::SegmentationTarget::Hepatic));
    m_target->addItem(tr("All vessels from the points"), int(imaging::SegmentationTarget::All));
    m_target->setToolTip(tr("Aorta: every aortic segment with its branches to a length (no point needed: the abdominal "
                            "aorta is found). Hepatic: a point in the aorta and one in the hepatic artery. All: every "
                            "contrast vessel connected to the points, up to the path length."));
    form->addRow(tr("Target"), m_target);
    m_maxLength = new QDoubleSpinBox(this);
    m_maxLength->setRange(0.0, 2000.0);
    m_maxLength->setDecimals(0);
    m_maxLength->setSuffix(" mm");
    m_maxLength->setSpecialValueText(tr("target's default"));
    m_maxLength->setToolTip(tr("Path length followed from the include points (0: aorta 1000 mm, hepatic 250 mm, all 150 mm)"));
    form->addRow(tr("Path length"), m_maxLength);
    layout->addLayout(form);

    auto* placing = new QHBoxLayout;
    m_placeInclude = new QPushButton(tr("Place Include"), this);
    m_placeExclude = new QPushButton(tr("Place Exclude"), this);
    m_placeInclude->setToolTip(tr("Click inside the vessel in any slice view to add an include point (drag a point to "
                                  "move it)"));
    m_placeExclude->setToolTip(tr("Click in what must stay out (heart chamber, vein, kidney, bone) to add an exclude "
                                  "point"));
    m_placeStop = new QPushButton(tr("Place Stop"), this);
    m_placeStop->setToolTip(tr("Click in a slice view where the vessel must end: a stop plane in that view's plane "
                               "through the point; the fronts do not cross it away from the include points"));
    for (QPushButton* button : {m_placeInclude, m_placeExclude, m_placeStop})
    {
        button->setCheckable(true);
        placing->addWidget(button);
    }
    connect(m_placeInclude, &QPushButton::clicked, this,
            [this](bool on) { setPlacing(on ? Placing::Include : Placing::None); });
    connect(m_placeExclude, &QPushButton::clicked, this,
            [this](bool on) { setPlacing(on ? Placing::Exclude : Placing::None); });
    connect(m_placeStop, &QPushButton::clicked, this, [this](bool on) { setPlacing(on ? Placing::Stop : Placing::None); });
    layout->addLayout(placing);

    m_table = new QTableWidget(0, 4, this);
    m_table->setObjectName("segmentationPoints");
    m_table->setHorizontalHeaderLabels({tr("Point"), tr("x (mm)"), tr("y (mm)"), tr("z (mm)")});
    m_table->horizontalHeaderItem(0)->setToolTip(tr("+N include point, xN exclude point, |N stop plane (its normal in "
                                                    "the tag's tooltip)"));
    for (int column = 1; column < 4; ++column)
        m_table->horizontalHeaderItem(column)->setToolTip(tr("Patient frame (LPS), mm"));
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->verticalHeader()->hide();
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    layout->addWidget(m_table);

    auto* buttons = new QHBoxLayout;
    auto* remove = new QPushButton(tr("Remove"), this);
    remove->setToolTip(tr("Remove the selected point"));
    connect(remove, &QPushButton::clicked, this, [this] {
        if (m_table->currentRow() >= 0)
            removePoint(m_table->currentRow());
    });
    auto* clear = new QPushButton(tr("Clear"), this);
    connect(clear, &QPushButton::clicked, this, [this] {
        m_points.clear();
        m_stops.clear();
        refreshTable();
    });
    m_segment = new QPushButton(tr("Segment", "verb: segment the vessels"), this);
    m_segment->setDefault(true);
    m_segment->setToolTip(tr("Segment from the points (a re-run replaces the label of the run before)"));
    connect(m_segment, &QPushButton::clicked, this, &SegmentationPointsPanel::runRequested);
    buttons->addWidget(remove);
    buttons->addWidget(clear);
    buttons->addStretch();
    buttons->addWidget(m_segment);
    layout->addLayout(buttons);
    m_rerun = new QCheckBox(tr("Re-run when a point moves"), this);
    m_rerun->setChecked(true);
    layout->addWidget(m_rerun);
}

imaging::SegmentationRequest SegmentationPointsPanel::request() const
{
    imaging::SegmentationRequest request;
    request.target = imaging::SegmentationTarget(m_target->currentData().toInt());
    for (const Point& point : m_points)
        (point.include ? request.includeMm : request.excludeMm).push_back(point.mm);
    request.stops = m_stops;
    if (m_maxLength->value() > 0.0)
        request.maxLengthMm = m_maxLength->value();
    return request;
}

void SegmentationPointsPanel::setRequest(const imaging::SegmentationRequest& request)
{
    m_target->setCurrentIndex(m_target->findData(int(request.target)));
    m_maxLength->setValue(request.maxLengthMm.value_or(0.0));
    m_stops = request.stops;
    m_points.clear();
    for (const Eigen::Vector3d& p : request.includeMm)
        m_points.push_back({p, true});
    for (const Eigen::Vector3d& p : request.excludeMm)
        m_points.push_back({p, false});
    refreshTable();
}

void SegmentationPointsPanel::addPoint(const Eigen::Vector3d& pointMm, bool include)
{
    m_points.push_back({pointMm, include});
    refreshTable();
    m_table->selectRow(int(m_points.size()) - 1);
}

void SegmentationPointsPanel::addStop(const Eigen::Vector3d& pointMm, const Eigen::Vector3d& planeNormal)
{
    Eigen::Vector3d normal = planeNormal.normalized(), centroid = Eigen::Vector3d::Zero();
    int includes = 0;
    for (const Point& point : m_points)
        if (point.include)
            centroid += point.mm, ++includes;
    if (includes > 0 && (centroid / includes - pointMm).dot(normal) > 0.0)
        normal = -normal;
    m_stops.push_back({pointMm, normal});
    refreshTable();
    m_table->selectRow(int(m_points.size() + m_stops.size()) - 1);
}

void SegmentationPointsPanel::movePoint(int id, const Eigen::Vector3d& pointMm)
{
    if (id < 0 || id >= int(m_points.size() + m_stops.size()))
        return;
    if (id < int(m_points.size()))
        m_points[std::size_t(id)].mm = pointMm;
    else
        m_stops[std::size_t(id) - m_points.size()].pointMm = pointMm;
    refreshTable();
    m_table->selectRow(id);
    if (rerunsOnMove())
        emit runRequested();
}

void SegmentationPointsPanel::removePoint(int id)
{
    if (id < 0 || id >= int(m_points.size() + m_stops.size()))
        return;
    if (id < int(m_points.size()))
        m_points.erase(m_points.begin() + id);
    else
        m_stops.erase(m_stops.begin() + (id - int(m_points.size())));
    refreshTable();
}

std::vector<viz::SliceMarker> SegmentationPointsPanel::markers() const
{
    std::vector<viz::SliceMarker> markers;
    int includes = 0, excludes = 0;
    for (std::size_t n = 0; n < m_points.size(); ++n)
    {
        const Point& point = m_points[n];
        viz::SliceMarker marker;
        marker.id = int(n);
        marker.pointMm = point.mm;
        marker.rgb = point.include ? kIncludeRgb : kExcludeRgb;
        marker.text = tagOf(point.include, point.include ? ++includes : ++excludes).toStdString();
        markers.push_back(marker);
    }
    for (std::size_t n = 0; n < m_stops.size(); ++n)
    {
        viz::SliceMarker marker;
        marker.id = int(m_points.size() + n);
        marker.pointMm = m_stops[n].pointMm;
        marker.rgb = kStopRgb;
        marker.text = stopTag(int(n) + 1).toStdString();
        markers.push_back(marker);
    }
    return markers;
}

void SegmentationPointsPanel::setPlacing(Placing placing)
{
    m_placing = placing;
    m_placeInclude->setChecked(placing == Placing::Include);
    m_placeExclude->setChecked(placing == Placing::Exclude);
    m_placeStop->setChecked(placing == Placing::Stop);
    emit placingChanged(placing);
}

bool SegmentationPointsPanel::rerunsOnMove() const { return m_rerun->isChecked(); }

void SegmentationPointsPanel::refreshTable()
{
    const std::vector<viz::SliceMarker> tags = markers();
    m_table->setRowCount(int(tags.size()));
    for (std::size_t n = 0; n < tags.size(); ++n)
    {
        auto* tag = new QTableWidgetItem(QString::fromStdString(tags[n].text));
        if (n >= m_points.size())
        {
            const Eigen::Vector3d& normal = m_stops[n - m_points.size()].normal;
            tag->setToolTip(tr("Stop plane, normal (%1, %2, %3) towards the side the fronts do not enter")
                                .arg(viz::decimalText(normal.x(), 2))
                                    .arg(viz::decimalText(normal.y(), 2))
                                    .arg(viz::decimalText(normal.z(), 2)));
        }
        m_table->setItem(int(n), 0, tag);
        for (int axis = 0; axis < 3; ++axis)
            m_table->setItem(int(n), axis + 1, new QTableWidgetItem(viz::decimalText(tags[n].pointMm[axis], 1)));
    }
    emit pointsChanged();
}

} // namespace vsim::gui
