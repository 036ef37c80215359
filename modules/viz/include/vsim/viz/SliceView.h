#pragma once

#include "vsim/core/ImageVolume.h"
#include "vsim/core/SimulationData.h"
#include "vsim/viz/BrushMode.h"
#include "vsim/viz/SliceMarker.h"
#include "vsim/viz/SliceOrientation.h"
#include "vsim/viz/VtkView.h"

#include <QString>

#include <optional>
#include <vector>

namespace vsim::viz {

/// One MPR view (axial, coronal or sagittal) of a CT through a cursor point in the patient frame: linear
/// reslicing at the finest voxel spacing, window/level, LPS orientation letters on the four edges and the slice
/// position. The cursor sits at the centre of the view; fieldOfView() mm span the view's height.
/// Mouse: left click/drag moves the cursor in the plane, right drag changes window (x) and level (y), the wheel
/// steps through slices by the finest spacing. A label map on the CT's grid can be overlaid (value 1 lumen in
/// translucent red, 4 thrombus yellow, 5 wall blue); in brush mode the left button paints or erases it instead of moving the cursor: the view
/// only reports where (brushDab), the owner edits the label and calls refreshLabel(). Markers (SliceMarker) are drawn
/// where the slice passes them and can be dragged with the left button (markerMoved on release); in placing mode a
/// left click reports a point (pointPlaced) instead of moving the cursor. A played run's frame can be shown cut by the
/// slice (setField).
class SliceView : public VtkView
{
    Q_OBJECT
public:
    explicit SliceView(SliceOrientation orientation, QWidget* parent = nullptr);
    ~SliceView() override;

    SliceOrientation orientation() const { return m_orientation; }
    /// Shows `image` (the view keeps a reference to its voxels); the cursor moves to the volume centre.
    void setImage(const CtVolume& image);
    void clearImage();
    bool hasImage() const;

    /// How label values are coloured: the tissue classes (1 lumen red, 2-3 orange, 4 thrombus yellow, 5 wall
    /// blue), or a chemoembolization territory (sim::network::TerritoryLabelValue: 1 liver not perfused clear, 2
    /// perfused liver green, 3 perfused tumour blue, 4 tumour missed red, 5 margin missed yellow).
    enum class LabelPalette
    {
        Tissue,
        Territory,
    };
    /// Overlays `label` (same grid as the image; the view keeps a reference to its voxels) in `palette`; an empty
    /// one hides it.
    void setLabel(const LabelVolume& label, LabelPalette palette = LabelPalette::Tissue);
    LabelPalette labelPalette() const { return m_palette; }
    /// Redraws the overlay after its voxels changed in place.
    void refreshLabel();
    bool hasLabel() const { return !m_label.isEmpty(); }

    /// A run frame's `field` drawn where this slice cuts it (a mesh's section, a tree's rings, a grid's plane),
    /// coloured blue to red over [low, high]; it follows the cursor. Throws vsim::Error when the frame has no such field.
    void setField(const SimulationData& frame, const std::string& field, double low, double high);
    void clearField();
    /// Cells of the frame's cut drawn in the current slice (0 when none is shown).
    long long fieldCellsShown() const;

    /// Brush mode and radius (mm): with a brush the left button reports dabs instead of moving the cursor.
    void setBrush(BrushMode brush, double radiusMm);
    BrushMode brush() const { return m_brush; }
    double brushRadius() const { return m_brushRadiusMm; }

    /// The markers drawn over the slices (replacing the ones before).
    void setMarkers(std::vector<SliceMarker> markers);
    const std::vector<SliceMarker>& markers() const;
    /// Placing mode: a left click away from a marker emits pointPlaced() and leaves the cursor where it is.
    void setPlacing(bool placing);
    bool placing() const { return m_placing; }
    /// The widget position (logical pixels) of a patient point projected onto the view's plane.
    QPointF widgetAt(const Eigen::Vector3d& pointMm) const;

    /// The cursor (mm, LPS): the slice passes through it and it sits at the centre of the view.
    Eigen::Vector3d cursor() const { return m_cursor; }
    void setCursor(const Eigen::Vector3d& cursor);
    /// Height of the view in mm (zoom).
    double fieldOfView() const { return m_fieldOfView; }
    void setFieldOfView(double heightMm);
    WindowLevel windowLevel() const { return m_windowLevel; }
    void setWindowLevel(const WindowLevel& windowLevel);
    /// The patient position (mm) under a widget position (logical pixels) in the current slice.
    Eigen::Vector3d patientAt(const QPointF& widgetPosition) const;
    /// The orientation letters shown on the left, right, top and bottom edges, e.g. "R", "L", "A", "P".
    QString edgeLabel(Qt::Edge edge) const;

signals:
    void cursorChanged(const Eigen::Vector3d& cursor);
    void windowLevelChanged(double window, double level);
    /// A brush dab at `centreMm` (patient frame) in the plane of this view; a stroke is the dabs between a press
    /// and brushStrokeFinished().
    void brushDab(const Eigen::Vector3d& centreMm, const Eigen::Vector3d& planeNormal);
    void brushStrokeFinished();
    /// A left click in placing mode at `pointMm` (in this view's slice).
    void pointPlaced(const Eigen::Vector3d& pointMm);
    /// The marker `id` was dragged to `pointMm` (reported once, on release).
    void markerMoved(int id, const Eigen::Vector3d& pointMm);

protected:
    void resizeGL(int width, int height) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;

private:
    void updateSlice();
    void updateCamera();
    void updateMarkers();
    double millimetresPerPixel() const;
    /// The slice's thickness along its normal (mm): the voxel spacing as the normal sees it, 1 without an image.
    double sliceThickness() const;

    struct Pipeline;
    std::unique_ptr<Pipeline> m_pipeline;
    SliceOrientation m_orientation;
    CtVolume m_image;
    LabelVolume m_label;
    LabelPalette m_palette = LabelPalette::Tissue;
    BrushMode m_brush = BrushMode::Off;
    double m_brushRadiusMm = 3.0;
    bool m_stroking = false;
    bool m_placing = false;
    std::optional<int> m_draggedMarker;
    Eigen::Vector3d m_cursor = Eigen::Vector3d::Zero();
    double m_fieldOfView = 300.0;
    WindowLevel m_windowLevel = kCtaPreset;
    QPointF m_dragStart;
    WindowLevel m_dragStartWindowLevel;
};

} // namespace vsim::viz
