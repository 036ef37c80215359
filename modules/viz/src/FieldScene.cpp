#include "FieldScene.h"
#include "TextFonts.h"
#include "TitleLines.h"

#include "vsim/core/Error.h"
#include "vsim/interop/VtkMesh.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCaptionActor2D.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkLookupTable.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkProperty2D.h>
#include <vtkScalarBarActor.h>
#include <vtkScalarsToColors.h>
#include <vtkSphereSource.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkTubeFilter.h>
#include <vtkVariant.h>

#include <algorithm>

namespace vsim::viz::detail {

vtkSmartPointer<vtkLookupTable> fieldLookupTable(double low, double high)
{
    auto table = vtkSmartPointer<vtkLookupTable>::New();
    table->SetHueRange(0.667, 0.0);
    table->SetTableRange(low, high);
    table->SetNanColor(0.6, 0.6, 0.6, 1.0); // grey where a field is not defined (VTK's default is a dark red)
    table->Build();
    return table;
}

vtkSmartPointer<vtkPolyDataMapper> fieldMapper(vtkPolyData* polyData, double low, double high)
{
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputData(polyData);
    mapper->SetLookupTable(fieldLookupTable(low, high));
    mapper->SetScalarRange(low, high);
    mapper->ScalarVisibilityOn();
    return mapper;
}

vtkSmartPointer<vtkPolyData> fieldSurface(const TriangleMesh& surface, const std::string& field)
{
    const auto values = surface.pointFields.find(field);
    if (values == surface.pointFields.end())
        throw Error(Pattern{"the surface has no field '%1' to colour by", {field}});
    vtkSmartPointer<vtkPolyData> polyData = interop::toVtk(surface);
    auto scalars = vtkSmartPointer<vtkDoubleArray>::New();
    scalars->SetName(field.c_str());
    for (double v : values->second)
        scalars->InsertNextValue(v);
    polyData->GetPointData()->SetScalars(scalars);
    return polyData;
}

vtkSmartPointer<vtkPolyData> fieldTubes(const std::vector<std::vector<Eigen::Vector3d>>& lines,
                                        const std::vector<double>& values,
                                        const std::vector<std::array<double, 2>>& radiiMm)
{
    if (values.size() != lines.size() || (!radiiMm.empty() && radiiMm.size() != lines.size()))
        throw Error("field lines need one value (and radius pair) per line");
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto cells = vtkSmartPointer<vtkCellArray>::New();
    auto scalars = vtkSmartPointer<vtkDoubleArray>::New();
    scalars->SetName("value");
    auto radius = vtkSmartPointer<vtkDoubleArray>::New();
    radius->SetName("radius");
    for (std::size_t l = 0; l < lines.size(); ++l)
    {
        cells->InsertNextCell(vtkIdType(lines[l].size()));
        for (std::size_t i = 0; i < lines[l].size(); ++i)
        {
            const Eigen::Vector3d& point = lines[l][i];
            cells->InsertCellPoint(points->InsertNextPoint(point.x(), point.y(), point.z()));
            if (!radiiMm.empty()) // linear along the line, as the conical segment
            {
                const double t = lines[l].size() > 1 ? double(i) / double(lines[l].size() - 1) : 0.0;
                radius->InsertNextValue(radiiMm[l][0] + t * (radiiMm[l][1] - radiiMm[l][0]));
            }
        }
        scalars->InsertNextValue(values[l]);
    }
    auto polyData = vtkSmartPointer<vtkPolyData>::New();
    polyData->SetPoints(points);
    polyData->SetLines(cells);
    polyData->GetCellData()->SetScalars(scalars);
    if (radiiMm.empty())
        return polyData;
    // The vessels as tubes of their radius: clearer than wide lines, which software GL draws poorly.
    polyData->GetPointData()->SetScalars(radius);
    auto tubes = vtkSmartPointer<vtkTubeFilter>::New();
    tubes->SetInputData(polyData);
    tubes->SetVaryRadiusToVaryRadiusByAbsoluteScalar();
    tubes->SetNumberOfSides(12);
    tubes->CappingOn();
    tubes->Update();
    return tubes->GetOutput();
}

std::vector<vtkSmartPointer<vtkProp>> calloutProps(const std::vector<Callout>& callouts, int fontSize, int widthPixels,
                                                   int heightPixels)
{
    std::vector<vtkSmartPointer<vtkProp>> props;
    for (std::size_t m = 0; m < callouts.size(); ++m)
    {
        // A caption left of the surface at the point's height (display offset from the point), its line to it.
        auto caption = vtkSmartPointer<vtkCaptionActor2D>::New();
        const Eigen::Vector3d& p = callouts[m].pointMm;
        caption->SetAttachmentPoint(p.x(), p.y(), p.z());
        caption->SetCaption(callouts[m].text.c_str());
        caption->BorderOff();
        caption->LeaderOn();
        caption->ThreeDimensionalLeaderOff();
        caption->GetProperty()->SetColor(0.0, 0.0, 0.0);
        caption->GetProperty()->SetLineWidth(2.0f);
        vtkTextProperty* text = caption->GetCaptionTextProperty();
        text->SetColor(0.0, 0.0, 0.0);
        text->SetFontSize(fontSize);
        fitFontToText(text, QString::fromStdString(callouts[m].text));
        text->ShadowOff();
        text->ItalicOff();
        text->BoldOn();
        caption->GetTextActor()->SetTextScaleModeToNone();
        caption->SetPosition(-0.38 * widthPixels, -0.02 * heightPixels - 0.03 * double(m) * heightPixels);
        caption->SetWidth(0.3);
        caption->SetHeight(0.06);
        props.push_back(caption);
        // A dark ball on the point, seen where the point faces the viewer (mm: 2.5).
        auto ball = vtkSmartPointer<vtkSphereSource>::New();
        ball->SetCenter(p.x(), p.y(), p.z());
        ball->SetRadius(2.5);
        ball->SetThetaResolution(16);
        ball->SetPhiResolution(16);
        auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
        mapper->SetInputConnection(ball->GetOutputPort());
        auto actor = vtkSmartPointer<vtkActor>::New();
        actor->SetMapper(mapper);
        actor->GetProperty()->SetColor(0.1, 0.1, 0.1);
        props.push_back(actor);
    }
    return props;
}

vtkSmartPointer<vtkScalarBarActor> newLegend()
{
    auto legend = vtkSmartPointer<vtkScalarBarActor>::New();
    legend->SetNumberOfLabels(5);
    legend->SetWidth(0.12);
    legend->SetHeight(0.6);
    return legend;
}

void titleLegend(vtkScalarBarActor* legend, const QString& title, int fontSize, double roomPixels, int dpi)
{
    constexpr int kLongestLine = 14; // characters; "von Mises (kPa)" stays on one line at 15 with its unit short
    constexpr double kCharacterWidth = 0.6; // of the font size: a wide estimate for Arial's mixed text
    QString lines = title;
    const int unit = title.indexOf(" (");
    if (title.size() > kLongestLine + 1 && unit > 0)
        lines = title.left(unit) + "\n" + title.mid(unit + 1);
    int longest = 0;
    for (const QString& line : lines.split('\n'))
        longest = std::max(longest, int(line.size()));
    if (roomPixels > 0.0 && longest > 0)
        fontSize = std::clamp(int(roomPixels / (kCharacterWidth * longest)), (3 * fontSize + 3) / 4, fontSize);
    fitFontToText(legend->GetTitleTextProperty(), title);
    for (vtkTextProperty* text :
         {legend->GetTitleTextProperty(), legend->GetLabelTextProperty(), legend->GetAnnotationTextProperty()})
    {
        text->SetFontSize(fontSize);
        text->ItalicOff();
    }
    // A line still wider than the room at that size breaks again where its script allows (TitleLines.h): VTK
    // centres the title over the bar and clips it at the view's edge.
    if (roomPixels > 0.0)
        lines = titleLines(lines, legend->GetTitleTextProperty(), roomPixels, dpi);
    legend->SetTitle(lines.toUtf8().constData());
    legend->UnconstrainedFontSizeOn();
}

void labelLegend(vtkScalarBarActor* legend, const std::function<std::string(double)>& text, int count)
{
    vtkScalarsToColors* table = legend->GetLookupTable();
    if (!table || count < 2)
        return;
    const double* range = table->GetRange();
    const double low = range[0], high = range[1];
    table->ResetAnnotations();
    for (int n = 0; n < count; ++n)
    {
        const double value = n + 1 == count ? high : low + (high - low) * n / (count - 1);
        table->SetAnnotation(vtkVariant(value), text(value));
    }
    legend->DrawTickLabelsOff();
    legend->DrawAnnotationsOn();
}

void lookFromFront(vtkCamera* camera, const Eigen::Vector3d& centre, double heightMm)
{
    camera->ParallelProjectionOn();
    camera->SetFocalPoint(centre.data());
    const Eigen::Vector3d position = centre - Eigen::Vector3d(0.0, 1000.0, 0.0); // anterior is -y in LPS
    camera->SetPosition(position.data());
    camera->SetViewUp(0.0, 0.0, 1.0);
    camera->SetParallelScale(0.5 * std::max(heightMm, 1.0));
}

} // namespace vsim::viz::detail
