#pragma once

#include "vsim/core/ImageVolume.h"
#include "vsim/core/SimulationData.h"
#include "vsim/viz/BrushMode.h"
#include "vsim/viz/SliceMeasurement.h"
#include "vsim/viz/SliceMarker.h"
#include "vsim/viz/SliceOrientation.h"
#include "vsim/viz/VtkView.h"

#include <QString>

#include <optional>
#include <vector>

namespace vsim::viz {

/// One MPR view (axial, coronal or sagittal) of a CT through a cursor point in the patient frame, with the habits of
/// 3D Slicer, Horos and vendor workstations: linear reslicing at the finest voxel spacing (or a thick-slab maximum
/// intensity projection), window/level, LPS orientation letters on the four edges, a crosshair through the cursor
/// in the colours of the other planes (axial red, coronal green, sagittal yellow), a scale bar, and four corner
/// texts: patient / study / series (setPatientText), window / level and slab, slice number and position, and the
/// value under the mouse (HU).
/// Mouse: a left click or drag moves the cursor (the crosshair) and leaves the image where it is; the middle button
/// pans; right drag changes window (x) and level (y), or zooms when setRightDragZooms(true); Ctrl + wheel zooms about
/// the mouse; the wheel steps one slice (the voxel spacing along the view's normal) per notch.
/// Keys: Up/Down one slice, Page Up/Down ten, Home/End the first and last slice, 1-4 the window/level presets (CTA,
/// soft tissue, bone, lung), R resets the view (volume centred, whole field).
/// A label map on the CT's grid can be overlaid (value 1 lumen in translucent red, 4 thrombus yellow, 5 wall blue); in
/// brush mode the left button paints or erases it instead of moving the cursor: the view only reports where
/// (brushDab), the owner edits the label and calls refreshLabel(). Markers (SliceMarker) are drawn where the slice
/// passes them and can be dragged with the left button (markerMoved on release); in placing mode a left click reports
/// a point (pointPlaced) instead of moving the cursor. A played run's frame can be shown cut by the slice (setField).
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
    /// The CT shown (empty without one).
    const CtVolume& image() const { return m_image; }

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

    /// The measurement tool of the left button (Off: the cursor); a finished drawing emits measurementDrawn().
    void setMeasureTool(MeasureTool tool);
    MeasureTool measureTool() const { return m_measureTool; }
    /// The measurements drawn where the slice passes them (replacing the ones before).
    void setMeasurements(std::vector<ShownMeasurement> measurements);
    /// How many of them the current slice shows.
    int shownMeasurementCount() const;

    /// The markers drawn over the slices (replacing the ones before).
    void setMarkers(std::vector<SliceMarker> markers);
    const std::vector<SliceMarker>& markers() const;
    /// Placing mode: a left click away from a marker emits pointPlaced() and leaves the cursor where it is.
    void setPlacing(bool placing);
    bool placing() const { return m_placing; }
    /// The widget position (logical pixels) of a patient point projected onto the view's plane.
    QPointF widgetAt(const Eigen::Vector3d& pointMm) const;

    /// The cursor (mm, LPS): the slice passes through it and the crosshair crosses at it. Moving it leaves the
    /// image where it is on screen (see ensureVisible()).
    Eigen::Vector3d cursor() const { return m_cursor; }
    void setCursor(const Eigen::Vector3d& cursor);
    /// The patient point (mm, LPS) shown at the centre of the view; only its part in the view's plane counts (pan).
    Eigen::Vector3d viewCentre() const { return m_viewCentre; }
    void setViewCentre(const Eigen::Vector3d& centreMm);
    /// Centres the view on `pointMm` when it lies outside the view's middle 80 %.
    void ensureVisible(const Eigen::Vector3d& pointMm);
    /// Height of the view in mm (zoom).
    double fieldOfView() const { return m_fieldOfView; }
    void setFieldOfView(double heightMm);
    /// Zooms by `factor` (> 1 magnifies) keeping the patient point under `aboutWidget` (logical pixels) in place.
    void zoomBy(double factor, const QPointF& aboutWidget);
    /// The volume centred and the whole volume in view.
    void resetView();

    /// Moves the cursor `count` slices along the view's normal (one slice = the voxel spacing as the normal sees it).
    void stepSlices(int count);
    /// The image slice the cursor lies in (1-based, along the image axis nearest the view's normal) and their count;
    /// 0 and 0 without an image.
    int sliceNumber() const;
    int sliceCount() const;

    /// Thick-slab maximum intensity projection over `thicknessMm` about the slice (0: the thin slice).
    void setSlabThickness(double thicknessMm);
    double slabThickness() const { return m_slabMm; }

    void setCrosshairShown(bool shown);
    bool crosshairShown() const;
    /// Right drag zooms instead of changing window/level (a preference; Slicer's habit).
    void setRightDragZooms(bool zooms) { m_rightDragZooms = zooms; }
    /// The top-left overlay: patient, study and series (one per line).
    void setPatientText(const QString& text);
    /// The overlay text in a corner (as drawn).
    QString overlayText(Qt::Corner corner) const;
    /// The CT value (HU) of the voxel nearest the patient point under a widget position, when it lies in the volume.
    std::optional<double> valueAt(const QPointF& widgetPosition) const;
    /// The scale bar's length (mm).
    double scaleBarMm() const;
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
    /// A measurement finished with the tool: its kind, points (patient mm) and this view's plane; no figures yet.
    void measurementDrawn(const vsim::ViewMeasurement& measurement);

protected:
    void resizeGL(int width, int height) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void leaveEvent(QEvent* event) override;

private:
    void updateSlice();
    void updateOverlay();
    void updateMouseReadout(const std::optional<QPointF>& widgetPosition);
    /// The view centre moved into the cursor's plane: the origin of the slice coordinates.
    Eigen::Vector3d planeOrigin() const;
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
    MeasureTool m_measureTool = MeasureTool::Off;
    ViewMeasurement m_pending; // the measurement being drawn; no points: none
    /// Starts, extends or finishes the measurement being drawn at a left press (true when the tool took it).
    bool measurePress(const QPointF& widgetPosition);
    bool measureRelease(const QPointF& widgetPosition);
    void measureMove(const QPointF& widgetPosition);
    std::optional<int> m_draggedMarker;
    Eigen::Vector3d m_cursor = Eigen::Vector3d::Zero();
    Eigen::Vector3d m_viewCentre = Eigen::Vector3d::Zero();
    double m_fieldOfView = 300.0;
    double m_slabMm = 0.0;
    bool m_rightDragZooms = false;
    int m_wheelRemainder = 0; // eighths of a degree not yet stepped (touchpads send small deltas)
    QString m_patientText;
    Eigen::Vector3d m_dragStartCentre = Eigen::Vector3d::Zero();
    double m_dragStartField = 300.0;
    WindowLevel m_windowLevel = kCtaPreset;
    QPointF m_dragStart;
    WindowLevel m_dragStartWindowLevel;
};

} // namespace vsim::viz
