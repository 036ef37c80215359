#pragma once

#include "LinePlot.h"
#include "SegmentChoices.h"
#include "vsim/core/ImageVolume.h"
#include "vsim/core/SkeletonGraph.h"
#include "vsim/imaging/CurvedReformation.h"
#include "vsim/imaging/VesselMeasurements.h"

#include <QWidget>

#include <Eigen/Core>

class QComboBox;
class QSlider;

namespace vsim::viz {
class PlaneImageView;
}

namespace vsim::gui {

/// Along the vessel (the "3D + CPR" layout): for a centerline segment chosen by name, the straightened curved
/// planar reformation (Kanitsar 2002) that turns about the centerline (the angle slider), the cross-section
/// perpendicular to the centerline at the current arc position with the lumen caliper drawn on it (a circle of the
/// equivalent diameter of the measured cross-section nearest there, VesselMeasurements; without measurements, of the
/// centerline's inscribed radius, said so), and that diameter along the centerline as a plot. Clicking the
/// CPR or the plot, or the wheel over the cross-section, moves the arc position; every move reports the centerline
/// point (positionChanged) so that the MPRs go there.
class VesselViewPanel : public QWidget
{
    Q_OBJECT
public:
    explicit VesselViewPanel(QWidget* parent = nullptr);

    /// The CT and the centerlines with one name per segment (edge); the longest segment is chosen.
    void setData(const CtVolume& ct, const SkeletonGraph& centerlines, const std::vector<std::string>& names,
                 const imaging::VesselMeasurements* measured = nullptr);
    /// The lumen diameter the caliper draws at an arc position (mm), and whether it comes from a measured section.
    double lumenDiameterAt(double arcMm, bool* measured = nullptr) const;
    /// The AAA sac's labels (1 lumen, 4 thrombus, 5 wall; the sac step's label), or none: with them the
    /// cross-section draws the outer-wall caliper, the largest caliper of the labels' section (yellow).
    void setSacLabels(std::optional<LabelVolume> sacLabels);
    /// The outer-wall caliper at an arc position (mm), none without the sac or outside it.
    std::optional<imaging::PlaneCaliper> outerCaliperAt(double arcMm) const;
    void clear();
    bool hasData() const { return !m_frames.points.empty(); }

    /// One segment, or a path of segments across junctions (SegmentChoices.h), along the view.
    void setSegment(int edge);
    void setPath(const VesselPath& path);
    /// The segment shown; -1 on a path of several.
    int segment() const;
    const VesselPath& path() const { return m_path; }
    /// Moves to an arc position (mm from the segment's start; clamped).
    void setArc(double arcMm);
    double arc() const { return m_arcMm; }
    /// The rotation of the CPR and the cross-section about the centerline (degrees).
    void setAngle(double degrees);
    double angle() const { return m_angle; }
    /// The centerline point at the current position (mm, LPS).
    Eigen::Vector3d position() const;
    const imaging::CenterlineFrames& frames() const { return m_frames; }

    viz::PlaneImageView* reformationView() const { return m_cpr; }
    viz::PlaneImageView* crossSectionView() const { return m_section; }
    LinePlot* diameterPlot() const { return m_plot; }

signals:
    void positionChanged(const Eigen::Vector3d& pointMm);

private:
    void rebuildReformation();
    void refreshPosition();

    CtVolume m_ct;
    SkeletonGraph m_centerlines;
    std::optional<imaging::VesselMeasurements> m_measured;
    std::optional<LabelVolume> m_sacLabels;
    imaging::CenterlineFrames m_frames;
    VesselPath m_path;
    std::vector<std::pair<double, double>> m_pathSections; ///< (arc along the path, equivalent diameter) mm
    double m_arcMm = 0.0, m_angle = 0.0;
    QComboBox* m_segments = nullptr;
    QSlider* m_rotation = nullptr;
    viz::PlaneImageView* m_cpr = nullptr;
    viz::PlaneImageView* m_section = nullptr;
    LinePlot* m_plot = nullptr;
};

} // namespace vsim::gui
