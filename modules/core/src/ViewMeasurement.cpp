#include "vsim/core/ViewMeasurement.h"

#include "vsim/core/Error.h"

#include <cmath>
#include <cstdio>

namespace vsim {

int pointCount(ViewMeasurement::Kind kind)
{
    return kind == ViewMeasurement::Kind::Angle ? 3 : 2;
}

std::string kindName(ViewMeasurement::Kind kind)
{
    switch (kind)
    {
    case ViewMeasurement::Kind::Ruler: return "ruler";
    case ViewMeasurement::Kind::Angle: return "angle";
    case ViewMeasurement::Kind::Roi: return "roi";
    }
    return "ruler";
}

ViewMeasurement::Kind measurementKindFromName(const std::string& name)
{
    for (ViewMeasurement::Kind kind : {ViewMeasurement::Kind::Ruler, ViewMeasurement::Kind::Angle, ViewMeasurement::Kind::Roi})
        if (kindName(kind) == name)
            return kind;
    throw Error("unknown measurement kind '" + name + "' (ruler, angle or roi)");
}

std::string measurementText(const ViewMeasurement& m)
{
    char text[160];
    switch (m.kind)
    {
    case ViewMeasurement::Kind::Ruler: std::snprintf(text, sizeof text, "%.1f mm", m.lengthMm); break;
    case ViewMeasurement::Kind::Angle: std::snprintf(text, sizeof text, "%.1f deg", m.angleDegrees); break;
    case ViewMeasurement::Kind::Roi:
        std::snprintf(text, sizeof text, "mean %.0f HU, SD %.0f HU, area %.0f mm2", m.meanHu, m.sdHu, m.areaMm2);
        break;
    }
    return text;
}

std::string measurementDefinition(ViewMeasurement::Kind kind)
{
    switch (kind)
    {
    case ViewMeasurement::Kind::Ruler: return "straight distance between the two points in the patient frame (mm)";
    case ViewMeasurement::Kind::Angle: return "angle at the middle point between the two arms (degrees)";
    case ViewMeasurement::Kind::Roi:
        return "CT values (HU) of the voxels nearest the in-plane samples inside the ellipse, one sample per finest "
               "voxel spacing squared: mean and sample standard deviation; area of the ellipse, pi a b (mm2)";
    }
    return {};
}

RoiEllipse roiEllipse(const ViewMeasurement& roi)
{
    if (roi.pointsMm.size() != 2)
        throw Error("an ROI takes two corner points");
    const Eigen::Vector3d diagonal = roi.pointsMm[1] - roi.pointsMm[0];
    return {0.5 * (roi.pointsMm[0] + roi.pointsMm[1]), 0.5 * std::abs(diagonal.dot(roi.planeRight)),
            0.5 * std::abs(diagonal.dot(roi.planeUp))};
}

} // namespace vsim
