#pragma once

// The virtual endoscope (issue 20, item 8; thesis 5.5.2): a camera inside the lumen flying along a centerline
// segment (play / pause, speed in mm/s, forwards or backwards, a slider for the position), with the lens's
// focal length, focus distance and aperture; "Focus on Centre" sets the focus to the wall at the picture's
// centre. A flow run's particles show as blood cells when the run player plays one. The camera's position is
// announced so that the slice views follow it.
#include "SegmentChoices.h"
#include "vsim/core/SkeletonGraph.h"
#include "vsim/core/TriangleMesh.h"
#include "vsim/imaging/CurvedReformation.h"

#include <Eigen/Core>

#include <QWidget>

#include <string>
#include <vector>

class QComboBox;
class QDoubleSpinBox;
class QPushButton;
class QSlider;
class QTimer;

namespace vsim::viz {
class EndoscopeView;
}

namespace vsim::gui {

class EndoscopePanel : public QWidget
{
    Q_OBJECT

public:
    explicit EndoscopePanel(QWidget* parent = nullptr);

    /// The lumen surface the camera flies in and the centerlines it flies along (the longest segment first).
    void setData(const TriangleMesh& lumen, const SkeletonGraph& centerlines,
                 const std::vector<std::string>& names);
    bool hasData() const { return !m_frames.points.empty(); }
    /// One segment, or a path of segments across junctions (SegmentChoices.h), to fly along.
    void setSegment(int edge);
    void setPath(const VesselPath& path);
    /// The segment flown along; -1 on a path of several.
    int segment() const;
    const VesselPath& path() const { return m_path; }
    /// The camera at `arcMm` along the segment (clamped).
    void setArc(double arcMm);
    double arc() const { return m_arcMm; }
    /// +1 flies from the segment's start to its end, -1 back.
    void setDirection(int direction);
    int direction() const { return m_direction; }
    void setSpeed(double mmPerSecond);
    double speed() const;
    void setFocalLength(double mm);
    void setFocusDistance(double mm);
    /// Sets the focus distance to the depth of the wall at the picture's centre.
    void focusOnCentre();
    void play();
    void pause();
    bool playing() const;
    /// Advances the flight by `seconds` (the timer's step; tests call it directly).
    void advance(double seconds);
    /// A flow run's particles (mm) drawn as blood cells as wide as their typical spacing; an empty list
    /// clears them.
    void setParticles(const std::vector<Eigen::Vector3d>& pointsMm);
    viz::EndoscopeView* view() const { return m_view; }
    const imaging::CenterlineFrames& frames() const { return m_frames; }

signals:
    /// The camera moved (mm, patient frame).
    void positionChanged(const Eigen::Vector3d& pointMm);

private:
    void placeCamera();
    void applyLens();

    viz::EndoscopeView* m_view;
    QComboBox* m_segments;
    QPushButton* m_play;
    QComboBox* m_directionChoice;
    QDoubleSpinBox* m_speed;
    QSlider* m_position;
    QDoubleSpinBox* m_focalLength;
    QDoubleSpinBox* m_focus;
    QDoubleSpinBox* m_fNumber;
    QTimer* m_timer;
    SkeletonGraph m_centerlines;
    imaging::CenterlineFrames m_frames;
    VesselPath m_path;
    double m_arcMm = 0.0;
    int m_direction = 1;
};

} // namespace vsim::gui
