#include "RunPlayer.h"

#include "FieldTitles.h"

#include "vsim/viz/DecimalText.h"

#include <QCheckBox>
#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSlider>
#include <QStyle>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace vsim::gui {

RunPlayer::RunPlayer(QWidget* parent)
    : QWidget(parent), m_timer(new QTimer(this)), m_play(new QPushButton(this)), m_slider(new QSlider(Qt::Horizontal, this)),
      m_label(new QLabel(this)), m_speed(new QComboBox(this)), m_loop(new QCheckBox(tr("Loop"), this)),
      m_field(new QComboBox(this)), m_perFrame(new QCheckBox(tr("Range per frame"), this))
{
    setObjectName("runPlayer");
    auto* back = new QPushButton(style()->standardIcon(QStyle::SP_MediaSeekBackward), QString(), this);
    auto* forward = new QPushButton(style()->standardIcon(QStyle::SP_MediaSeekForward), QString(), this);
    back->setToolTip(tr("Previous frame"));
    forward->setToolTip(tr("Next frame"));
    m_play->setObjectName("runPlay");
    m_play->setIcon(style()->standardIcon(QStyle::SP_MediaPlay));
    m_play->setToolTip(tr("Play / pause"));
    m_slider->setObjectName("runSlider");
    for (double speed : {0.25, 0.5, 1.0, 2.0, 4.0})
        m_speed->addItem(QString("%1x").arg(speed), speed);
    m_speed->setCurrentIndex(2);
    m_speed->setToolTip(tr("Playback speed (1x = %1 frames per second)").arg(kFramesPerSecond));
    m_field->setToolTip(tr("The field the frames are coloured by"));
    m_perFrame->setToolTip(tr("Scale the legend to each frame instead of the whole run"));

    auto* buttons = new QHBoxLayout;
    for (QWidget* w : std::initializer_list<QWidget*>{back, m_play, forward, m_slider})
        buttons->addWidget(w);
    auto* options = new QHBoxLayout;
    for (QWidget* w : std::initializer_list<QWidget*>{m_speed, m_loop, m_field, m_perFrame})
        options->addWidget(w);
    options->addStretch();
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(buttons);
    layout->addWidget(m_label);
    layout->addLayout(options);

    connect(m_play, &QPushButton::clicked, this, [this] { isPlaying() ? pause() : play(); });
    connect(back, &QPushButton::clicked, this, &RunPlayer::stepBack);
    connect(forward, &QPushButton::clicked, this, &RunPlayer::stepForward);
    connect(m_slider, &QSlider::valueChanged, this, &RunPlayer::setFrame);
    connect(m_timer, &QTimer::timeout, this, &RunPlayer::advance);
    connect(m_speed, &QComboBox::currentIndexChanged, this, [this] { setSpeed(speed()); });
    connect(m_field, &QComboBox::currentIndexChanged, this, &RunPlayer::appearanceChanged);
    connect(m_perFrame, &QCheckBox::toggled, this, &RunPlayer::appearanceChanged);
}

void RunPlayer::setFrames(std::vector<double> positions, const QString& quantity, const QString& unit,
                          const QStringList& fields)
{
    pause();
    m_positions = std::move(positions);
    m_quantity = quantity, m_unit = unit;
    {
        const QSignalBlocker blockField(m_field), blockSlider(m_slider);
        m_field->clear();
        for (const QString& key : fields)
            m_field->addItem(fieldTitle(key), key);
        m_field->setVisible(!fields.isEmpty()); // a player of one picture (the drug dock's tracers) has none
        m_perFrame->setVisible(!fields.isEmpty());
        m_slider->setRange(0, std::max(0, frameCount() - 1));
        m_slider->setValue(0);
    }
    m_frame = -1;
    setFrame(0);
}

bool RunPlayer::isPlaying() const { return m_timer->isActive(); }

int RunPlayer::frameNearest(double position) const
{
    int nearest = 0;
    for (int f = 1; f < frameCount(); ++f)
        if (std::abs(m_positions[std::size_t(f)] - position) < std::abs(m_positions[std::size_t(nearest)] - position))
            nearest = f;
    return nearest;
}

QString RunPlayer::axisTitle() const { return m_unit.isEmpty() ? m_quantity : QString("%1 (%2)").arg(m_quantity, m_unit); }
double RunPlayer::speed() const { return m_speed->currentData().toDouble(); }
bool RunPlayer::loops() const { return m_loop->isChecked(); }
QString RunPlayer::field() const { return m_field->currentData().toString(); }
QString RunPlayer::fieldText() const { return m_field->currentText(); }
bool RunPlayer::rangePerFrame() const { return m_perFrame->isChecked(); }

QString RunPlayer::frameText() const
{
    if (m_positions.empty())
        return tr("no frames");
    return tr("frame %1 / %2, %3 %4 %5")
        .arg(m_frame + 1)
        .arg(frameCount())
        .arg(m_quantity)
        .arg(viz::significantText(m_positions[std::size_t(m_frame)], 4))
        .arg(m_unit);
}

void RunPlayer::setFrame(int frame)
{
    frame = std::clamp(frame, 0, std::max(0, frameCount() - 1));
    if (frame == m_frame)
        return;
    m_frame = frame;
    {
        const QSignalBlocker block(m_slider);
        m_slider->setValue(frame);
    }
    m_label->setText(frameText());
    emit frameChanged(frame);
}

void RunPlayer::play()
{
    if (frameCount() < 2)
        return;
    if (m_frame == frameCount() - 1 && !loops())
        setFrame(0);
    m_timer->start(int(std::lround(1000.0 / (kFramesPerSecond * speed()))));
    m_play->setIcon(style()->standardIcon(QStyle::SP_MediaPause));
}

void RunPlayer::pause()
{
    m_timer->stop();
    m_play->setIcon(style()->standardIcon(QStyle::SP_MediaPlay));
}

void RunPlayer::stepForward() { setFrame(m_frame + 1); }
void RunPlayer::stepBack() { setFrame(m_frame - 1); }

void RunPlayer::setSpeed(double speed)
{
    const int index = m_speed->findData(speed);
    if (index >= 0 && index != m_speed->currentIndex())
        m_speed->setCurrentIndex(index);
    if (isPlaying())
        m_timer->setInterval(int(std::lround(1000.0 / (kFramesPerSecond * this->speed()))));
}

void RunPlayer::setLoop(bool loop) { m_loop->setChecked(loop); }

void RunPlayer::advance()
{
    if (m_frame + 1 < frameCount())
    {
        setFrame(m_frame + 1);
        if (m_frame + 1 == frameCount() && !loops())
            pause(); // stopped as the last frame shows, not a tick later
    }
    else if (loops())
        setFrame(0);
    else
        pause();
}

} // namespace vsim::gui
