#include "VolumeProperties.h"

#include <vtkColorTransferFunction.h>
#include <vtkPiecewiseFunction.h>
#include <vtkVolumeProperty.h>

namespace vsim::viz::detail {

vtkSmartPointer<vtkVolumeProperty> ctaRenderedProperty()
{
    auto opacity = vtkSmartPointer<vtkPiecewiseFunction>::New();
    opacity->AddPoint(-1024, 0.0);
    opacity->AddPoint(150, 0.0);
    opacity->AddPoint(250, 0.25);
    opacity->AddPoint(450, 0.7);
    opacity->AddPoint(3000, 0.9);
    auto colour = vtkSmartPointer<vtkColorTransferFunction>::New();
    colour->AddRGBPoint(-1024, 0.0, 0.0, 0.0);
    colour->AddRGBPoint(200, 0.75, 0.15, 0.1);
    colour->AddRGBPoint(450, 0.95, 0.4, 0.3);
    colour->AddRGBPoint(700, 0.95, 0.92, 0.85);
    colour->AddRGBPoint(3000, 1.0, 1.0, 1.0);
    auto property = vtkSmartPointer<vtkVolumeProperty>::New();
    property->SetScalarOpacity(opacity);
    property->SetColor(colour);
    property->SetInterpolationTypeToLinear();
    property->ShadeOn();
    property->SetAmbient(0.4);
    return property;
}

vtkSmartPointer<vtkVolumeProperty> ctaMaximumIntensityProperty()
{
    auto opacity = vtkSmartPointer<vtkPiecewiseFunction>::New();
    opacity->AddPoint(-1024, 0.0);
    opacity->AddPoint(200, 0.0);
    opacity->AddPoint(700, 0.85);
    opacity->AddPoint(3000, 0.85);
    auto grey = vtkSmartPointer<vtkColorTransferFunction>::New();
    grey->AddRGBPoint(200, 0.0, 0.0, 0.0);
    grey->AddRGBPoint(700, 1.0, 1.0, 1.0);
    auto property = vtkSmartPointer<vtkVolumeProperty>::New();
    property->SetScalarOpacity(opacity);
    property->SetColor(grey);
    property->SetInterpolationTypeToLinear();
    property->ShadeOff();
    return property;
}

vtkSmartPointer<vtkVolumeProperty> smokeProperty(double low, double high)
{
    const double top = high > low ? high : low + 1.0;
    auto opacity = vtkSmartPointer<vtkPiecewiseFunction>::New();
    opacity->AddPoint(low, 0.0);
    opacity->AddPoint(low + 0.05 * (top - low), 0.02);
    opacity->AddPoint(top, 0.6);
    auto colour = vtkSmartPointer<vtkColorTransferFunction>::New();
    colour->AddRGBPoint(low, 0.45, 0.45, 0.47);
    colour->AddRGBPoint(top, 0.95, 0.95, 0.92);
    auto property = vtkSmartPointer<vtkVolumeProperty>::New();
    property->SetScalarOpacity(opacity);
    property->SetColor(colour);
    property->SetInterpolationTypeToLinear();
    property->ShadeOff();
    return property;
}

} // namespace vsim::viz::detail
