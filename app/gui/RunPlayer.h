#pragma once

// The one time player of the workstation (issue 17): plays any Run artifact's kept frames. Play / pause, step back
// and forward, a slider to scrub, speed (frames per second x 0.25 .. 4), loop, the field to colour by and whether the
// legend's range is fixed over the run or follows each frame. It only counts frames and says which one to show: the
// main window draws it (MainWindowRuns.cpp), so the same player serves the wall, the drug filling and the solvers to
// come.

#include <QWidget>

#include <vector>

class QCheckBox;
class QComboBox;
class QLabel;
class QPushButton;
class QSlider;
class QTimer;

namespace vsim::gui {

class RunPlayer : public QWidget
{
    Q_OBJECT
public:
    /// Frames shown per second at speed 1.
    static constexpr double kFramesPerSecond = 10.0;

    explicit RunPlayer(QWidget* parent = nullptr);

    /// A new run: each kept frame's position on the run's axis (`quantity` in `unit`), the fields to colour by (the
    /// first is chosen); the player stops at frame 0.
    void setFrames(std::vector<double> positions, const QString& quantity, const QString& unit, const QStringList& fields);

    int frame() const { return m_frame; }
    int frameCount() const { return int(m_positions.size()); }
    /// The frames' positions on the run's axis, and the frame nearest to `position`.
    const std::vector<double>& positions() const { return m_positions; }
    int frameNearest(double position) const;
    /// "pressure (kPa)", "time (s)".
    QString axisTitle() const;
    bool isPlaying() const;
    double speed() const;
    bool loops() const;
    /// The field the frames are coloured by: its key (as the frames name it), and its title for people.
    QString field() const;
    QString fieldText() const;
    /// True when the legend follows each frame's own range instead of the run's.
    bool rangePerFrame() const;
    /// "frame 3 / 21, time 0.150 s".
    QString frameText() const;
    QSlider* slider() const { return m_slider; }

public slots:
    void setFrame(int frame);
    void play();
    void pause();
    void stepForward();
    void stepBack();
    void setSpeed(double speed);
    void setLoop(bool loop);

signals:
    void frameChanged(int frame);
    /// The field or the legend's range mode changed: draw the frame again.
    void appearanceChanged();

private:
    void advance();

    std::vector<double> m_positions;
    QString m_quantity, m_unit;
    int m_frame = 0;
    QTimer* m_timer;
    QPushButton* m_play;
    QSlider* m_slider;
    QLabel* m_label;
    QComboBox* m_speed;
    QCheckBox* m_loop;
    QComboBox* m_field;
    QCheckBox* m_perFrame;
};

} // namespace vsim::gui
