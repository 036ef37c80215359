#include "SliceMeasurementLayer.h"
#include "SliceDepths.h"
#include "TextFonts.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include <cmath>

namespace vsim::viz {
namespace {

constexpr int kEllipseSegments = 48;
const double kColour[3] = {0.3, 0.85, 1.0}; // cyan: apart from the crosshair's plane colours and the labels

} // namespace

SliceMeasurementLayer::SliceMeasurementLayer(vtkRenderer* renderer)
    : m_renderer(renderer), m_lines(vtkSmartPointer<vtkActor>::New())
{
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputData(vtkSmartPointer<vtkPolyData>::New());
    m_lines->SetMapper(mapper);
    m_lines->GetProperty()->SetColor(kColour[0], kColour[1], kColour[2]);
    m_lines->GetProperty()->SetLineWidth(2.0);
    m_lines->GetProperty()->LightingOff();
    m_renderer->AddViewProp(m_lines);
}

SliceMeasurementLayer::~SliceMeasurementLayer() = default;

void SliceMeasurementLayer::setPixelScale(double scale)
{
    m_pixelScale = scale;
    m_lines->GetProperty()->SetLineWidth(float(2.0 * scale));
}

void SliceMeasurementLayer::update(const Eigen::Vector3d& originMm, const ScreenAxes& axes, double thicknessMm)
{
    for (auto& text : m_texts)
        m_renderer->RemoveViewProp(text);
    m_texts.clear();
    m_shown = 0;
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto lines = vtkSmartPointer<vtkCellArray>::New();
    const Eigen::Vector3d normal = axes.normal();
    const auto toSlice = [&](const Eigen::Vector3d& p) {
        const Eigen::Vector3d offset = p - originMm;
        return Eigen::Vector2d(offset.dot(axes.right), offset.dot(axes.up));
    };
    const auto polyline = [&](const std::vector<Eigen::Vector2d>& corners) {
        std::vector<vtkIdType> ids;
        for (const Eigen::Vector2d& c : corners)
            ids.push_back(points->InsertNextPoint(c.x(), c.y(), slice_depth::kMeasurements));
        lines->InsertNextCell(vtkIdType(ids.size()), ids.data());
    };
    const auto draw = [&](const ViewMeasurement& m, const std::string& text) {
        std::vector<Eigen::Vector2d> p;
        for (const Eigen::Vector3d& point : m.pointsMm)
            p.push_back(toSlice(point));
        if (p.size() < 2)
            return;
        if (m.kind == ViewMeasurement::Kind::Roi)
        {
            const Eigen::Vector2d centre = 0.5 * (p[0] + p[1]), half = 0.5 * (p[1] - p[0]).cwiseAbs();
            std::vector<Eigen::Vector2d> ring;
            for (int s = 0; s <= kEllipseSegments; ++s)
            {
                const double angle = 2.0 * M_PI * s / kEllipseSegments;
                ring.emplace_back(centre.x() + half.x() * std::cos(angle), centre.y() + half.y() * std::sin(angle));
            }
            polyline(ring);
        }
        else
            polyline(p);
        if (text.empty())
            return;
        auto label = vtkSmartPointer<vtkTextActor>::New();
        setActorText(label, QString::fromStdString(text));
        label->GetTextProperty()->SetFontSize(int(std::lround(12 * m_pixelScale)));
        label->GetTextProperty()->SetColor(kColour[0], kColour[1], kColour[2]);
        label->GetPositionCoordinate()->SetCoordinateSystemToWorld();
        const Eigen::Vector2d at = m.kind == ViewMeasurement::Kind::Angle ? p[1] : p.back();
        label->GetPositionCoordinate()->SetValue(at.x() + 2.0, at.y() + 2.0, slice_depth::kMeasurements);
        m_renderer->AddViewProp(label);
        m_texts.push_back(label);
    };
    for (const ShownMeasurement& shown : m_measurements)
    {
        const ViewMeasurement& m = shown.measurement;
        const Eigen::Vector3d planeNormal = m.planeRight.cross(m.planeUp);
        if (m.pointsMm.empty() || std::abs(planeNormal.dot(normal)) < 0.99 ||
            std::abs((m.pointsMm.front() - originMm).dot(normal)) > 0.5 * thicknessMm + 1e-6)
            continue;
        draw(m, shown.text);
        ++m_shown;
    }
    draw(m_pending, {});
    auto data = vtkSmartPointer<vtkPolyData>::New();
    data->SetPoints(points);
    data->SetLines(lines);
    static_cast<vtkPolyDataMapper*>(m_lines->GetMapper())->SetInputData(data);
    m_lines->SetVisibility(lines->GetNumberOfCells() > 0);
}

} // namespace vsim::viz
