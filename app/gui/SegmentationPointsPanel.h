#pragma once

// The Segmentation Points dock: the guided segmentation's request as the user builds it on the MPR views (as in
// 3D Slicer's markups): the target, include points (green, "+N") and exclude points (red, "xN") placed with a click
// while Place Include / Place Exclude is on, dragged to move them, listed with their position; Segment runs it, and
// with "Re-run when a point moves" on, moving a point runs it again.

#include "vsim/imaging/GuidedSegmentation.h"
#include "vsim/viz/SliceMarker.h"

#include <QWidget>

#include <vector>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QPushButton;
class QTableWidget;

namespace vsim::gui {

class SegmentationPointsPanel : public QWidget
{
    Q_OBJECT
public:
    enum class Placing { None, Include, Exclude, Stop };

    explicit SegmentationPointsPanel(QWidget* parent = nullptr);

    /// The request as the panel holds it (stop planes from setRequest() or Place Stop).
    imaging::SegmentationRequest request() const;
    /// Shows a request (e.g. the one a label was made with); the points' markers are redrawn.
    void setRequest(const imaging::SegmentationRequest& request);
    void addPoint(const Eigen::Vector3d& pointMm, bool include);
    /// A stop plane through `pointMm` with the plane's normal (the clicked view's); the normal is turned away from the
    /// include points' centroid, so the fronts stop on the far side of the plane from the points.
    void addStop(const Eigen::Vector3d& pointMm, const Eigen::Vector3d& planeNormal);
    /// Marker ids are the points' rows (include and exclude points, then stop planes): moves or removes the point of
    /// row `id` (a stop plane moves with its point).
    void movePoint(int id, const Eigen::Vector3d& pointMm);
    void removePoint(int id);
    std::vector<viz::SliceMarker> markers() const;

    Placing placing() const { return m_placing; }
    void setPlacing(Placing placing);
    bool rerunsOnMove() const;
    QTableWidget* pointTable() const { return m_table; }
    QPushButton* segmentButton() const { return m_segment; }

signals:
    /// The points changed: their markers need drawing again.
    void pointsChanged();
    void placingChanged(SegmentationPointsPanel::Placing placing);
    /// Segment pressed, or a point moved with re-run on.
    void runRequested();

private:
    struct Point
    {
        Eigen::Vector3d mm;
        bool include;
    };
    void refreshTable();

    std::vector<Point> m_points;
    std::vector<imaging::StopPlane> m_stops; ///< listed and drawn after the points
    Placing m_placing = Placing::None;
    QComboBox* m_target = nullptr;
    QDoubleSpinBox* m_maxLength = nullptr;
    QTableWidget* m_table = nullptr;
    QPushButton* m_placeInclude = nullptr;
    QPushButton* m_placeExclude = nullptr;
    QPushButton* m_placeStop = nullptr;
    QPushButton* m_segment = nullptr;
    QCheckBox* m_rerun = nullptr;
};

} // namespace vsim::gui
