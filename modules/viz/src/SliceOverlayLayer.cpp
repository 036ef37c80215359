#include "SliceOverlayLayer.h"
#include "SliceDepths.h"
#include "TextFonts.h"
#include "vsim/viz/DecimalText.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
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

constexpr double kGapPixels = 10.0;  // the crosshair leaves the cursor's surroundings free
constexpr double kMarginFraction = 0.08; // the scale bar's distance from the view's bottom edge
const Eigen::Vector3d kTextColour(1.0, 0.85, 0.2);

vtkSmartPointer<vtkActor> lineActor(double width)
{
    auto actor = vtkSmartPointer<vtkActor>::New();
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputData(vtkSmartPointer<vtkPolyData>::New());
    mapper->SetScalarModeToUseCellData();
    actor->SetMapper(mapper);
    actor->GetProperty()->SetLineWidth(float(width));
    actor->GetProperty()->LightingOff();
    return actor;
}

/// Line segments (x0, y0, x1, y1) with a colour each, as the actor's poly data.
void setSegments(vtkActor* actor, const std::vector<std::array<double, 4>>& segments, const std::vector<Eigen::Vector3d>& colours)
{
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto lines = vtkSmartPointer<vtkCellArray>::New();
    auto scalars = vtkSmartPointer<vtkUnsignedCharArray>::New();
    scalars->SetNumberOfComponents(3);
    for (std::size_t s = 0; s < segments.size(); ++s)
    {
        const vtkIdType ids[2] = {points->InsertNextPoint(segments[s][0], segments[s][1], slice_depth::kOverlay),
                                  points->InsertNextPoint(segments[s][2], segments[s][3], slice_depth::kOverlay)};
        lines->InsertNextCell(2, ids);
        scalars->InsertNextTuple3(255.0 * colours[s][0], 255.0 * colours[s][1], 255.0 * colours[s][2]);
    }
    auto data = vtkSmartPointer<vtkPolyData>::New();
    data->SetPoints(points);
    data->SetLines(lines);
    data->GetCellData()->SetScalars(scalars);
    static_cast<vtkPolyDataMapper*>(actor->GetMapper())->SetInputData(data);
}

vtkSmartPointer<vtkTextActor> cornerActor(Qt::Corner corner)
{
    const bool left = corner == Qt::TopLeftCorner || corner == Qt::BottomLeftCorner;
    const bool top = corner == Qt::TopLeftCorner || corner == Qt::TopRightCorner;
    auto text = vtkSmartPointer<vtkTextActor>::New();
    vtkTextProperty* property = text->GetTextProperty();
    property->SetFontSize(12);
    property->SetColor(kTextColour.data());
    property->SetJustification(left ? VTK_TEXT_LEFT : VTK_TEXT_RIGHT);
    property->SetVerticalJustification(top ? VTK_TEXT_TOP : VTK_TEXT_BOTTOM);
    text->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    text->GetPositionCoordinate()->SetValue(left ? 0.01 : 0.99, top ? 0.99 : 0.01);
    return text;
}

} // namespace

double roundLengthBelow(double limit)
{
    const double decade = std::pow(10.0, std::floor(std::log10(limit)));
    for (double mantissa : {5.0, 2.0, 1.0})
        if (mantissa * decade <= limit)
            return mantissa * decade;
    return decade;
}

SliceOverlayLayer::SliceOverlayLayer(vtkRenderer* renderer)
    : m_renderer(renderer), m_crosshair(lineActor(1.0)), m_scaleBar(lineActor(2.0)),
      m_scaleText(vtkSmartPointer<vtkTextActor>::New())
{
    m_renderer->AddViewProp(m_crosshair);
    m_renderer->AddViewProp(m_scaleBar);
    m_scaleText->GetTextProperty()->SetFontSize(11);
    m_scaleText->GetTextProperty()->SetColor(kTextColour.data());
    m_scaleText->GetTextProperty()->SetJustification(VTK_TEXT_CENTERED);
    m_scaleText->GetTextProperty()->SetVerticalJustification(VTK_TEXT_BOTTOM);
    m_scaleText->GetPositionCoordinate()->SetCoordinateSystemToWorld();
    m_renderer->AddViewProp(m_scaleText);
    for (Qt::Corner corner : {Qt::TopLeftCorner, Qt::TopRightCorner, Qt::BottomLeftCorner, Qt::BottomRightCorner})
    {
        m_corners[std::size_t(corner)] = cornerActor(corner);
        m_renderer->AddViewProp(m_corners[std::size_t(corner)]);
    }
    setCrosshairColours({0.3, 0.9, 0.3}, {0.95, 0.85, 0.2});
}

SliceOverlayLayer::~SliceOverlayLayer() = default;

void SliceOverlayLayer::setCrosshairColours(const Eigen::Vector3d& horizontal, const Eigen::Vector3d& vertical)
{
    m_crosshairColours = {horizontal, vertical};
}

void SliceOverlayLayer::setCrosshairShown(bool shown)
{
    m_crosshairShown = shown;
    m_crosshair->SetVisibility(shown);
}

void SliceOverlayLayer::update(const Eigen::Vector2d& crosshairMm, int widthPixels, int heightPixels, double mmPerPixel)
{
    const double halfWidth = 0.5 * widthPixels * mmPerPixel, halfHeight = 0.5 * heightPixels * mmPerPixel;
    const double gap = kGapPixels * mmPerPixel;
    const double x = crosshairMm.x(), y = crosshairMm.y();
    setSegments(m_crosshair,
                {{-halfWidth, y, x - gap, y}, {x + gap, y, halfWidth, y}, {x, -halfHeight, x, y - gap}, {x, y + gap, x, halfHeight}},
                {m_crosshairColours[0], m_crosshairColours[0], m_crosshairColours[1], m_crosshairColours[1]});
    m_crosshair->SetVisibility(m_crosshairShown && widthPixels > 0);

    m_scaleBarMm = widthPixels > 0 ? roundLengthBelow(0.25 * 2.0 * halfWidth) : 0.0;
    const double left = 0.1 * halfWidth, right = left + m_scaleBarMm;
    const double bottom = -halfHeight + kMarginFraction * 2.0 * halfHeight, tick = 4.0 * mmPerPixel;
    setSegments(m_scaleBar, {{left, bottom, right, bottom}, {left, bottom, left, bottom + tick}, {right, bottom, right, bottom + tick}},
                {kTextColour, kTextColour, kTextColour});
    m_scaleBar->SetVisibility(m_scaleBarMm > 0.0);
    m_scaleText->SetInput(QStringLiteral("%1 mm").arg(significantText(m_scaleBarMm, 3)).toUtf8().constData());
    m_scaleText->GetPositionCoordinate()->SetValue(0.5 * (left + right), bottom + 1.5 * tick, slice_depth::kOverlay);
    m_scaleText->SetVisibility(m_scaleBarMm > 0.0);
}

void SliceOverlayLayer::setPixelScale(double scale)
{
    m_pixelScale = scale;
    for (auto& corner : m_corners)
        corner->GetTextProperty()->SetFontSize(int(std::lround(12 * scale)));
    m_scaleText->GetTextProperty()->SetFontSize(int(std::lround(11 * scale)));
    m_crosshair->GetProperty()->SetLineWidth(float(1.0 * scale));
    m_scaleBar->GetProperty()->SetLineWidth(float(2.0 * scale));
}

void SliceOverlayLayer::setCornerText(Qt::Corner corner, const QString& text)
{
    m_cornerTexts[std::size_t(corner)] = text;
    setActorText(m_corners[std::size_t(corner)], text);
}

} // namespace vsim::viz
