#include "vsim/viz/VolumeView3D.h"

#include "FieldScene.h"
#include "TitleLines.h"
#include "ViewLegend.h"
#include "VolumeProperties.h"

#include "vsim/core/Error.h"
#include "vsim/interop/VtkImage.h"
#include "vsim/interop/VtkMesh.h"

#include <Eigen/Geometry>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellPicker.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkColorTransferFunction.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkLookupTable.h>
#include <vtkMatrix4x4.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPointData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkScalarsToColors.h>
#include <vtkTextProperty.h>
#include <vtkTubeFilter.h>
#include <vtkUnsignedCharArray.h>
#include <vtkSmartVolumeMapper.h>
#include <vtkVolume.h>
#include <vtkVolumeProperty.h>

#include <QMouseEvent>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace vsim::viz {

using detail::fieldMapper;

using detail::kPointsLegendX;
using detail::kSurfaceLegendX;
using detail::lineWidthsPixels;
using detail::showLegendIn;

struct VolumeView3D::Scene
{
    vtkSmartPointer<vtkImageData> scaledIndexImage;
    vtkSmartPointer<vtkSmartVolumeMapper> mapper = vtkSmartPointer<vtkSmartVolumeMapper>::New();
    vtkSmartPointer<vtkVolume> volume = vtkSmartPointer<vtkVolume>::New();
    vtkSmartPointer<vtkVolumeProperty> rendered, maximumIntensity;
    VolumeStyle style = VolumeStyle::Rendered;
    std::vector<vtkSmartPointer<vtkActor>> surfaces;
    std::vector<vtkSmartPointer<vtkActor>> lines;
    std::vector<vtkSmartPointer<vtkProp>> callouts;
    std::size_t calloutCount = 0;
    vtkSmartPointer<vtkActor> fieldSurface, fieldLines, tubelets;
    // The field volume (a smoke run's density): its own mapper and prop beside the CT's.
    RealVolume fieldVoxels;
    vtkSmartPointer<vtkSmartVolumeMapper> fieldMapper;
    vtkSmartPointer<vtkVolume> fieldVolume;
    Eigen::Vector3d fieldLow = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN()), fieldHigh;
    vtkSmartPointer<vtkRenderer> overlay; // layer 1: the tubelets on top of the vessels
    int tubeletQuads = 0;
    vtkSmartPointer<vtkScalarBarActor> legend, surfaceLegend; // points and lines on the right, surfaces on the left
    QString legendTitle, surfaceLegendTitle;
    int lineCount = 0;
};

VolumeView3D::VolumeView3D(QWidget* parent) : VtkView(parent), m_scene(std::make_unique<Scene>())
{
    m_scene->rendered = detail::ctaRenderedProperty();
    m_scene->maximumIntensity = detail::ctaMaximumIntensityProperty();
    m_scene->volume->SetMapper(m_scene->mapper);
    m_scene->volume->SetProperty(m_scene->rendered);
    m_scene->volume->VisibilityOff();
    renderer()->AddVolume(m_scene->volume);
    renderer()->SetBackground(0.08, 0.09, 0.12);
}

VolumeView3D::~VolumeView3D() = default;

