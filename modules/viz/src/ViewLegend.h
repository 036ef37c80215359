#pragma once

// The 3D view's colour legends (VolumeView3D): the coloured surface's on the left, the points' and lines' on the
// right, their numbers in the reader's decimal mark and their titles readable (FieldScene.h's legend pieces).

#include <vtkSmartPointer.h>

#include <QString>

class vtkRenderer;
class vtkScalarBarActor;
class vtkScalarsToColors;

namespace vsim::viz::detail {

constexpr double kSurfaceLegendX = 0.02, kPointsLegendX = 0.82; // view fractions: the surface's left, the rest right

/// Shows `legend` (made and added to `renderer` at `x` across the view the first time) for `table`, titled `title`,
/// its text 12 pixels high at `pixelScale` device pixels a pixel.
void showLegendIn(vtkRenderer* renderer, vtkSmartPointer<vtkScalarBarActor>& legend, double x,
                  vtkScalarsToColors* table, const QString& title, double pixelScale);

} // namespace vsim::viz::detail
