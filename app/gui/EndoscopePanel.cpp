// EndoscopePanel.h: the flight along rotation-minimising frames (CurvedReformation.h) and the lens's
// controls.
#include "EndoscopePanel.h"

#include "SegmentChoices.h"
#include "vsim/viz/EndoscopeView.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <limits>

namespace vsim::gui {
namespace {

constexpr double kFlightStepMm = 0.25; // the frames' arc step: the slider's resolution
constexpr int kTimerMs = 50;     // 20 camera moves a second while playing

QDoubleSpinBox* spinBox(QWidget* parent, const char* name, double low, double high, double value, double step,
                        const QString& suffix, const QString& tip)
{
    auto* box = new QDoubleSpinBox(parent);
    box->setObjectName(name);
    box->setRange(low, high);
    box->setSingleStep(step);
    box->setDecimals(step < 1.0 ? 1 : 0);
    box->setValue(value);
    box->setSuffix(suffix);
    box->setToolTip(tip);
    return box;
}

} // namespace

EndoscopePanel::EndoscopePanel(QWidget* parent) : QWidget(parent)
{
    setObjectName("endoscopePanel");
    m_view = new viz::EndoscopeView(this);
    m_view->setObjectName("endoscopeView");
    m_segments = new QComboBox(this);
    m_segments->setObjectName("endoscopeSegment");
    m_segments->setToolTip(tr("The centerline segment the camera flies along"));
    m_play = new QPushButton(tr("Play"), this);
    m_play->setObjectName("endoscopePlay");
    m_play->setCheckable(true);
    m_play->setToolTip(tr("Fly the camera along the segment at the speed set"));
    m_directionChoice = new QComboBox(this);
    m_directionChoice->setObjectName("endoscopeDirection");
    m_directionChoice->addItem(tr("Forwards (start to end)"), 1);
    m_directionChoice->addItem(tr("Backwards (end to start)"), -1);
    m_speed = spinBox(this, "endoscopeSpeed", 1.0, 50.0, 10.0, 1.0, tr(" mm/s"),
                      tr("Flight speed along the centerline (mm per second)"));
    m_position = new QSlider(Qt::Horizontal, this);
    m_position->setObjectName("endoscopePosition");
    m_position->setToolTip(tr("The camera's position along the segment (mm from its start)"));
    const viz::EndoscopeLens lens;
    m_focalLength =
        spinBox(this, "endoscopeFocalLength", 1.0, 8.0, lens.focalLengthMm, 0.1, tr(" mm"),
                tr("Focal length of the probe's lens (mm): longer narrows the field of view (4 mm sensor)"));
    m_focus =
        spinBox(this, "endoscopeFocus", 2.0, 150.0, lens.focusDistanceMm, 0.5, tr(" mm"),
                tr("Distance in focus (mm along the view); out of focus the picture blurs and grows noisy"));
    m_fNumber =
        spinBox(this, "endoscopeAperture", 1.0, 16.0, lens.fNumber, 0.1, QString(),
                tr("Aperture as an f-number: smaller lets in more light and shortens the depth of field"));
    auto* focusCentre = new QPushButton(tr("Focus on Centre"), this);
    focusCentre->setObjectName("endoscopeFocusCentre");
    focusCentre->setToolTip(tr("Set the focus distance to the wall at the picture's centre"));

    auto* flight = new QHBoxLayout;
    flight->addWidget(m_play);
    flight->addWidget(m_directionChoice);
    flight->addWidget(m_speed);
    flight->addWidget(m_position, 1);
    auto* optics = new QFormLayout;
    optics->addRow(tr("Segment"), m_segments);
    optics->addRow(tr("Focal length"), m_focalLength);
    optics->addRow(tr("Focus distance"), m_focus);
    optics->addRow(tr("Aperture (f-number)"), m_fNumber);
    optics->addRow(focusCentre);
    auto* top = new QHBoxLayout;
    top->addWidget(m_view, 1);
    top->addLayout(optics);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->addLayout(top, 1);
    layout->addLayout(flight);

    m_timer = new QTimer(this);
    m_timer->setInterval(kTimerMs);
    connect(m_timer, &QTimer::timeout, this, [this] { advance(kTimerMs / 1000.0); });
    connect(m_play, &QPushButton::toggled, this, [this](bool on) { on ? play() : pause(); });
    connect(m_directionChoice, &QComboBox::currentIndexChanged, this,
            [this](int index) { setDirection(m_directionChoice->itemData(index).toInt()); });
    connect(m_segments, &QComboBox::currentIndexChanged, this,
            [this](int index)
            {
                if (index >= 0)
                    setPath(m_segments->itemData(index).toList());
            });
    connect(m_position, &QSlider::valueChanged, this, [this](int step) { setArc(step * kFlightStepMm); });
    for (QDoubleSpinBox* box : {m_focalLength, m_focus, m_fNumber})
        connect(box, &QDoubleSpinBox::valueChanged, this, [this] { applyLens(); });
    connect(focusCentre, &QPushButton::clicked, this, [this] { focusOnCentre(); });
    applyLens();
}

void EndoscopePanel::setData(const TriangleMesh& lumen, const SkeletonGraph& centerlines,
                             const std::vector<std::string>& names)
{
    pause();
    m_view->setLumen(lumen);
    m_centerlines = centerlines;
    m_path = {};
    m_frames = {};
    const QSignalBlocker quiet(m_segments);
    const int longest = fillSegmentChoices(m_segments, centerlines, names);
    if (longest >= 0)
        setPath(m_segments->itemData(longest).toList());
}

void EndoscopePanel::setSegment(int edge) { setPath(VesselPath{edge + 1}); }

int EndoscopePanel::segment() const { return singleSegment(m_path); }

void EndoscopePanel::setPath(const VesselPath& path)
{
    if (!adoptPath(m_centerlines, path, kFlightStepMm, m_segments, m_path, m_frames))
        return;
    {
        const QSignalBlocker quiet(m_position);
        m_position->setRange(0, int(m_frames.points.size()) - 1);
    }
    setArc(m_direction > 0 ? 0.0 : m_frames.lengthMm());
}

void EndoscopePanel::setArc(double arcMm)
{
    if (m_frames.points.empty())
        return;
    m_arcMm = std::clamp(arcMm, 0.0, m_frames.lengthMm());
    const QSignalBlocker quiet(m_position);
    m_position->setValue(int(m_frames.indexAt(m_arcMm)));
    placeCamera();
}

void EndoscopePanel::setDirection(int direction)
{
    m_direction = direction < 0 ? -1 : 1;
    if (const int index = m_directionChoice->findData(m_direction);
        index != m_directionChoice->currentIndex())
    {
        const QSignalBlocker quiet(m_directionChoice);
        m_directionChoice->setCurrentIndex(index);
    }
    placeCamera();
}

void EndoscopePanel::setSpeed(double mmPerSecond)
{
    m_speed->setValue(mmPerSecond);
}

double EndoscopePanel::speed() const
{
    return m_speed->value();
}

void EndoscopePanel::setFocalLength(double mm)
{
    m_focalLength->setValue(mm);
}

void EndoscopePanel::setFocusDistance(double mm)
{
    m_focus->setValue(mm);
}

void EndoscopePanel::focusOnCentre()
{
    const QImage shown = m_view->picture(); // rendered for the pose shown now, with its depth
    const std::vector<float>& depth = m_view->depthMm();
    if (depth.empty())
        return;
    // The nearest wall within the picture's central tenth: what a probe's centre-weighted autofocus would
    // pick.
    const int width = shown.width(), height = shown.height(), half = std::max(1, width / 20);
    float nearest = std::numeric_limits<float>::infinity();
    for (int y = height / 2 - half; y <= height / 2 + half; ++y)
        for (int x = width / 2 - half; x <= width / 2 + half; ++x)
            if (x >= 0 && y >= 0 && x < width && y < height)
                nearest = std::min(nearest, depth[std::size_t(y) * std::size_t(width) + std::size_t(x)]);
    if (std::isfinite(nearest))
        setFocusDistance(nearest);
}

void EndoscopePanel::play()
{
    if (m_frames.points.empty())
        return;
    const bool atEnd = m_direction > 0 ? m_arcMm >= m_frames.lengthMm() : m_arcMm <= 0.0;
    if (atEnd)
        setArc(m_direction > 0 ? 0.0 : m_frames.lengthMm());
    m_timer->start();
    const QSignalBlocker quiet(m_play);
    m_play->setChecked(true);
    m_play->setText(tr("Pause"));
}

void EndoscopePanel::pause()
{
    m_timer->stop();
    const QSignalBlocker quiet(m_play);
    m_play->setChecked(false);
    m_play->setText(tr("Play"));
}

bool EndoscopePanel::playing() const
{
    return m_timer->isActive();
}

void EndoscopePanel::advance(double seconds)
{
    if (m_frames.points.empty())
        return;
    setArc(m_arcMm + m_direction * speed() * seconds);
    if (m_arcMm <= 0.0 || m_arcMm >= m_frames.lengthMm())
        pause(); // the segment's end
}

void EndoscopePanel::setParticles(const std::vector<Eigen::Vector3d>& pointsMm)
{
    // The typical spacing: the median distance to the nearest neighbour of up to 64 particles spread over the
    // list.
    std::vector<double> nearest;
    const std::size_t stride = std::max<std::size_t>(1, pointsMm.size() / 64);
    for (std::size_t i = 0; i < pointsMm.size() && pointsMm.size() > 1; i += stride)
    {
        double best = std::numeric_limits<double>::infinity();
        for (std::size_t j = 0; j < pointsMm.size(); ++j)
            if (j != i)
                best = std::min(best, (pointsMm[j] - pointsMm[i]).squaredNorm());
        nearest.push_back(std::sqrt(best));
    }
    std::nth_element(nearest.begin(), nearest.begin() + std::ptrdiff_t(nearest.size() / 2), nearest.end());
    const double spacingMm = nearest.empty() ? 1.0 : nearest[nearest.size() / 2];
    m_view->setParticles(pointsMm, spacingMm / 2.0);
}

void EndoscopePanel::placeCamera()
{
    if (m_frames.points.empty())
        return;
    // Interpolated between the frames about the arc position, so that slow flights move smoothly.
    const double at = m_arcMm / m_frames.stepMm;
    const std::size_t i = std::min(std::size_t(std::floor(at)), m_frames.points.size() - 1);
    const std::size_t j = std::min(i + 1, m_frames.points.size() - 1);
    const double t = std::clamp(at - double(i), 0.0, 1.0);
    const Eigen::Vector3d position = (1.0 - t) * m_frames.points[i] + t * m_frames.points[j];
    const Eigen::Vector3d forward =
        (m_direction * ((1.0 - t) * m_frames.tangents[i] + t * m_frames.tangents[j])).normalized();
    Eigen::Vector3d up = (1.0 - t) * m_frames.normals[i] + t * m_frames.normals[j];
    up = (up - up.dot(forward) * forward).normalized();
    m_view->setPose(position, forward, up);
    emit positionChanged(position);
}

void EndoscopePanel::applyLens()
{
    viz::EndoscopeLens lens = m_view->lens();
    lens.focalLengthMm = m_focalLength->value();
    lens.focusDistanceMm = m_focus->value();
    lens.fNumber = m_fNumber->value();
    m_view->setLens(lens);
}

} // namespace vsim::gui
