#include "vsim/viz/SliceView.h"

#include "SliceDepths.h"
#include "SliceViewPipeline.h"

#include "vsim/interop/VtkImage.h"
#include "vsim/viz/DecimalText.h"
#include "vsim/viz/LabelPalette.h"

#include <vtkCamera.h>
#include <vtkImageActor.h>
#include <vtkImageData.h>
#include <vtkImageMapToColors.h>
#include <vtkImageMapper3D.h>
#include <vtkImageProperty.h>
#include <vtkImageReslice.h>
#include <vtkLookupTable.h>
#include <vtkMatrix4x4.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include <array>
#include <cmath>

namespace vsim::viz {
namespace {

/// LPS letter of the patient-frame direction a vector points to most.
QString patientLetter(const Eigen::Vector3d& direction)
{
    int axis = 0;
    direction.cwiseAbs().maxCoeff(&axis);
    static const char* positive[] = {"L", "P", "S"};
    static const char* negative[] = {"R", "A", "I"};
    return direction[axis] >= 0 ? positive[axis] : negative[axis];
}

vtkSmartPointer<vtkTextActor> makeLabel(int justification, int verticalJustification)
{
    auto label = vtkSmartPointer<vtkTextActor>::New();
    label->GetTextProperty()->SetFontSize(16);
    label->GetTextProperty()->SetColor(1.0, 0.85, 0.2);
    label->GetTextProperty()->SetJustification(justification);
    label->GetTextProperty()->SetVerticalJustification(verticalJustification);
    label->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    return label;
}

/// The colours of label values 0-5 (RGBA; 0 clear) in a palette (SliceView.h).
vtkSmartPointer<vtkLookupTable> labelTable(SliceView::LabelPalette palette)
{
    const auto& colours = palette == SliceView::LabelPalette::Territory ? kTerritoryPalette : kTissuePalette;
    auto table = vtkSmartPointer<vtkLookupTable>::New();
    table->SetNumberOfTableValues(6);
    table->SetTableRange(0.0, 5.0);
    for (std::size_t v = 0; v < colours.size(); ++v)
        table->SetTableValue(vtkIdType(v), colours[v][0], colours[v][1], colours[v][2], colours[v][3]);
    table->Build();
    return table;
}

} // namespace


SliceView::SliceView(SliceOrientation orientation, QWidget* parent)
    : VtkView(parent), m_pipeline(std::make_unique<Pipeline>()), m_orientation(orientation)
{
    setForwardEventsToVtk(false); // the slice view handles its own mouse: cursor, window/level, scrolling
    Pipeline& p = *m_pipeline;
    p.reslice->SetOutputDimensionality(2);
    p.reslice->SetInterpolationModeToLinear();
    p.reslice->SetBackgroundLevel(-1024.0);
    p.actor->GetMapper()->SetInputConnection(p.reslice->GetOutputPort());
    p.actor->GetProperty()->SetInterpolationTypeToLinear();
    p.actor->VisibilityOff();
    renderer()->AddViewProp(p.actor);
    renderer()->SetBackground(0.0, 0.0, 0.0);

    p.labelReslice->SetOutputDimensionality(2);
    p.labelReslice->SetInterpolationModeToNearestNeighbor();
    p.labelReslice->SetBackgroundLevel(0.0);
    p.labelColours->SetLookupTable(labelTable(LabelPalette::Tissue));
    p.labelColours->SetOutputFormatToRGBA();
    p.labelColours->SetInputConnection(p.labelReslice->GetOutputPort());
    p.labelActor->GetMapper()->SetInputConnection(p.labelColours->GetOutputPort());
    p.labelActor->GetProperty()->SetInterpolationTypeToNearest();
    p.labelActor->SetPosition(0.0, 0.0, slice_depth::kLabels);
    p.labelActor->VisibilityOff();
    renderer()->AddViewProp(p.labelActor);

    p.edgeLabels = {makeLabel(VTK_TEXT_LEFT, VTK_TEXT_CENTERED), makeLabel(VTK_TEXT_RIGHT, VTK_TEXT_CENTERED),
                    makeLabel(VTK_TEXT_CENTERED, VTK_TEXT_TOP), makeLabel(VTK_TEXT_CENTERED, VTK_TEXT_BOTTOM)};
    const double positions[4][2] = {{0.01, 0.5}, {0.99, 0.5}, {0.5, 0.99}, {0.5, 0.01}};
    const Qt::Edge edges[4] = {Qt::LeftEdge, Qt::RightEdge, Qt::TopEdge, Qt::BottomEdge};
    for (int e = 0; e < 4; ++e)
    {
        p.edgeLabels[e]->GetPositionCoordinate()->SetValue(positions[e][0], positions[e][1]);
        p.edgeLabels[e]->SetInput(edgeLabel(edges[e]).toLatin1().constData());
        renderer()->AddViewProp(p.edgeLabels[e]);
    }
    p.markers = std::make_unique<SliceMarkerLayer>(renderer());
    p.field = std::make_unique<SliceFieldLayer>(renderer());
    p.overlay = std::make_unique<SliceOverlayLayer>(renderer());
    p.measurements = std::make_unique<SliceMeasurementLayer>(renderer());
    // The crosshair's lines stand for the other two planes: the one whose normal is the view's up is horizontal.
    const ScreenAxes axes = screenAxes(orientation);
    Eigen::Vector3d horizontal = Eigen::Vector3d::Ones(), vertical = Eigen::Vector3d::Ones();
    for (SliceOrientation other : {SliceOrientation::Axial, SliceOrientation::Coronal, SliceOrientation::Sagittal})
    {
        const double alongUp = std::abs(screenAxes(other).normal().dot(axes.up));
        const double alongRight = std::abs(screenAxes(other).normal().dot(axes.right));
        if (alongUp > 0.9)
            horizontal = planeColour(other);
        else if (alongRight > 0.9)
            vertical = planeColour(other);
    }
    p.overlay->setCrosshairColours(horizontal, vertical);
    setMouseTracking(true); // the value under the mouse
    setWindowLevel(kCtaPreset);
    updateCamera();
}

SliceView::~SliceView() = default;

bool SliceView::hasImage() const { return !m_image.isEmpty(); }

QString SliceView::edgeLabel(Qt::Edge edge) const
{
    const ScreenAxes axes = screenAxes(m_orientation);
    switch (edge)
    {
    case Qt::LeftEdge: return patientLetter(-axes.right);
    case Qt::RightEdge: return patientLetter(axes.right);
    case Qt::TopEdge: return patientLetter(axes.up);
    case Qt::BottomEdge: return patientLetter(-axes.up);
    }
    return {};
}

void SliceView::setImage(const CtVolume& image)
{
    m_image = image;
    if (!m_label.isEmpty() && !m_label.geometry().isClose(image.geometry(), 1e-4))
    {
        m_label = LabelVolume(); // an overlay belongs to its image's grid
        m_pipeline->labelActor->VisibilityOff();
    }
    Pipeline& p = *m_pipeline;
    p.scaledIndexImage = interop::toVtk(m_image);
    p.scaledIndexImage->SetOrigin(0.0, 0.0, 0.0); // reslicing happens in index * spacing space, see updateSlice()
    const double identity[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    p.scaledIndexImage->SetDirectionMatrix(identity);
    p.reslice->SetInputData(p.scaledIndexImage);
    const VolumeGeometry& geometry = m_image.geometry();
    const Eigen::Vector3d centreIndex(0.5 * (geometry.dims[0] - 1), 0.5 * (geometry.dims[1] - 1),
                                      0.5 * (geometry.dims[2] - 1));
    m_viewCentre = geometry.indexToPatient(centreIndex);
    p.actor->VisibilityOn();
    m_cursor = geometry.indexToPatient(centreIndex) + Eigen::Vector3d::Constant(1.0); // so that setCursor announces
    setCursor(geometry.indexToPatient(centreIndex));
    resetView();
}

void SliceView::setLabel(const LabelVolume& label, LabelPalette palette)
{
    Pipeline& p = *m_pipeline;
    if (palette != m_palette)
    {
        m_palette = palette;
        p.labelColours->SetLookupTable(labelTable(palette));
    }
    if (label.isEmpty() || !hasImage() || !label.geometry().isClose(m_image.geometry(), 1e-4))
    {
        m_label = LabelVolume();
        p.labelActor->VisibilityOff();
        update();
        return;
    }
    m_label = label;
    p.scaledIndexLabel = interop::toVtk(m_label);
    p.scaledIndexLabel->SetOrigin(0.0, 0.0, 0.0);
    const double identity[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    p.scaledIndexLabel->SetDirectionMatrix(identity);
    p.labelReslice->SetInputData(p.scaledIndexLabel);
    p.labelActor->VisibilityOn();
    updateSlice();
}

void SliceView::refreshLabel()
{
    if (m_pipeline->scaledIndexLabel)
        m_pipeline->scaledIndexLabel->Modified();
    update();
}

void SliceView::setField(const SimulationData& frame, const std::string& field, double low, double high)
{
    m_pipeline->field->setField(frame, field, low, high);
    m_pipeline->field->update(planeOrigin(), screenAxes(m_orientation), sliceThickness());
    update();
}

void SliceView::clearField()
{
    m_pipeline->field->clear();
    update();
}

long long SliceView::fieldCellsShown() const { return m_pipeline->field->cellsShown(); }

void SliceView::setBrush(BrushMode brush, double radiusMm)
{
    m_brush = brush;
    m_brushRadiusMm = std::max(0.1, radiusMm);
    QWidget::setCursor(m_placing || m_brush != BrushMode::Off ? Qt::CrossCursor : Qt::ArrowCursor);
}

void SliceView::clearImage()
{
    m_image = CtVolume();
    m_label = LabelVolume();
    m_pipeline->labelActor->VisibilityOff();
    m_pipeline->actor->VisibilityOff();
    for (Qt::Corner corner : {Qt::TopRightCorner, Qt::BottomLeftCorner, Qt::BottomRightCorner})
        m_pipeline->overlay->setCornerText(corner, {});
    update();
}

void SliceView::setCursor(const Eigen::Vector3d& cursor)
{
    if (cursor == m_cursor) // linked views call each other: only a change is announced
        return updateSlice();
    m_cursor = cursor;
    updateSlice();
    emit cursorChanged(m_cursor);
}

void SliceView::setViewCentre(const Eigen::Vector3d& centreMm)
{
    m_viewCentre = centreMm;
    if (hasImage())
    {
        // Kept within the volume's box: the resliced plane covers the volume from any point inside it.
        const VolumeGeometry& geometry = m_image.geometry();
        Eigen::Vector3d index = geometry.patientToIndex(centreMm);
        for (int a = 0; a < 3; ++a)
            index[a] = std::clamp(index[a], 0.0, double(geometry.dims[std::size_t(a)] - 1));
        m_viewCentre = geometry.indexToPatient(index);
    }
    updateSlice();
}

void SliceView::ensureVisible(const Eigen::Vector3d& pointMm)
{
    const QPointF at = widgetAt(pointMm);
    const QRectF middle(0.1 * width(), 0.1 * height(), 0.8 * width(), 0.8 * height());
    if (!middle.contains(at))
        setViewCentre(pointMm);
}

void SliceView::setFieldOfView(double heightMm)
{
    m_fieldOfView = std::clamp(heightMm, 5.0, 5000.0);
    updateCamera();
}

void SliceView::zoomBy(double factor, const QPointF& aboutWidget)
{
    const Eigen::Vector3d before = patientAt(aboutWidget);
    setFieldOfView(m_fieldOfView / factor);
    setViewCentre(m_viewCentre + before - patientAt(aboutWidget));
}

void SliceView::resetView()
{
    if (!hasImage())
        return;
    const VolumeGeometry& geometry = m_image.geometry();
    const Eigen::Vector3d extent = geometry.spacing.cwiseProduct(
        Eigen::Vector3d(geometry.dims[0], geometry.dims[1], geometry.dims[2]));
    m_fieldOfView = extent.maxCoeff() * 1.05;
    updateCamera();
    setViewCentre(geometry.indexToPatient(0.5 * Eigen::Vector3d(geometry.dims[0] - 1, geometry.dims[1] - 1, geometry.dims[2] - 1)));
}

namespace {
/// The image axis nearest a patient direction.
int imageAxisAlong(const VolumeGeometry& geometry, const Eigen::Vector3d& direction)
{
    int axis = 0;
    (geometry.direction.transpose() * direction).cwiseAbs().maxCoeff(&axis);
    return axis;
}
} // namespace

void SliceView::stepSlices(int count)
{
    if (!hasImage())
        return;
    // Stops at the first and the last slice of the stack.
    const VolumeGeometry& geometry = m_image.geometry();
    const int axis = imageAxisAlong(geometry, screenAxes(m_orientation).normal());
    Eigen::Vector3d index = geometry.patientToIndex(m_cursor + count * sliceThickness() * screenAxes(m_orientation).normal());
    index[axis] = std::clamp(index[axis], 0.0, double(geometry.dims[std::size_t(axis)] - 1));
    setCursor(geometry.indexToPatient(index));
}

int SliceView::sliceNumber() const
{
    if (!hasImage())
        return 0;
    const int axis = imageAxisAlong(m_image.geometry(), screenAxes(m_orientation).normal());
    return int(std::lround(m_image.geometry().patientToIndex(m_cursor)[axis])) + 1;
}

int SliceView::sliceCount() const
{
    return hasImage() ? m_image.geometry().dims[std::size_t(imageAxisAlong(m_image.geometry(), screenAxes(m_orientation).normal()))] : 0;
}

void SliceView::setSlabThickness(double thicknessMm)
{
    m_slabMm = std::max(0.0, thicknessMm);
    updateSlice();
    updateOverlay();
}

void SliceView::setCrosshairShown(bool shown)
{
    m_pipeline->overlay->setCrosshairShown(shown);
    update();
}

bool SliceView::crosshairShown() const { return m_pipeline->overlay->crosshairShown(); }

void SliceView::setPatientText(const QString& text)
{
    m_patientText = text;
    updateOverlay();
}

QString SliceView::overlayText(Qt::Corner corner) const { return m_pipeline->overlay->cornerText(corner); }

double SliceView::scaleBarMm() const { return m_pipeline->overlay->scaleBarMm(); }

std::optional<double> SliceView::valueAt(const QPointF& widgetPosition) const
{
    if (!hasImage())
        return std::nullopt;
    const Eigen::Vector3d index = m_image.geometry().patientToIndex(patientAt(widgetPosition));
    const int i = int(std::lround(index.x())), j = int(std::lround(index.y())), k = int(std::lround(index.z()));
    if (!m_image.geometry().contains(i, j, k))
        return std::nullopt;
    return double(m_image.at(i, j, k));
}

Eigen::Vector3d SliceView::planeOrigin() const
{
    const Eigen::Vector3d normal = screenAxes(m_orientation).normal();
    return m_viewCentre + (m_cursor - m_viewCentre).dot(normal) * normal;
}

void SliceView::setWindowLevel(const WindowLevel& windowLevel)
{
    m_windowLevel = {std::max(1.0, windowLevel.window), windowLevel.level};
    m_pipeline->actor->GetProperty()->SetColorWindow(m_windowLevel.window);
    m_pipeline->actor->GetProperty()->SetColorLevel(m_windowLevel.level);
    updateOverlay();
    emit windowLevelChanged(m_windowLevel.window, m_windowLevel.level);
}

double SliceView::millimetresPerPixel() const { return m_fieldOfView / std::max(1, height()); }

Eigen::Vector3d SliceView::patientAt(const QPointF& widgetPosition) const
{
    const double right = (widgetPosition.x() - 0.5 * width()) * millimetresPerPixel();
    const double up = (0.5 * height() - widgetPosition.y()) * millimetresPerPixel();
    const ScreenAxes axes = screenAxes(m_orientation);
    return planeOrigin() + right * axes.right + up * axes.up;
}

QPointF SliceView::widgetAt(const Eigen::Vector3d& pointMm) const
{
    const ScreenAxes axes = screenAxes(m_orientation);
    const Eigen::Vector3d offset = pointMm - planeOrigin();
    return {0.5 * width() + offset.dot(axes.right) / millimetresPerPixel(),
            0.5 * height() - offset.dot(axes.up) / millimetresPerPixel()};
}

void SliceView::setMarkers(std::vector<SliceMarker> markers)
{
    m_draggedMarker.reset();
    m_pipeline->markers->setMarkers(std::move(markers));
    updateMarkers();
}

const std::vector<SliceMarker>& SliceView::markers() const { return m_pipeline->markers->markers(); }

void SliceView::setMeasureTool(MeasureTool tool)
{
    m_measureTool = tool;
    m_pending.pointsMm.clear();
    m_pipeline->measurements->clearPending();
    QWidget::setCursor(tool != MeasureTool::Off || m_placing || m_brush != BrushMode::Off ? Qt::CrossCursor : Qt::ArrowCursor);
    updateMarkers();
}

void SliceView::setMeasurements(std::vector<ShownMeasurement> measurements)
{
    m_pipeline->measurements->setMeasurements(std::move(measurements));
    updateMarkers();
}

int SliceView::shownMeasurementCount() const { return m_pipeline->measurements->shownCount(); }

void SliceView::setPlacing(bool placing)
{
    m_placing = placing;
    QWidget::setCursor(m_placing || m_brush != BrushMode::Off ? Qt::CrossCursor : Qt::ArrowCursor);
}

double SliceView::sliceThickness() const
{
    if (!hasImage())
        return 1.0;
    const VolumeGeometry& geometry = m_image.geometry();
    const Eigen::Vector3d normalInIndex = geometry.direction.transpose() * screenAxes(m_orientation).normal();
    return normalInIndex.cwiseAbs().dot(geometry.spacing) / normalInIndex.cwiseAbs().sum();
}

void SliceView::updateMarkers()
{
    // Markers within one slice spacing (as the normal sees the voxels) of the plane are drawn.
    m_pipeline->markers->update(planeOrigin(), screenAxes(m_orientation), sliceThickness(), millimetresPerPixel());
    m_pipeline->measurements->update(planeOrigin(), screenAxes(m_orientation), sliceThickness());
    const ScreenAxes axes = screenAxes(m_orientation);
    const Eigen::Vector3d offset = m_cursor - planeOrigin();
    m_pipeline->overlay->update({offset.dot(axes.right), offset.dot(axes.up)}, width(), height(), millimetresPerPixel());
    update();
}

void SliceView::updateSlice()
{
    if (!hasImage())
        return;
    // Reslice axes map output (right, up, normal) mm around the cursor into the input's index * spacing space:
    // input = D^T (patient - origin), with D the orthonormal direction matrix.
    const VolumeGeometry& geometry = m_image.geometry();
    const ScreenAxes axes = screenAxes(m_orientation);
    const Eigen::Matrix3d toInput = geometry.direction.transpose();
    Eigen::Matrix3d columns;
    columns << toInput * axes.right, toInput * axes.up, toInput * axes.normal();
    const Eigen::Vector3d centre = toInput * (planeOrigin() - geometry.origin);
    auto matrix = vtkSmartPointer<vtkMatrix4x4>::New();
    for (int row = 0; row < 3; ++row)
    {
        for (int column = 0; column < 3; ++column)
            matrix->SetElement(row, column, columns(row, column));
        matrix->SetElement(row, 3, centre[row]);
    }
    Pipeline& p = *m_pipeline;
    p.reslice->SetResliceAxes(matrix);
    const double pixel = geometry.spacing.minCoeff();
    const Eigen::Vector3d extent = geometry.spacing.cwiseProduct(
        Eigen::Vector3d(geometry.dims[0], geometry.dims[1], geometry.dims[2]));
    const int half = static_cast<int>(std::ceil(extent.norm() / pixel)); // covers the volume from any cursor inside it
    p.reslice->SetOutputSpacing(pixel, pixel, pixel);
    p.reslice->SetOutputOrigin(0.0, 0.0, 0.0);
    p.reslice->SetOutputExtent(-half, half, -half, half, 0, 0);
    const int slabSlices = std::max(1, int(std::lround(m_slabMm / pixel)));
    p.reslice->SetSlabModeToMax();
    p.reslice->SetSlabNumberOfSlices(slabSlices);
    p.labelReslice->SetResliceAxes(matrix);
    p.labelReslice->SetOutputSpacing(pixel, pixel, pixel);
    p.labelReslice->SetOutputOrigin(0.0, 0.0, 0.0);
    p.labelReslice->SetOutputExtent(-half, half, -half, half, 0, 0);
    updateOverlay();
    if (!p.field->isEmpty())
        p.field->update(planeOrigin(), axes, sliceThickness());
    updateMarkers();
}

void SliceView::updateOverlay()
{
    SliceOverlayLayer& overlay = *m_pipeline->overlay;
    overlay.setCornerText(Qt::TopLeftCorner, m_patientText);
    if (!hasImage())
        return update();
    QString windowLevel = tr("W %1  L %2")
        .arg(decimalText(m_windowLevel.window, 0))
        .arg(decimalText(m_windowLevel.level, 0));
    if (m_slabMm > 0.0)
        windowLevel += '\n' + tr("MIP slab %1 mm").arg(decimalText(m_slabMm, 1));
    overlay.setCornerText(Qt::TopRightCorner, windowLevel);
    const double along = m_cursor.dot(screenAxes(m_orientation).normal().cwiseAbs());
    const char* axisName = m_orientation == SliceOrientation::Axial ? "z" : m_orientation == SliceOrientation::Coronal ? "y" : "x";
    overlay.setCornerText(Qt::BottomLeftCorner, tr("Im %1/%2  %3 = %4 mm")
                                                    .arg(sliceNumber())
                                                    .arg(sliceCount())
                                                    .arg(QLatin1String(axisName))
                                                    .arg(decimalText(along, 1)));
    update();
}

void SliceView::updateMouseReadout(const std::optional<QPointF>& widgetPosition)
{
    QString text;
    if (widgetPosition && hasImage())
    {
        const Eigen::Vector3d at = patientAt(*widgetPosition);
        const std::optional<double> value = valueAt(*widgetPosition);
        text = tr("(%1, %2, %3) mm")
            .arg(decimalText(at.x(), 1))
            .arg(decimalText(at.y(), 1))
            .arg(decimalText(at.z(), 1));
        if (value)
            text = tr("%1 HU").arg(decimalText(*value, 0)) + "  " + text;
    }
    m_pipeline->overlay->setCornerText(Qt::BottomRightCorner, text);
    update();
}

void SliceView::updateCamera()
{
    vtkCamera* camera = renderer()->GetActiveCamera();
    camera->ParallelProjectionOn();
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetPosition(0.0, 0.0, 1000.0);
    camera->SetViewUp(0.0, 1.0, 0.0);
    camera->SetParallelScale(0.5 * m_fieldOfView);
    renderer()->ResetCameraClippingRange(-2000, 2000, -2000, 2000, -1, 2);
    updateMarkers(); // the rings keep their size on screen
}

void SliceView::resizeGL(int width, int height)
{
    // HiDPI: VTK draws text and lines in device pixels; they keep their size on screen.
    const double scale = devicePixelRatioF();
    for (auto& label : m_pipeline->edgeLabels)
        label->GetTextProperty()->SetFontSize(int(std::lround(16 * scale)));
    m_pipeline->overlay->setPixelScale(scale);
    m_pipeline->markers->setPixelScale(scale);
    m_pipeline->measurements->setPixelScale(scale);
    VtkView::resizeGL(width, height);
    updateCamera();
}

} // namespace vsim::viz
