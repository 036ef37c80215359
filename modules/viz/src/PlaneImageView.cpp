#include "vsim/viz/PlaneImageView.h"
#include "TextFonts.h"

#include <QMouseEvent>
#include <QWheelEvent>
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkImageActor.h>
#include <vtkImageData.h>
#include <vtkImageMapper3D.h>
#include <vtkImageProperty.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include <Eigen/Core>

#include <cmath>

namespace vsim::viz {

// World coordinates: x = column * pixel (mm from the left edge), y = -row * pixel (mm below the top edge), so that
// the top row is on top; the camera looks down -z and fits the picture.
struct PlaneImageView::Pipeline
{
    vtkSmartPointer<vtkImageData> image = vtkSmartPointer<vtkImageData>::New();
    vtkSmartPointer<vtkImageActor> actor = vtkSmartPointer<vtkImageActor>::New();
    vtkSmartPointer<vtkActor> lines = vtkSmartPointer<vtkActor>::New();
    vtkSmartPointer<vtkActor> caliper = vtkSmartPointer<vtkActor>::New(); // yellow, with end ticks
    vtkSmartPointer<vtkTextActor> caption = vtkSmartPointer<vtkTextActor>::New();
};

PlaneImageView::PlaneImageView(QWidget* parent) : VtkView(parent), m_pipeline(std::make_unique<Pipeline>())
{
    setForwardEventsToVtk(false);
    Pipeline& p = *m_pipeline;
    p.actor->GetMapper()->SetInputData(p.image);
    p.actor->GetProperty()->SetInterpolationTypeToLinear();
    p.actor->VisibilityOff();
    renderer()->AddViewProp(p.actor);
    renderer()->SetBackground(0.0, 0.0, 0.0);
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputData(vtkSmartPointer<vtkPolyData>::New());
    p.lines->SetMapper(mapper);
    p.lines->GetProperty()->SetColor(0.3, 0.85, 1.0);
    p.lines->GetProperty()->SetLineWidth(2.0);
    p.lines->GetProperty()->LightingOff();
    renderer()->AddViewProp(p.lines);
    auto caliperMapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    caliperMapper->SetInputData(vtkSmartPointer<vtkPolyData>::New());
    p.caliper->SetMapper(caliperMapper);
    p.caliper->GetProperty()->SetColor(1.0, 0.85, 0.2);
    p.caliper->GetProperty()->LightingOff();
    p.caliper->VisibilityOff();
    renderer()->AddViewProp(p.caliper);
    p.caption->GetTextProperty()->SetFontSize(12);
    p.caption->GetTextProperty()->SetColor(1.0, 0.85, 0.2);
    p.caption->GetTextProperty()->SetVerticalJustification(VTK_TEXT_TOP);
    p.caption->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    p.caption->GetPositionCoordinate()->SetValue(0.02, 0.98);
    renderer()->AddViewProp(p.caption);
    setWindowLevel(kCtaPreset);
}

PlaneImageView::~PlaneImageView() = default;

void PlaneImageView::setPicture(int width, int height, double pixelMm, const std::vector<float>& values)
{
    m_width = width;
    m_height = height;
    m_pixelMm = pixelMm;
    Pipeline& p = *m_pipeline;
    p.image->SetDimensions(width, height, 1);
    p.image->SetSpacing(pixelMm, pixelMm, 1.0);
    p.image->SetOrigin(0.0, -(height - 1) * pixelMm, 0.0); // VTK's first row at the bottom: the picture's last
    auto scalars = vtkSmartPointer<vtkFloatArray>::New();
    scalars->SetNumberOfValues(vtkIdType(width) * height);
    for (int row = 0; row < height; ++row)
        for (int column = 0; column < width; ++column)
            scalars->SetValue(vtkIdType(height - 1 - row) * width + column, values[std::size_t(row) * std::size_t(width) + std::size_t(column)]);
    p.image->GetPointData()->SetScalars(scalars);
    p.image->Modified();
    p.actor->SetVisibility(width > 0 && height > 0);
    updateCamera();
    updateLines();
}

void PlaneImageView::setWindowLevel(const WindowLevel& windowLevel)
{
    m_windowLevel = {std::max(1.0, windowLevel.window), windowLevel.level};
    m_pipeline->actor->GetProperty()->SetColorWindow(m_windowLevel.window);
    m_pipeline->actor->GetProperty()->SetColorLevel(m_windowLevel.level);
    update();
}

void PlaneImageView::setCaption(const QString& text)
{
    m_caption = text;
    setActorText(m_pipeline->caption, text);
    update();
}

void PlaneImageView::setMarkerRow(std::optional<double> rowMm)
{
    m_markerRowMm = rowMm;
    updateLines();
}

void PlaneImageView::setCentreCircle(std::optional<double> radiusMm)
{
    m_circleMm = radiusMm;
    updateLines();
}

void PlaneImageView::setCaliper(std::optional<std::pair<QPointF, QPointF>> endsMm)
{
    m_caliperMm = endsMm;
    updateLines();
}

double PlaneImageView::millimetresPerPixel() const
{
    // The whole picture fits: the larger of its height and its width (for the view's aspect) sets the scale.
    const double heightMm = std::max(1, m_height) * m_pixelMm, widthMm = std::max(1, m_width) * m_pixelMm;
    const double aspect = double(std::max(1, width())) / std::max(1, height());
    return 1.05 * std::max(heightMm, widthMm / aspect) / std::max(1, height());
}

QPointF PlaneImageView::widgetAt(const QPointF& pictureMm) const
{
    const double mpp = millimetresPerPixel();
    const QPointF centreMm(0.5 * (m_width - 1) * m_pixelMm, 0.5 * (m_height - 1) * m_pixelMm);
    return {0.5 * width() + (pictureMm.x() - centreMm.x()) / mpp, 0.5 * height() + (pictureMm.y() - centreMm.y()) / mpp};
}

QPointF PlaneImageView::pictureAt(const QPointF& widgetPosition) const
{
    const double mpp = millimetresPerPixel();
    const QPointF centreMm(0.5 * (m_width - 1) * m_pixelMm, 0.5 * (m_height - 1) * m_pixelMm);
    return {centreMm.x() + (widgetPosition.x() - 0.5 * width()) * mpp, centreMm.y() + (widgetPosition.y() - 0.5 * height()) * mpp};
}

void PlaneImageView::updateCamera()
{
    vtkCamera* camera = renderer()->GetActiveCamera();
    camera->ParallelProjectionOn();
    const double cx = 0.5 * (m_width - 1) * m_pixelMm, cy = -0.5 * (m_height - 1) * m_pixelMm;
    camera->SetFocalPoint(cx, cy, 0.0);
    camera->SetPosition(cx, cy, 1000.0);
    camera->SetViewUp(0.0, 1.0, 0.0);
    camera->SetParallelScale(0.5 * millimetresPerPixel() * std::max(1, height()));
    renderer()->ResetCameraClippingRange(-1e5, 1e5, -1e5, 1e5, -1, 2);
    m_pipeline->caption->GetTextProperty()->SetFontSize(int(std::lround(12 * devicePixelRatioF())));
    update();
}

void PlaneImageView::updateLines()
{
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto cells = vtkSmartPointer<vtkCellArray>::New();
    if (m_markerRowMm)
    {
        const vtkIdType ids[2] = {points->InsertNextPoint(0.0, -*m_markerRowMm, 1.0),
                                  points->InsertNextPoint((m_width - 1) * m_pixelMm, -*m_markerRowMm, 1.0)};
        cells->InsertNextCell(2, ids);
    }
    if (m_circleMm)
    {
        const double cx = 0.5 * (m_width - 1) * m_pixelMm, cy = -0.5 * (m_height - 1) * m_pixelMm;
        std::vector<vtkIdType> ring;
        for (int s = 0; s <= 64; ++s)
            ring.push_back(points->InsertNextPoint(cx + *m_circleMm * std::cos(2 * M_PI * s / 64),
                                                   cy + *m_circleMm * std::sin(2 * M_PI * s / 64), 1.0));
        cells->InsertNextCell(vtkIdType(ring.size()), ring.data());
    }
    auto data = vtkSmartPointer<vtkPolyData>::New();
    data->SetPoints(points);
    data->SetLines(cells);
    static_cast<vtkPolyDataMapper*>(m_pipeline->lines->GetMapper())->SetInputData(data);
    m_pipeline->lines->GetProperty()->SetLineWidth(float(2.0 * devicePixelRatioF()));
    m_pipeline->lines->SetVisibility(cells->GetNumberOfCells() > 0);

    // The caliper: its line and a tick across each end, 1.5 mm long (world y is minus the picture's row).
    auto caliperPoints = vtkSmartPointer<vtkPoints>::New();
    auto caliperCells = vtkSmartPointer<vtkCellArray>::New();
    if (m_caliperMm)
    {
        const Eigen::Vector2d a(m_caliperMm->first.x(), -m_caliperMm->first.y()), b(m_caliperMm->second.x(), -m_caliperMm->second.y());
        const Eigen::Vector2d along = (b - a).norm() > 0.0 ? Eigen::Vector2d((b - a).normalized()) : Eigen::Vector2d(1.0, 0.0);
        const Eigen::Vector2d across(-along.y(), along.x());
        auto segment = [&](const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
            const vtkIdType ids[2] = {caliperPoints->InsertNextPoint(from.x(), from.y(), 1.5),
                                      caliperPoints->InsertNextPoint(to.x(), to.y(), 1.5)};
            caliperCells->InsertNextCell(2, ids);
        };
        segment(a, b);
        for (const Eigen::Vector2d& end : {a, b})
            segment(end - 0.75 * across, end + 0.75 * across);
    }
    auto caliperData = vtkSmartPointer<vtkPolyData>::New();
    caliperData->SetPoints(caliperPoints);
    caliperData->SetLines(caliperCells);
    static_cast<vtkPolyDataMapper*>(m_pipeline->caliper->GetMapper())->SetInputData(caliperData);
    m_pipeline->caliper->GetProperty()->SetLineWidth(float(2.0 * devicePixelRatioF()));
    m_pipeline->caliper->SetVisibility(bool(m_caliperMm));
    update();
}

void PlaneImageView::resizeGL(int width, int height)
{
    VtkView::resizeGL(width, height);
    updateCamera();
    updateLines();
}

void PlaneImageView::mousePressEvent(QMouseEvent* event)
{
    m_dragStart = event->position();
    m_dragStartWindowLevel = m_windowLevel;
    if (event->button() == Qt::LeftButton && m_width > 0)
        emit clicked(pictureAt(event->position()));
}

void PlaneImageView::mouseMoveEvent(QMouseEvent* event)
{
    if ((event->buttons() & Qt::LeftButton) && m_width > 0)
        emit clicked(pictureAt(event->position()));
    else if (event->buttons() & Qt::RightButton)
    {
        const QPointF delta = event->position() - m_dragStart;
        setWindowLevel({m_dragStartWindowLevel.window + 4.0 * delta.x(), m_dragStartWindowLevel.level - 2.0 * delta.y()});
    }
}

void PlaneImageView::wheelEvent(QWheelEvent* event)
{
    m_wheelRemainder += event->angleDelta().y();
    const int steps = m_wheelRemainder / 120;
    m_wheelRemainder -= steps * 120;
    if (steps != 0)
        emit stepped(steps);
}

} // namespace vsim::viz
