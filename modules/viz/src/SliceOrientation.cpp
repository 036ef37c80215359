#include "vsim/viz/SliceOrientation.h"

namespace vsim::viz {

ScreenAxes screenAxes(SliceOrientation orientation)
{
    switch (orientation)
    {
    case SliceOrientation::Axial: return {{1, 0, 0}, {0, -1, 0}};
    case SliceOrientation::Coronal: return {{1, 0, 0}, {0, 0, 1}};
    case SliceOrientation::Sagittal: return {{0, -1, 0}, {0, 0, 1}};
    }
    return {{1, 0, 0}, {0, 1, 0}};
}

Eigen::Vector3d planeColour(SliceOrientation orientation)
{
    switch (orientation)
    {
    case SliceOrientation::Axial: return {0.95, 0.35, 0.3};
    case SliceOrientation::Coronal: return {0.35, 0.85, 0.35};
    case SliceOrientation::Sagittal: return {0.95, 0.85, 0.25};
    }
    return {1.0, 1.0, 1.0};
}

} // namespace vsim::viz
