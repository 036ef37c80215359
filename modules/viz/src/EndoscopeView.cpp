// EndoscopeView.h: an offscreen VTK window (the lumen, the particles, a headlight) read back with its depth
// buffer.
#include "vsim/viz/EndoscopeView.h"

#include "vsim/interop/VtkMesh.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkFloatArray.h>
#include <vtkGlyph3DMapper.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkSphereSource.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>

#include <QPainter>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>

namespace vsim::viz {

namespace {

constexpr double kNearMm = 0.2, kFarMm = 600.0; // the clipping range: the probe's tip to well past any vessel
constexpr double kTissue[3] = {0.86, 0.46, 0.42}; // the lumen's intima, pink
constexpr double kBloodCell[3] = {0.62, 0.06, 0.08};

/// A sphere of unit radius flattened to a third of its height along z: a red blood cell's shape
/// (thesis 5.5.2).
vtkSmartPointer<vtkPolyData> bloodCellShape()
{
    auto sphere = vtkSmartPointer<vtkSphereSource>::New();
    sphere->SetRadius(1.0);
    sphere->SetThetaResolution(16);
    sphere->SetPhiResolution(10);
    auto flatten = vtkSmartPointer<vtkTransform>::New();
    flatten->Scale(1.0, 1.0, 0.35);
    auto filter = vtkSmartPointer<vtkTransformPolyDataFilter>::New();
    filter->SetInputConnection(sphere->GetOutputPort());
    filter->SetTransform(flatten);
    filter->Update();
    return filter->GetOutput();
}

} // namespace

struct EndoscopeView::Pipeline
{
    vtkSmartPointer<vtkRenderWindow> window = vtkSmartPointer<vtkRenderWindow>::New();
    vtkSmartPointer<vtkRenderer> renderer = vtkSmartPointer<vtkRenderer>::New();
    vtkSmartPointer<vtkActor> lumen = vtkSmartPointer<vtkActor>::New();
    vtkSmartPointer<vtkActor> cells = vtkSmartPointer<vtkActor>::New();
    vtkSmartPointer<vtkGlyph3DMapper> cellMapper = vtkSmartPointer<vtkGlyph3DMapper>::New();
    std::size_t cellCount = 0;

