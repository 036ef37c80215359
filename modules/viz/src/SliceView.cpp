#include "vsim/viz/SliceView.h"

#include "SliceFieldLayer.h"
#include "SliceMarkerLayer.h"

#include "vsim/interop/VtkImage.h"
#include "vsim/viz/LabelPalette.h"

#include <QMouseEvent>
#include <QWheelEvent>
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

struct SliceView::Pipeline
{
    vtkSmartPointer<vtkImageData> scaledIndexImage; // the CT in "index * spacing" space, sharing its voxels
    vtkSmartPointer<vtkImageReslice> reslice = vtkSmartPointer<vtkImageReslice>::New();
    vtkSmartPointer<vtkImageActor> actor = vtkSmartPointer<vtkImageActor>::New();
    // The label overlay: same reslice axes, nearest neighbour, translucent colours per value (see the table).
    vtkSmartPointer<vtkImageData> scaledIndexLabel;
    vtkSmartPointer<vtkImageReslice> labelReslice = vtkSmartPointer<vtkImageReslice>::New();
    vtkSmartPointer<vtkImageMapToColors> labelColours = vtkSmartPointer<vtkImageMapToColors>::New();
    vtkSmartPointer<vtkImageActor> labelActor = vtkSmartPointer<vtkImageActor>::New();
    std::array<vtkSmartPointer<vtkTextActor>, 4> edgeLabels; // left, right, top, bottom
    vtkSmartPointer<vtkTextActor> positionLabel;
    std::unique_ptr<SliceMarkerLayer> markers;
    std::unique_ptr<SliceFieldLayer> field;
};

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
    p.labelActor->SetPosition(0.0, 0.0, 0.5); // in front of the CT slice (the camera looks down -z)
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
    p.positionLabel = makeLabel(VTK_TEXT_LEFT, VTK_TEXT_BOTTOM);
    p.positionLabel->GetPositionCoordinate()->SetValue(0.01, 0.01);
    p.positionLabel->GetTextProperty()->SetFontSize(12);
    renderer()->AddViewProp(p.positionLabel);
    p.markers = std::make_unique<SliceMarkerLayer>(renderer());
    p.field = std::make_unique<SliceFieldLayer>(renderer());
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
    const Eigen::Vector3d extent = geometry.spacing.cwiseProduct(
        Eigen::Vector3d(geometry.dims[0], geometry.dims[1], geometry.dims[2]));
    m_fieldOfView = extent.maxCoeff() * 1.05;
    p.actor->VisibilityOn();
    setCursor(geometry.indexToPatient(centreIndex));
    updateCamera();
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
    m_pipeline->field->update(m_cursor, screenAxes(m_orientation), sliceThickness());
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
    m_pipeline->positionLabel->SetInput("");
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

void SliceView::setFieldOfView(double heightMm)
{
    m_fieldOfView = heightMm;
    updateCamera();
}

void SliceView::setWindowLevel(const WindowLevel& windowLevel)
{
    m_windowLevel = {std::max(1.0, windowLevel.window), windowLevel.level};
    m_pipeline->actor->GetProperty()->SetColorWindow(m_windowLevel.window);
    m_pipeline->actor->GetProperty()->SetColorLevel(m_windowLevel.level);
    update();
    emit windowLevelChanged(m_windowLevel.window, m_windowLevel.level);
}

double SliceView::millimetresPerPixel() const { return m_fieldOfView / std::max(1, height()); }

Eigen::Vector3d SliceView::patientAt(const QPointF& widgetPosition) const
{
    const double right = (widgetPosition.x() - 0.5 * width()) * millimetresPerPixel();
    const double up = (0.5 * height() - widgetPosition.y()) * millimetresPerPixel();
    const ScreenAxes axes = screenAxes(m_orientation);
    return m_cursor + right * axes.right + up * axes.up;
}

