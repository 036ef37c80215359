#include "vsim/viz/Snapshot.h"

#include "FieldScene.h"
#include "vsim/core/Error.h"
#include "vsim/core/Localized.h"

#include <vtkActor.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace vsim::viz {
namespace {

/// Renders `polyData` (its scalars in point or cell data) offscreen from the front, framed with a margin.
QImage render(vtkPolyData* polyData, bool cellScalars, const SnapshotColouring& colouring, QSize pixels,
              const std::vector<Callout>& callouts = {})
{
    if (!canRenderSnapshots())
        throw Error("3D snapshots need a display (set DISPLAY, or run under xvfb-run)");
    if (pixels.width() < 16 || pixels.height() < 16)
        throw Error("a snapshot needs at least 16 x 16 pixels");
    vtkSmartPointer<vtkPolyDataMapper> mapper = detail::fieldMapper(polyData, colouring.low, colouring.high);
    if (cellScalars)
        mapper->SetScalarModeToUseCellData();
    else
        mapper->SetScalarModeToUsePointData();
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    auto renderer = vtkSmartPointer<vtkRenderer>::New();
    renderer->SetBackground(1.0, 1.0, 1.0);
    renderer->AddActor(actor);
    vtkSmartPointer<vtkScalarBarActor> legend = detail::newLegend();
    legend->SetLookupTable(mapper->GetLookupTable());
    // The report's decimal mark (the thread's language: core Localized.h), not the window's.
    detail::labelLegend(legend, [](double value) {
        char printed[32];
        std::snprintf(printed, sizeof printed, "%.3g", value);
        return localizedNumber(printed);
    });
    const int fontSize = std::max(12, pixels.height() / 40);
    detail::titleLegend(legend, QString::fromStdString(colouring.legendTitle), fontSize);
    for (vtkTextProperty* text :
         {legend->GetTitleTextProperty(), legend->GetLabelTextProperty(), legend->GetAnnotationTextProperty()})
    {
        text->SetColor(0.0, 0.0, 0.0); // on the report's white
        text->ShadowOff();
    }
    legend->SetPosition(0.86, 0.15);
    renderer->AddViewProp(legend);
    for (const vtkSmartPointer<vtkProp>& prop : detail::calloutProps(callouts, fontSize, pixels.width(), pixels.height()))
        renderer->AddViewProp(prop);

    double bounds[6];
    polyData->GetBounds(bounds);
    const Eigen::Vector3d centre(0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
                                 0.5 * (bounds[4] + bounds[5]));
    const double aspect = double(pixels.width()) / double(pixels.height());
    // Left-right spans the width (less the legend), superior-inferior the height.
    const double height = 1.1 * std::max(bounds[5] - bounds[4], (bounds[1] - bounds[0]) / (0.8 * aspect));
    // The picture's right is the patient's left (+x): shift the view so that the legend on the right stays clear.
    detail::lookFromFront(renderer->GetActiveCamera(), centre + Eigen::Vector3d(0.08 * height * aspect, 0, 0), height);
    renderer->ResetCameraClippingRange();

    auto window = vtkSmartPointer<vtkRenderWindow>::New();
    window->SetOffScreenRendering(1);
    window->SetMultiSamples(8);
    window->SetSize(pixels.width(), pixels.height());
    window->AddRenderer(renderer);
    window->Render();
    auto grab = vtkSmartPointer<vtkWindowToImageFilter>::New();
    grab->SetInput(window);
    grab->SetInputBufferTypeToRGB();
    grab->ReadFrontBufferOff();
    grab->Update();
    vtkImageData* image = grab->GetOutput();
    int dims[3];
    image->GetDimensions(dims);
    auto* rgb = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars());
    if (!rgb || dims[0] != pixels.width() || dims[1] != pixels.height())
        throw Error("the offscreen snapshot could not be read back");
    QImage picture(dims[0], dims[1], QImage::Format_RGB888);
    for (int y = 0; y < dims[1]; ++y) // VTK's rows run bottom-up
        std::memcpy(picture.scanLine(dims[1] - 1 - y), rgb->GetPointer(vtkIdType(3) * y * dims[0]), std::size_t(3 * dims[0]));
    window->Finalize();
    return picture;
}

} // namespace

bool canRenderSnapshots()
{
    const char* display = std::getenv("DISPLAY");
    return display && *display;
}

QImage snapshotSurface(const TriangleMesh& surface, const std::string& field, const SnapshotColouring& colouring,
                       QSize pixels, const std::vector<Callout>& callouts)
{
    vtkSmartPointer<vtkPolyData> polyData = detail::fieldSurface(surface, field);
    return render(polyData, false, colouring, pixels, callouts);
}

QImage snapshotTubes(const std::vector<std::vector<Eigen::Vector3d>>& lines, const std::vector<double>& values,
                     const std::vector<std::array<double, 2>>& radiiMm, const SnapshotColouring& colouring,
                     QSize pixels)
{
    vtkSmartPointer<vtkPolyData> polyData = detail::fieldTubes(lines, values, radiiMm);
    return render(polyData, true, colouring, pixels);
}

} // namespace vsim::viz