void VolumeView3D::setImage(const CtVolume& image)
{
    m_image = image;
    // The mapper sees the CT in index * spacing space; the prop's user matrix places it in the patient frame.
    m_scene->scaledIndexImage = interop::toVtk(m_image);
    m_scene->scaledIndexImage->SetOrigin(0.0, 0.0, 0.0);
    const double identity[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    m_scene->scaledIndexImage->SetDirectionMatrix(identity);
    m_scene->mapper->SetInputData(m_scene->scaledIndexImage);
    m_scene->volume->SetUserMatrix(interop::scaledIndexToPatient(m_image.geometry()));
    m_scene->volume->VisibilityOn();
    showAnteriorView();
}

void VolumeView3D::clearImage()
{
    m_image = CtVolume();
    m_scene->volume->VisibilityOff();
    update();
}

void VolumeView3D::showFieldVolume(const RealVolume& field, double low, double high, const QString& legendTitle)
{
    Scene& scene = *m_scene;
    if (!scene.fieldVolume)
    {
        scene.fieldMapper = vtkSmartPointer<vtkSmartVolumeMapper>::New();
        scene.fieldVolume = vtkSmartPointer<vtkVolume>::New();
        scene.fieldVolume->SetMapper(scene.fieldMapper);
        renderer()->AddVolume(scene.fieldVolume);
    }
    scene.fieldVoxels = field;
    vtkSmartPointer<vtkImageData> image = interop::toVtk(scene.fieldVoxels);
    image->SetOrigin(0.0, 0.0, 0.0);
    const double identity[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    image->SetDirectionMatrix(identity);
    scene.fieldMapper->SetInputData(image);
    scene.fieldVolume->SetUserMatrix(interop::scaledIndexToPatient(field.geometry()));
    const vtkSmartPointer<vtkVolumeProperty> property = detail::smokeProperty(low, high);
    scene.fieldVolume->SetProperty(property);
    scene.fieldVolume->VisibilityOn();
    showLegend(property->GetRGBTransferFunction(), legendTitle);
    // A new box (a new run): frame it.
    const VolumeGeometry& geometry = field.geometry();
    const Eigen::Vector3d first = geometry.indexToPatient(Eigen::Vector3d::Zero());
    const Eigen::Vector3d last = geometry.indexToPatient(
        Eigen::Vector3d(geometry.dims[0] - 1, geometry.dims[1] - 1, geometry.dims[2] - 1));
    const Eigen::Vector3d lowMm = first.cwiseMin(last), highMm = first.cwiseMax(last);
    if (!(lowMm.isApprox(scene.fieldLow) && highMm.isApprox(scene.fieldHigh)))
    {
        scene.fieldLow = lowMm, scene.fieldHigh = highMm;
        showAnteriorViewOf(lowMm, highMm);
    }
    update();
}

void VolumeView3D::clearFieldVolume()
{
    if (m_scene->fieldVolume)
        m_scene->fieldVolume->VisibilityOff();
    m_scene->fieldVoxels = RealVolume();
    update();
}

bool VolumeView3D::hasFieldVolume() const
{
    return m_scene->fieldVolume && m_scene->fieldVolume->GetVisibility();
}

void VolumeView3D::addSurface(const TriangleMesh& surface, const QColor& colour)
{
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputData(interop::toVtk(surface));
    mapper->ScalarVisibilityOff();
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(colour.redF(), colour.greenF(), colour.blueF());
    actor->GetProperty()->SetOpacity(colour.alphaF());
    renderer()->AddActor(actor);
    m_scene->surfaces.push_back(actor);
    update();
}

void VolumeView3D::showCallouts(const std::vector<Callout>& callouts)
{
    for (const auto& prop : m_scene->callouts)
        renderer()->RemoveViewProp(prop);
    const int fontSize = std::max(12, height() / 45);
    m_scene->callouts = detail::calloutProps(callouts, fontSize, width(), height());
    for (const auto& prop : m_scene->callouts)
        renderer()->AddViewProp(prop);
    m_scene->calloutCount = callouts.size();
    update();
}

std::size_t VolumeView3D::calloutCount() const { return m_scene->calloutCount; }

void VolumeView3D::clearSurfaces()
{
    showCallouts({});
    for (const auto& actor : m_scene->surfaces)
        renderer()->RemoveActor(actor);
    m_scene->surfaces.clear();
    if (m_scene->fieldSurface)
        renderer()->RemoveActor(m_scene->fieldSurface);
    m_scene->fieldSurface = nullptr;
    if (m_scene->surfaceLegend)
        m_scene->surfaceLegend->SetVisibility(false);
    if (m_scene->legendTitle == m_scene->surfaceLegendTitle)
        m_scene->legendTitle.clear();
    m_scene->surfaceLegendTitle.clear();
    update();
}

void VolumeView3D::showFieldSurface(const TriangleMesh& surface, const std::string& field, double low, double high,
                                    const QString& legendTitle)
{
    const auto values = surface.pointFields.find(field);
    if (values == surface.pointFields.end())
        throw Error(Pattern{"the surface has no field '%1' to colour by", {field}});
    // A surface of the same size as the one shown (the interactive wall, frame after frame) only gets new
    // points and values; anything else builds a new actor.
    vtkPolyData* shown = m_scene->fieldSurface
                             ? vtkPolyData::SafeDownCast(m_scene->fieldSurface->GetMapper()->GetInput())
                             : nullptr;
    if (shown && shown->GetNumberOfPoints() == vtkIdType(surface.points.size()) &&
        shown->GetNumberOfPolys() == vtkIdType(surface.triangles.size()))
    {
        vtkPoints* points = shown->GetPoints();
        vtkDataArray* scalars = shown->GetPointData()->GetScalars();
        for (std::size_t i = 0; i < surface.points.size(); ++i)
        {
            points->SetPoint(vtkIdType(i), surface.points[i].data());
            scalars->SetTuple1(vtkIdType(i), values->second[i]);
        }
        points->Modified();
        scalars->Modified();
        shown->Modified();
        m_scene->fieldSurface->GetMapper()->SetScalarRange(low, high);
        vtkLookupTable::SafeDownCast(m_scene->fieldSurface->GetMapper()->GetLookupTable())->SetTableRange(low, high);
    }
    else
    {
        vtkSmartPointer<vtkPolyData> polyData = detail::fieldSurface(surface, field);
        vtkSmartPointer<vtkPolyDataMapper> mapper = fieldMapper(polyData, low, high);
        mapper->SetScalarModeToUsePointData();
        if (m_scene->fieldSurface)
            renderer()->RemoveActor(m_scene->fieldSurface);
        m_scene->fieldSurface = vtkSmartPointer<vtkActor>::New();
        m_scene->fieldSurface->SetMapper(mapper);
        renderer()->AddActor(m_scene->fieldSurface);
    }
    // The surface's own legend, on the left: particles or lines shown with it keep theirs on the right.
    showLegendIn(renderer(), m_scene->surfaceLegend, kSurfaceLegendX,
                 m_scene->fieldSurface->GetMapper()->GetLookupTable(), legendTitle, devicePixelRatioF());
    m_scene->surfaceLegendTitle = m_scene->legendTitle = legendTitle;
    update();
}

void VolumeView3D::setFieldSurfaceOpacity(double opacity)
{
    if (m_scene->fieldSurface)
        m_scene->fieldSurface->GetProperty()->SetOpacity(std::clamp(opacity, 0.0, 1.0));
    update();
}

QString VolumeView3D::surfaceLegendTitle() const { return m_scene->surfaceLegendTitle; }

QStringList VolumeView3D::legendLabels(bool surface) const
{
    vtkScalarBarActor* legend = surface ? m_scene->surfaceLegend : m_scene->legend;
    QStringList labels;
    if (!legend || !legend->GetVisibility() || !legend->GetLookupTable())
        return labels;
    vtkScalarsToColors* table = legend->GetLookupTable();
    for (vtkIdType n = 0; n < table->GetNumberOfAnnotatedValues(); ++n)
        labels << QString::fromStdString(table->GetAnnotation(n));
    return labels;
}

QStringList VolumeView3D::legendTitleLines(bool surface) const
{
    vtkScalarBarActor* legend = surface ? m_scene->surfaceLegend : m_scene->legend;
    if (!legend || !legend->GetVisibility() || !legend->GetTitle())
        return {};
    return QString::fromUtf8(legend->GetTitle()).split('\n');
}

bool VolumeView3D::legendTitleWithinView(bool surface) const
{
    vtkScalarBarActor* legend = surface ? m_scene->surfaceLegend : m_scene->legend;
    const QStringList lines = legendTitleLines(surface);
    if (lines.isEmpty())
        return false;
    const int* size = renderer()->GetSize(); // device pixels
    const double middle = (legend->GetPosition()[0] + 0.5 * legend->GetWidth()) * double(size[0]);
    for (int width : lineWidthsPixels(lines.join('\n'), legend->GetTitleTextProperty(), renderWindow()->GetDPI()))
        if (middle - 0.5 * width < 0.0 || middle + 0.5 * width > double(size[0]))
            return false;
    return true;
}

void VolumeView3D::showLegend(vtkScalarsToColors* table, const QString& title)
{
    showLegendIn(renderer(), m_scene->legend, kPointsLegendX, table, title, devicePixelRatioF());
    m_scene->legendTitle = title;
    update();
}

void VolumeView3D::showFieldLines(const std::vector<std::vector<Eigen::Vector3d>>& lines, const std::vector<double>& values,
                                  double low, double high, double widthPixels, const QString& legendTitle,
                                  const std::vector<std::array<double, 2>>& radiiMm)
{
    vtkSmartPointer<vtkPolyData> polyData = detail::fieldTubes(lines, values, radiiMm);
    clearFieldLines();
    vtkSmartPointer<vtkPolyDataMapper> mapper = fieldMapper(polyData, low, high);
    mapper->SetScalarModeToUseCellData();
    m_scene->fieldLines = vtkSmartPointer<vtkActor>::New();
    m_scene->fieldLines->SetMapper(mapper);
    m_scene->fieldLines->GetProperty()->SetLineWidth(float(widthPixels * devicePixelRatioF())); // screen pixels
    m_scene->fieldLines->GetProperty()->SetLighting(!radiiMm.empty());
    renderer()->AddActor(m_scene->fieldLines);
    showLegend(mapper->GetLookupTable(), legendTitle);
}

void VolumeView3D::showFieldPoints(const std::vector<Eigen::Vector3d>& points, const std::vector<double>& values,
                                   double low, double high, double sizePixels, const QString& legendTitle)
{
    if (values.size() != points.size())
        throw Error("field points need one value per point");
    auto vertices = vtkSmartPointer<vtkCellArray>::New();
    for (vtkIdType i = 0; i < vtkIdType(points.size()); ++i)
        vertices->InsertNextCell(1, &i);
    auto scalars = vtkSmartPointer<vtkDoubleArray>::New();
    scalars->SetName("value");
    for (double v : values)
        scalars->InsertNextValue(v);
    auto polyData = vtkSmartPointer<vtkPolyData>::New();
    auto vtkPointsMm = vtkSmartPointer<vtkPoints>::New();
    vtkPointsMm->SetDataTypeToDouble();
    for (const Eigen::Vector3d& p : points)
        vtkPointsMm->InsertNextPoint(p.data());
    polyData->SetPoints(vtkPointsMm);
    polyData->SetVerts(vertices);
    polyData->GetPointData()->SetScalars(scalars);
    clearFieldLines();
    vtkSmartPointer<vtkPolyDataMapper> mapper = fieldMapper(polyData, low, high);
    mapper->SetScalarModeToUsePointData();
    m_scene->fieldLines = vtkSmartPointer<vtkActor>::New();
    m_scene->fieldLines->SetMapper(mapper);
    m_scene->fieldLines->GetProperty()->SetPointSize(float(sizePixels * devicePixelRatioF())); // screen pixels
    m_scene->fieldLines->GetProperty()->SetRenderPointsAsSpheres(true);
    renderer()->AddActor(m_scene->fieldLines);
    showLegend(mapper->GetLookupTable(), legendTitle);
}

void VolumeView3D::clearFieldLines()
{
    if (m_scene->fieldLines)
        renderer()->RemoveActor(m_scene->fieldLines);
    m_scene->fieldLines = nullptr;
    if (m_scene->legend)
        m_scene->legend->SetVisibility(false);
    m_scene->legendTitle = m_scene->surfaceLegendTitle;
    update();
}

int VolumeView3D::showTubelets(const std::vector<std::vector<Eigen::Vector3d>>& trails, double widthMm, const QColor& colour)
{
    // The tubelets run inside the vessels: they are drawn in an overlay layer with the same camera, on top.
    if (!m_scene->overlay)
    {
        m_scene->overlay = vtkSmartPointer<vtkRenderer>::New();
        m_scene->overlay->SetLayer(1);
        m_scene->overlay->InteractiveOff();
        m_scene->overlay->SetActiveCamera(renderer()->GetActiveCamera());
        renderWindow()->SetNumberOfLayers(2);
        renderWindow()->AddRenderer(m_scene->overlay);
    }
    if (m_scene->tubelets)
        m_scene->overlay->RemoveActor(m_scene->tubelets);
    m_scene->tubelets = nullptr;
    m_scene->tubeletQuads = 0;
    double view[3];
    renderer()->GetActiveCamera()->GetDirectionOfProjection(view);
    const Eigen::Vector3d towardsViewer = -Eigen::Vector3d(view[0], view[1], view[2]).normalized();
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto quads = vtkSmartPointer<vtkCellArray>::New();
    auto colours = vtkSmartPointer<vtkUnsignedCharArray>::New();
    colours->SetNumberOfComponents(4);
    for (const auto& trail : trails)
        for (std::size_t i = 0; i + 1 < trail.size(); ++i)
        {
            const Eigen::Vector3d along = trail[i + 1] - trail[i];
            Eigen::Vector3d side = along.cross(towardsViewer);
            if (side.norm() < 1e-9)
                continue;
            side = 0.5 * widthMm * side.normalized();
            // Opacity falls from the head (i = 0) to the tail: the washing-out look of the thesis's figure 6.9.
            const double a0 = 1.0 - double(i) / double(trail.size() - 1), a1 = 1.0 - double(i + 1) / double(trail.size() - 1);
            quads->InsertNextCell(4);
            for (const auto& [point, alpha] : {std::pair{Eigen::Vector3d(trail[i] - side), a0}, std::pair{Eigen::Vector3d(trail[i] + side), a0},
                                               std::pair{Eigen::Vector3d(trail[i + 1] + side), a1},
                                               std::pair{Eigen::Vector3d(trail[i + 1] - side), a1}})
            {
                quads->InsertCellPoint(points->InsertNextPoint(point.x(), point.y(), point.z()));
                const unsigned char rgba[4] = {static_cast<unsigned char>(colour.red()), static_cast<unsigned char>(colour.green()),
                                               static_cast<unsigned char>(colour.blue()),
                                               static_cast<unsigned char>(std::lround(255.0 * alpha))};
                colours->InsertNextTypedTuple(rgba);
            }
            ++m_scene->tubeletQuads;
        }
    auto polyData = vtkSmartPointer<vtkPolyData>::New();
    polyData->SetPoints(points);
    polyData->SetPolys(quads);
    polyData->GetPointData()->SetScalars(colours);
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputData(polyData);
    mapper->SetColorModeToDirectScalars();
    mapper->ScalarVisibilityOn();
    m_scene->tubelets = vtkSmartPointer<vtkActor>::New();
    m_scene->tubelets->SetMapper(mapper);
    m_scene->tubelets->GetProperty()->SetLighting(false);
    m_scene->overlay->AddActor(m_scene->tubelets);
    update();
    return m_scene->tubeletQuads;
}

int VolumeView3D::tubeletQuadCount() const { return m_scene->tubeletQuads; }

QString VolumeView3D::legendTitle() const { return m_scene->legendTitle; }

void VolumeView3D::setSurfaceOpacity(double opacity)
{
    for (const auto& actor : m_scene->surfaces)
        actor->GetProperty()->SetOpacity(std::clamp(opacity, 0.0, 1.0));
    update();
}

void VolumeView3D::addLines(const SkeletonGraph& graph, const QColor& colour, double widthPixels)
{
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto cells = vtkSmartPointer<vtkCellArray>::New();
    for (const SkeletonGraph::Edge& edge : graph.edges)
    {
        cells->InsertNextCell(vtkIdType(edge.points.size()));
        for (const Eigen::Vector3d& point : edge.points)
            cells->InsertCellPoint(points->InsertNextPoint(point.x(), point.y(), point.z()));
    }
    auto polyData = vtkSmartPointer<vtkPolyData>::New();
    polyData->SetPoints(points);
    polyData->SetLines(cells);
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputData(polyData);
    mapper->ScalarVisibilityOff();
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(colour.redF(), colour.greenF(), colour.blueF());
    actor->GetProperty()->SetLineWidth(float(widthPixels * devicePixelRatioF())); // screen pixels
    actor->GetProperty()->SetLighting(false);
    renderer()->AddActor(actor);
    m_scene->lines.push_back(actor);
    m_scene->lineCount += int(graph.edges.size());
    update();
}

void VolumeView3D::clearLines()
{
    for (const auto& actor : m_scene->lines)
        renderer()->RemoveActor(actor);
    m_scene->lines.clear();
    m_scene->lineCount = 0;
    update();
}

int VolumeView3D::lineCount() const { return m_scene->lineCount; }

void VolumeView3D::setVolumeStyle(VolumeStyle style)
{
    m_scene->style = style;
    const bool mip = style == VolumeStyle::MaximumIntensity;
    m_scene->mapper->SetBlendMode(mip ? vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND : vtkVolumeMapper::COMPOSITE_BLEND);
    m_scene->volume->SetProperty(mip ? m_scene->maximumIntensity : m_scene->rendered);
    update();
}

VolumeView3D::VolumeStyle VolumeView3D::volumeStyle() const { return m_scene->style; }

void VolumeView3D::setVolumeVisible(bool visible)
{
    m_scene->volume->SetVisibility(visible && !m_image.isEmpty());
    update();
}

Eigen::Vector3d VolumeView3D::volumeCentre() const
{
    if (m_image.isEmpty())
        return Eigen::Vector3d::Zero();
    const VolumeGeometry& geometry = m_image.geometry();
    return geometry.indexToPatient(0.5 * Eigen::Vector3d(geometry.dims[0] - 1, geometry.dims[1] - 1, geometry.dims[2] - 1));
}

std::optional<Eigen::Vector3d> VolumeView3D::surfacePointAt(const QPointF& position) const
{
    auto picker = vtkSmartPointer<vtkCellPicker>::New();
    picker->SetTolerance(0.002);
    picker->PickFromListOn();
    bool any = false;
    for (const auto& actor : m_scene->surfaces)
        picker->AddPickList(actor), any = true;
    if (m_scene->fieldSurface)
        picker->AddPickList(m_scene->fieldSurface), any = true;
    if (m_scene->fieldLines)
        picker->AddPickList(m_scene->fieldLines), any = true;
    if (!any)
        return std::nullopt;
    const double ratio = devicePixelRatioF();
    if (!picker->Pick(position.x() * ratio, (height() - position.y()) * ratio, 0.0, renderer()))
        return std::nullopt;
    double point[3];
    picker->GetPickPosition(point);
    return Eigen::Vector3d(point[0], point[1], point[2]);
}

Eigen::Vector3d VolumeView3D::pointAtDepthOf(const QPointF& position, const Eigen::Vector3d& reference) const
{
    vtkRenderer* r = renderer();
    r->SetWorldPoint(reference.x(), reference.y(), reference.z(), 1.0);
    r->WorldToDisplay();
    double display[3];
    r->GetDisplayPoint(display);
    const double ratio = devicePixelRatioF();
    r->SetDisplayPoint(position.x() * ratio, (height() - position.y()) * ratio, display[2]);
    r->DisplayToWorld();
    double world[4];
    r->GetWorldPoint(world);
    return Eigen::Vector3d(world[0], world[1], world[2]) / (world[3] != 0.0 ? world[3] : 1.0);
}

void VolumeView3D::mousePressEvent(QMouseEvent* event)
{
    if (m_pickEnabled && event->button() == Qt::LeftButton)
        if (const auto point = surfacePointAt(event->position()))
        {
            emit pointPicked(*point);
            return;
        }
    if (m_dragEnabled && event->button() == Qt::LeftButton)
        if (const auto point = surfacePointAt(event->position()))
        {
            m_grabbed = *point;
            emit pointGrabbed(*point);
            return;
        }
    VtkView::mousePressEvent(event);
}

void VolumeView3D::mouseMoveEvent(QMouseEvent* event)
{
    if (m_grabbed)
    {
        emit pointDragged(pointAtDepthOf(event->position(), *m_grabbed));
        return;
    }
    VtkView::mouseMoveEvent(event);
}

void VolumeView3D::mouseReleaseEvent(QMouseEvent* event)
{
    if (m_grabbed && event->button() == Qt::LeftButton)
    {
        m_grabbed.reset();
        emit pointReleased();
        return;
    }
    VtkView::mouseReleaseEvent(event);
}

void VolumeView3D::showAnteriorView(double heightMm) { showAnteriorView(volumeCentre(), heightMm); }

void VolumeView3D::showAnteriorView(const Eigen::Vector3d& centre, double heightMm)
{
    double height = heightMm;
    if (height <= 0.0 && !m_image.isEmpty())
    {
        const VolumeGeometry& geometry = m_image.geometry();
        height = 1.1 * geometry.spacing.cwiseProduct(Eigen::Vector3d(geometry.dims[0], geometry.dims[1], geometry.dims[2]))
                           .norm();
    }
    detail::lookFromFront(renderer()->GetActiveCamera(), centre, height);
    renderer()->ResetCameraClippingRange();
    update();
}

void VolumeView3D::showAnteriorViewOf(const Eigen::Vector3d& low, const Eigen::Vector3d& high)
{
    // From the front the screen's right is the patient's left (+x) and its top superior (+z); the legend starts at
    // kPointsLegendX of the width. The box, with a 10 % border, fits the height and kFramedShare of the width.
    const double aspect = double(std::max(1, width())) / double(std::max(1, height())); // width / height
    const Eigen::Vector3d size = (high - low) * 1.1;
    const double viewHeight = std::max({size.z(), size.x() / (kFramedShare * aspect), 1.0});
    const double viewWidth = viewHeight * aspect;
    Eigen::Vector3d centre = 0.5 * (low + high);
    centre.x() += 0.5 * size.x() - (kFramedShare - 0.5) * viewWidth; // the box's right edge at kFramedShare
    showAnteriorView(centre, viewHeight);
}

} // namespace vsim::viz
