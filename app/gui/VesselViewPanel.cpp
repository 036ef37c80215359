#include "VesselViewPanel.h"

#include "SegmentChoices.h"

#include "vsim/viz/DecimalText.h"
#include "vsim/viz/PlaneImageView.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <QVBoxLayout>

#include <algorithm>

namespace vsim::gui {
namespace {

constexpr double kArcStepMm = 0.5;           // arc step of the CPR rows and of a wheel notch
constexpr double kHalfWidthMm = 25.0;     // the CPR and the cross-section span +-25 mm about the centerline
constexpr double kSectionPixelMm = 0.25;

} // namespace

VesselViewPanel::VesselViewPanel(QWidget* parent) : QWidget(parent)
{
    setObjectName("vesselViewPanel");
    m_segments = new QComboBox(this);
    m_segments->setObjectName("vesselSegment");
    m_segments->setToolTip(tr("The centerline segment shown along its length"));
    m_rotation = new QSlider(Qt::Horizontal, this);
    m_rotation->setObjectName("vesselRotation");
    m_rotation->setRange(0, 179);
    m_rotation->setToolTip(tr("Rotation of the curved reformation about the centerline (degrees)"));
    m_cpr = new viz::PlaneImageView(this);
    m_cpr->setObjectName("vesselReformation");
    m_section = new viz::PlaneImageView(this);
    m_section->setObjectName("vesselCrossSection");
    m_plot = new LinePlot(this);
    m_plot->setObjectName("vesselDiameterPlot");
    m_plot->setAxes(tr("distance along the centerline (mm)"), tr("lumen diameter (mm)"));

    auto* controls = new QHBoxLayout;
    controls->addWidget(new QLabel(tr("Segment"), this));
    controls->addWidget(m_segments, 1);
    controls->addWidget(new QLabel(tr("Rotation"), this));
    controls->addWidget(m_rotation, 1);
    auto* pictures = new QHBoxLayout;
    pictures->addWidget(m_cpr, 1);
    pictures->addWidget(m_section, 1);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->addLayout(controls);
    layout->addLayout(pictures, 3);
    layout->addWidget(m_plot, 1);

    connect(m_segments, &QComboBox::currentIndexChanged, this, [this](int index) {
        if (index >= 0)
            setPath(m_segments->itemData(index).toList());
    });
    connect(m_rotation, &QSlider::valueChanged, this, [this](int degrees) { setAngle(degrees); });
    connect(m_cpr, &viz::PlaneImageView::clicked, this, [this](const QPointF& mm) { setArc(mm.y()); });
    connect(m_plot, &LinePlot::clicked, this, [this](double x) { setArc(x); });
    connect(m_section, &viz::PlaneImageView::stepped, this, [this](int steps) { setArc(m_arcMm + steps * kArcStepMm); });
}

void VesselViewPanel::setData(const CtVolume& ct, const SkeletonGraph& centerlines, const std::vector<std::string>& names,
                              const imaging::VesselMeasurements* measured)
{
    m_ct = ct;
    m_centerlines = centerlines;
    m_measured.reset();
    if (measured && measured->segments.size() == centerlines.edges.size())
        m_measured = *measured;
    const QSignalBlocker quiet(m_segments);
    const int longest = fillSegmentChoices(m_segments, centerlines, names);
    m_path = {};
    if (longest >= 0)
    {
        m_segments->setCurrentIndex(longest);
        setPath(m_segments->itemData(longest).toList());
    }
}

void VesselViewPanel::clear()
{
    m_frames = {};
    m_path = {};
    m_pathSections.clear();
    m_segments->clear();
    m_cpr->setPicture(0, 0, 1.0, {});
    m_section->setPicture(0, 0, 1.0, {});
    m_plot->setCurves({});
}

void VesselViewPanel::setSegment(int edge) { setPath(VesselPath{edge + 1}); }

int VesselViewPanel::segment() const { return singleSegment(m_path); }

void VesselViewPanel::setPath(const VesselPath& path)
{
    if (!adoptPath(m_centerlines, path, kArcStepMm, m_segments, m_path, m_frames))
        return;
    // The measured sections of the path's segments, at their arc along the path (a segment run backwards counts
    // from its end).
    m_pathSections.clear();
    double offsetMm = 0.0;
    for (const QVariant& step : path)
    {
        const std::size_t edge = std::size_t(std::abs(step.toInt()) - 1);
        const double lengthMm = m_centerlines.edges[edge].length();
        if (m_measured)
            for (const imaging::CrossSection& section : m_measured->segments[edge].sections)
                m_pathSections.emplace_back(offsetMm + (step.toInt() > 0 ? section.arcLengthMm : lengthMm - section.arcLengthMm),
                                            section.equivalentDiameterMm);
        offsetMm += lengthMm;
    }
    std::sort(m_pathSections.begin(), m_pathSections.end());
    const bool fromSections = !m_pathSections.empty();
    LinePlot::Curve diameter{fromSections ? tr("lumen equivalent diameter (measured sections)")
                                          : tr("lumen diameter (2 x the centerline's radius: reads low)"),
                             QColor(60, 170, 230), {}, {}};
    if (fromSections)
        for (const auto& [arcMm, diameterMm] : m_pathSections)
        {
            diameter.x.push_back(arcMm);
            diameter.y.push_back(diameterMm);
        }
    else
        for (std::size_t i = 0; i < m_frames.points.size(); ++i)
        {
            diameter.x.push_back(m_frames.arcMm[i]);
            diameter.y.push_back(2.0 * m_frames.radiiMm[i]);
        }
    m_plot->setCurves({diameter});
    rebuildReformation();
    m_arcMm = -1.0;
    setArc(0.5 * m_frames.lengthMm());
}

void VesselViewPanel::setAngle(double degrees)
{
    m_angle = degrees;
    if (m_rotation->value() != int(std::lround(degrees)))
    {
        const QSignalBlocker quiet(m_rotation);
        m_rotation->setValue(int(std::lround(degrees)));
    }
    rebuildReformation();
    refreshPosition();
}

void VesselViewPanel::setArc(double arcMm)
{
    if (m_frames.points.empty())
        return;
    const double arc = m_frames.arcMm[m_frames.indexAt(arcMm)];
    if (arc == m_arcMm)
        return;
    m_arcMm = arc;
    refreshPosition();
    emit positionChanged(position());
}

double VesselViewPanel::lumenDiameterAt(double arcMm, bool* measured) const
{
    if (measured)
        *measured = !m_pathSections.empty();
    if (m_pathSections.empty())
        return m_frames.points.empty() ? 0.0 : 2.0 * m_frames.radiiMm[m_frames.indexAt(arcMm)];
    const auto nearest = std::min_element(m_pathSections.begin(), m_pathSections.end(), [&](const auto& a, const auto& b) {
        return std::abs(a.first - arcMm) < std::abs(b.first - arcMm);
    });
    return nearest->second;
}

void VesselViewPanel::setSacLabels(std::optional<LabelVolume> sacLabels)
{
    m_sacLabels = std::move(sacLabels);
    refreshPosition();
}

std::optional<imaging::PlaneCaliper> VesselViewPanel::outerCaliperAt(double arcMm) const
{
    if (!m_sacLabels || m_frames.points.empty())
        return std::nullopt;
    return imaging::largestCaliper(
        imaging::labelCrossSection(*m_sacLabels, m_frames, arcMm, kHalfWidthMm, kSectionPixelMm, m_angle));
}

Eigen::Vector3d VesselViewPanel::position() const
{
    return m_frames.points.empty() ? Eigen::Vector3d::Zero() : m_frames.points[m_frames.indexAt(m_arcMm)];
}

void VesselViewPanel::rebuildReformation()
{
    if (m_frames.points.empty() || m_ct.isEmpty())
        return;
    const imaging::PlaneImage cpr = imaging::straightenedReformation(m_ct, m_frames, kHalfWidthMm, m_angle);
    m_cpr->setPicture(cpr.width, cpr.height, cpr.pixelMm, cpr.values);
    m_cpr->setCaption(tr("Straightened CPR, %1 deg\n%2 mm of centerline")
        .arg(viz::decimalText(m_angle, 0))
        .arg(viz::decimalText(m_frames.lengthMm(), 0)));
}

void VesselViewPanel::refreshPosition()
{
    if (m_frames.points.empty() || m_ct.isEmpty())
        return;
    const imaging::PlaneImage section = imaging::crossSection(m_ct, m_frames, m_arcMm, kHalfWidthMm, kSectionPixelMm, m_angle);
    m_section->setPicture(section.width, section.height, section.pixelMm, section.values);
    bool measured = false;
    const double diameter = lumenDiameterAt(m_arcMm, &measured);
    m_section->setCentreCircle(diameter > 0.0 ? std::optional<double>(0.5 * diameter) : std::nullopt);
    QString caption = tr("Perpendicular to the centerline at %1 mm\nlumen %2 mm (circle: %3)")
                          .arg(viz::decimalText(m_arcMm, 1))
                          .arg(viz::decimalText(diameter, 1))
                          .arg(measured ? tr("equivalent diameter of the measured section")
                                        : tr("2 x the centerline's radius, which reads low; run the measurements"));
    const std::optional<imaging::PlaneCaliper> outer = outerCaliperAt(m_arcMm);
    m_section->setCaliper(outer ? std::optional(std::pair{QPointF(outer->fromMm.x(), outer->fromMm.y()),
                                                          QPointF(outer->toMm.x(), outer->toMm.y())})
                                : std::nullopt);
    if (outer)
        caption += '\n' + tr("outer wall %1 mm (yellow: the largest caliper of the sac's labels here)")
            .arg(viz::decimalText(outer->lengthMm, 1));
    m_section->setCaption(caption);
    m_cpr->setMarkerRow(m_arcMm);
    m_plot->setCursor(m_arcMm);
}

} // namespace vsim::gui