QPointF SliceView::widgetAt(const Eigen::Vector3d& pointMm) const
{
    const ScreenAxes axes = screenAxes(m_orientation);
    const Eigen::Vector3d offset = pointMm - m_cursor;
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
    m_pipeline->markers->update(m_cursor, screenAxes(m_orientation), sliceThickness(), millimetresPerPixel());
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
    const Eigen::Vector3d centre = toInput * (m_cursor - geometry.origin);
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
    p.labelReslice->SetResliceAxes(matrix);
    p.labelReslice->SetOutputSpacing(pixel, pixel, pixel);
    p.labelReslice->SetOutputOrigin(0.0, 0.0, 0.0);
    p.labelReslice->SetOutputExtent(-half, half, -half, half, 0, 0);
    const Eigen::Vector3d index = geometry.patientToIndex(m_cursor);
    const double along = m_cursor.dot(axes.normal().cwiseAbs());
    const char* axisName = m_orientation == SliceOrientation::Axial ? "z" : m_orientation == SliceOrientation::Coronal ? "y" : "x";
    p.positionLabel->SetInput(QStringLiteral("%1 = %2 mm  (voxel %3, %4, %5)")
                                  .arg(axisName)
                                  .arg(along, 0, 'f', 1)
                                  .arg(index.x(), 0, 'f', 0)
                                  .arg(index.y(), 0, 'f', 0)
                                  .arg(index.z(), 0, 'f', 0)
                                  .toLatin1()
                                  .constData());
    if (!p.field->isEmpty())
        p.field->update(m_cursor, axes, sliceThickness());
    updateMarkers();
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
    VtkView::resizeGL(width, height);
    updateCamera();
}

void SliceView::mousePressEvent(QMouseEvent* event)
{
    m_dragStart = event->position();
    m_dragStartWindowLevel = m_windowLevel;
    if (event->button() != Qt::LeftButton || !hasImage())
        return;
    if (m_brush != BrushMode::Off && hasLabel())
    {
        m_stroking = true;
        emit brushDab(patientAt(event->position()), screenAxes(m_orientation).normal());
        return;
    }
    constexpr double kPickPixels = 9.0;
    m_draggedMarker = m_pipeline->markers->pick(patientAt(event->position()), kPickPixels * millimetresPerPixel());
    if (m_draggedMarker)
        return;
    if (m_placing)
    {
        emit pointPlaced(patientAt(event->position()));
        return;
    }
    setCursor(patientAt(event->position()));
}

void SliceView::mouseMoveEvent(QMouseEvent* event)
{
    if (!hasImage())
        return;
    if ((event->buttons() & Qt::LeftButton) && m_stroking)
        emit brushDab(patientAt(event->position()), screenAxes(m_orientation).normal());
    else if ((event->buttons() & Qt::LeftButton) && m_draggedMarker)
    {
        m_pipeline->markers->moveMarker(*m_draggedMarker, patientAt(event->position()));
        updateMarkers();
    }
    else if ((event->buttons() & Qt::LeftButton) && !m_placing)
        setCursor(patientAt(event->position()));
    else if (event->buttons() & Qt::RightButton)
    {
        const QPointF delta = event->position() - m_dragStart;
        setWindowLevel({m_dragStartWindowLevel.window + 4.0 * delta.x(), m_dragStartWindowLevel.level - 2.0 * delta.y()});
    }
}

void SliceView::mouseReleaseEvent(QMouseEvent* event)
{
    if (event->button() == Qt::LeftButton && m_stroking)
    {
        m_stroking = false;
        emit brushStrokeFinished();
    }
    if (event->button() == Qt::LeftButton && m_draggedMarker)
    {
        const int id = *m_draggedMarker;
        m_draggedMarker.reset();
        emit markerMoved(id, patientAt(event->position()));
    }
}

void SliceView::wheelEvent(QWheelEvent* event)
{
    if (!hasImage())
        return;
    const double step = m_image.geometry().spacing.minCoeff() * (event->angleDelta().y() > 0 ? 1.0 : -1.0);
    setCursor(m_cursor + step * screenAxes(m_orientation).normal());
}

} // namespace vsim::viz
