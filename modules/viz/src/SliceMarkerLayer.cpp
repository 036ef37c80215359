#include "SliceMarkerLayer.h"
#include "SliceDepths.h"
#include "TextFonts.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCoordinate.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>

#include <cmath>

namespace vsim::viz {
namespace {

constexpr double kRingPixels = 7.0; // ring radius on screen
constexpr int kRingSegments = 24;

} // namespace

SliceMarkerLayer::SliceMarkerLayer(vtkRenderer* renderer)
    : m_renderer(renderer), m_rings(vtkSmartPointer<vtkActor>::New())
{
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputData(vtkSmartPointer<vtkPolyData>::New());
    mapper->SetScalarModeToUseCellData();
    m_rings->SetMapper(mapper);
    m_rings->GetProperty()->SetLineWidth(2.0);
    m_rings->GetProperty()->LightingOff();
    m_renderer->AddViewProp(m_rings);
}

SliceMarkerLayer::~SliceMarkerLayer() = default;

bool SliceMarkerLayer::moveMarker(int id, const Eigen::Vector3d& pointMm)
{
    for (SliceMarker& marker : m_markers)
        if (marker.id == id)
        {
            marker.pointMm = pointMm;
            return true;
        }
    return false;
}

void SliceMarkerLayer::update(const Eigen::Vector3d& cursorMm, const ScreenAxes& axes, double thicknessMm,
                              double mmPerPixel)
{
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto lines = vtkSmartPointer<vtkCellArray>::New();
    auto colours = vtkSmartPointer<vtkUnsignedCharArray>::New();
    colours->SetNumberOfComponents(3);
    for (auto& text : m_texts)
        m_renderer->RemoveViewProp(text);
    m_texts.clear();
    m_drawn.clear();
    const double radius = kRingPixels * mmPerPixel;
    for (const SliceMarker& marker : m_markers)
    {
        const Eigen::Vector3d offset = marker.pointMm - cursorMm;
        if (std::abs(offset.dot(axes.normal())) > thicknessMm)
            continue;
        m_drawn.push_back(marker.id);
        const double x = offset.dot(axes.right), y = offset.dot(axes.up);
        const vtkIdType first = points->GetNumberOfPoints();
        for (int s = 0; s < kRingSegments; ++s)
        {
            const double angle = 2.0 * M_PI * s / kRingSegments;
            points->InsertNextPoint(x + radius * std::cos(angle), y + radius * std::sin(angle), slice_depth::kMarkers);
        }
        std::vector<vtkIdType> ring(kRingSegments + 1);
        for (int s = 0; s <= kRingSegments; ++s)
            ring[std::size_t(s)] = first + s % kRingSegments;
        lines->InsertNextCell(vtkIdType(ring.size()), ring.data());
        colours->InsertNextTuple3(255.0 * marker.rgb[0], 255.0 * marker.rgb[1], 255.0 * marker.rgb[2]);
        if (marker.text.empty())
            continue;
        auto text = vtkSmartPointer<vtkTextActor>::New();
        setActorText(text, QString::fromStdString(marker.text));
        text->GetTextProperty()->SetFontSize(int(std::lround(13 * m_pixelScale)));
        text->GetTextProperty()->SetColor(marker.rgb[0], marker.rgb[1], marker.rgb[2]);
        text->GetPositionCoordinate()->SetCoordinateSystemToWorld();
        text->GetPositionCoordinate()->SetValue(x + 1.3 * radius, y + 0.3 * radius, slice_depth::kMarkers);
        m_renderer->AddViewProp(text);
        m_texts.push_back(text);
    }
    auto rings = vtkSmartPointer<vtkPolyData>::New();
    rings->SetPoints(points);
    rings->SetLines(lines);
    rings->GetCellData()->SetScalars(colours);
    static_cast<vtkPolyDataMapper*>(m_rings->GetMapper())->SetInputData(rings);
    m_rings->SetVisibility(!m_drawn.empty());
}

void SliceMarkerLayer::setPixelScale(double scale)
{
    m_pixelScale = scale;
    m_rings->GetProperty()->SetLineWidth(float(2.0 * scale));
}

std::optional<int> SliceMarkerLayer::pick(const Eigen::Vector3d& pointMm, double radiusMm) const
{
    std::optional<int> best;
    double bestDistance = radiusMm;
    for (const SliceMarker& marker : m_markers)
    {
        if (std::find(m_drawn.begin(), m_drawn.end(), marker.id) == m_drawn.end())
            continue;
        const double distance = (marker.pointMm - pointMm).norm();
        if (distance <= bestDistance)
            best = marker.id, bestDistance = distance;
    }
    return best;
}

} // namespace vsim::viz