    Pipeline()
    {
        window->SetOffScreenRendering(1);
        window->AddRenderer(renderer);
        renderer->SetBackground(0.0, 0.0, 0.0);
        renderer->TwoSidedLightingOn(); // the wall is seen from inside: its back faces, lit as front ones
        auto lumenMapper = vtkSmartPointer<vtkPolyDataMapper>::New();
        lumenMapper->ScalarVisibilityOff();
        lumen->SetMapper(lumenMapper);
        lumen->GetProperty()->SetColor(kTissue[0], kTissue[1], kTissue[2]);
        lumen->GetProperty()->SetSpecular(0.35);
        lumen->GetProperty()->SetSpecularPower(25.0);
        lumen->SetVisibility(false);
        renderer->AddActor(lumen);
        cellMapper->SetSourceData(bloodCellShape());
        cellMapper->SetOrientationArray("orientation");
        cellMapper->SetOrientationModeToDirection();
        cellMapper->ScalingOn();
        cellMapper->SetScaleModeToNoDataScaling();
        cellMapper->ScalarVisibilityOff();
        cells->SetMapper(cellMapper);
        cells->GetProperty()->SetColor(kBloodCell[0], kBloodCell[1], kBloodCell[2]);
        cells->SetVisibility(false);
        renderer->AddActor(cells);
        vtkCamera* camera = renderer->GetActiveCamera();
        camera->UseHorizontalViewAngleOn();
        camera->SetClippingRange(kNearMm, kFarMm);
    }
    ~Pipeline() { window->Finalize(); }
};

EndoscopeView::EndoscopeView(QWidget* parent) : QWidget(parent), m_pipeline(std::make_unique<Pipeline>())
{
    setMinimumSize(320, 240);
    setAttribute(Qt::WA_OpaquePaintEvent);
}

EndoscopeView::~EndoscopeView() = default;

void EndoscopeView::setLumen(const TriangleMesh& surface)
{
    auto normals = vtkSmartPointer<vtkPolyDataNormals>::New();
    normals->SetInputData(interop::toVtk(surface));
    normals->SplittingOff();
    normals->Update();
    static_cast<vtkPolyDataMapper*>(m_pipeline->lumen->GetMapper())->SetInputData(normals->GetOutput());
    m_pipeline->lumen->SetVisibility(!surface.triangles.empty());
    m_dirty = true;
    update();
}

bool EndoscopeView::hasLumen() const
{
    return m_pipeline->lumen->GetVisibility();
}

void EndoscopeView::setParticles(const std::vector<Eigen::Vector3d>& pointsMm, double radiusMm)
{
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto orientation = vtkSmartPointer<vtkFloatArray>::New();
    orientation->SetName("orientation");
    orientation->SetNumberOfComponents(3);
    std::mt19937 random(7); // each cell's tumble, the same every frame for the same index
    std::normal_distribution<float> gauss;
    for (const Eigen::Vector3d& p : pointsMm)
    {
        points->InsertNextPoint(p.x(), p.y(), p.z());
        const float axis[3] = {gauss(random), gauss(random), gauss(random)};
        orientation->InsertNextTuple(axis);
    }
    auto cloud = vtkSmartPointer<vtkPolyData>::New();
    cloud->SetPoints(points);
    cloud->GetPointData()->AddArray(orientation);
    m_pipeline->cellMapper->SetInputData(cloud);
    m_pipeline->cellMapper->SetScaleFactor(radiusMm);
    m_pipeline->cells->SetVisibility(!pointsMm.empty());
    m_pipeline->cellCount = pointsMm.size();
    m_dirty = true;
    update();
}

std::size_t EndoscopeView::particleCount() const
{
    return m_pipeline->cellCount;
}

void EndoscopeView::setPose(const Eigen::Vector3d& positionMm, const Eigen::Vector3d& forward,
                            const Eigen::Vector3d& up)
{
    vtkCamera* camera = m_pipeline->renderer->GetActiveCamera();
    const Eigen::Vector3d target = positionMm + 10.0 * forward;
    camera->SetPosition(positionMm.data());
    camera->SetFocalPoint(target.data());
    camera->SetViewUp(up.data());
    camera->SetClippingRange(kNearMm, kFarMm);
    m_dirty = true;
    update();
}

void EndoscopeView::setLens(const EndoscopeLens& lens)
{
    m_lens = lens;
    m_dirty = true;
    update();
}

QImage EndoscopeView::picture()
{
    renderIfNeeded();
    return m_picture;
}

QImage EndoscopeView::sharpPicture()
{
    renderIfNeeded();
    return m_sharp;
}

void EndoscopeView::renderIfNeeded()
{
    if (!m_dirty && !m_picture.isNull())
        return;
    const double ratio = devicePixelRatioF();
    int width = std::max(16, int(std::lround(this->width() * ratio)));
    int height = std::max(16, int(std::lround(this->height() * ratio)));
    if (width > kMaxWidthPx)
    {
        height = std::max(16, height * kMaxWidthPx / width);
        width = kMaxWidthPx;
    }
    m_pipeline->renderer->GetActiveCamera()->SetViewAngle(horizontalFieldOfViewDegrees(m_lens));
    m_pipeline->renderer->GetActiveCamera()->SetClippingRange(kNearMm, kFarMm);
    vtkRenderWindow* window = m_pipeline->window;
    window->SetSize(width, height);
    window->Render();

    // The colour (rows bottom-up) and the depth buffer, linearised to the distance along the view axis.
    unsigned char* rgb = window->GetPixelData(0, 0, width - 1, height - 1, 0);
    float* z = window->GetZbufferData(0, 0, width - 1, height - 1);
    m_sharp = QImage(width, height, QImage::Format_RGB888);
    m_depth.assign(std::size_t(width) * std::size_t(height), std::numeric_limits<float>::infinity());
    for (int y = 0; y < height; ++y)
    {
        std::memcpy(m_sharp.scanLine(height - 1 - y),
                    rgb + std::size_t(3) * std::size_t(y) * std::size_t(width), std::size_t(3 * width));
        for (int x = 0; x < width; ++x)
        {
            const double depth = z[std::size_t(y) * std::size_t(width) + std::size_t(x)];
            if (depth >= 1.0)
                continue; // nothing drawn: the view goes on past the far plane
            const double ndc = 2.0 * depth - 1.0;
            m_depth[std::size_t(height - 1 - y) * std::size_t(width) + std::size_t(x)] =
                float(2.0 * kNearMm * kFarMm / (kFarMm + kNearMm - ndc * (kFarMm - kNearMm)));
        }
    }
    delete[] rgb;
    delete[] z;
    m_picture = lensImage(m_sharp, m_depth, m_lens, ++m_frame, &m_medianBlurPx);
    m_dirty = false;
}

void EndoscopeView::paintEvent(QPaintEvent*)
{
    QPainter painter(this);
    painter.fillRect(rect(), Qt::black);
    if (!hasLumen())
        return;
    const QImage shown = picture();
    painter.setRenderHint(QPainter::SmoothPixmapTransform);
    painter.drawImage(rect(), shown);
}

void EndoscopeView::resizeEvent(QResizeEvent* event)
{
    m_dirty = true;
    QWidget::resizeEvent(event);
}

} // namespace vsim::viz
