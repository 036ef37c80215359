#include "ViewLegend.h"

#include "FieldScene.h"

#include "vsim/viz/DecimalText.h"

#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkScalarsToColors.h>

#include <algorithm>
#include <cmath>

namespace vsim::viz::detail {

void showLegendIn(vtkRenderer* renderer, vtkSmartPointer<vtkScalarBarActor>& legend, double x,
                  vtkScalarsToColors* table, const QString& title, double pixelScale)
{
    if (!legend)
    {
        legend = newLegend();
        legend->SetPosition(x, 0.1);
        // Its numbers are annotations (labelLegend), drawn on the side opposite the tick labels': inward, towards
        // the view's middle.
        if (x < 0.5)
            legend->SetTextPositionToPrecedeScalarBar();
        renderer->AddViewProp(legend);
    }
    legend->SetLookupTable(table);
    labelLegend(legend, [](double value) { return significantText(value, 3).toStdString(); });
    // The title is centred over the bar (the legend's middle, half its width right of x): its room is twice the
    // distance from there to the nearer edge.
    const double middle = x + 0.5 * legend->GetWidth();
    const int* size = renderer->GetSize(); // device pixels
    const double room = 2.0 * std::min(middle, 1.0 - middle) * double(size[0]);
    vtkRenderWindow* window = renderer->GetRenderWindow();
    titleLegend(legend, title, int(std::lround(12 * pixelScale)), room, window ? window->GetDPI() : 72);
    legend->SetVisibility(true);
}

} // namespace vsim::viz::detail
