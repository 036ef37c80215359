#include "vsim/core/StoredText.h"
#include "vsim/core/ViewMeasurement.h"

#include "vsim/core/Error.h"
#include "vsim/core/Localized.h"

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
    throw Error(Pattern{"unknown measurement kind '%1' (ruler, angle or roi)", {name}});
}

std::string measurementText(const ViewMeasurement& m, bool forPeople)
{
    const LocalizedWhen localized{forPeople};
    const auto number = [](double value, const char* format)
    {
        char text[64];
        std::snprintf(text, sizeof text, format, value);
        return std::string(text);
    };
    switch (m.kind)
    {
    case ViewMeasurement::Kind::Ruler: return number(m.lengthMm, "%.1f") + " mm";
    case ViewMeasurement::Kind::Angle: return number(m.angleDegrees, "%.1f") + " deg";
    case ViewMeasurement::Kind::Roi:
    {
        // Stored in a measurement's name in English (StoredText.h), or for people in their language.
        const std::vector<std::string> values{number(m.meanHu, "%.0f"), number(m.sdHu, "%.0f"), number(m.areaMm2, "%.0f")};
        return forPeople ? withArguments(localized("vsim::ViewMeasurement", "mean %1 HU, SD %2 HU, area %3 mm2"), values)
                         : storedText(Pattern{"mean %1 HU, SD %2 HU, area %3 mm2", values});
    }
    }
    return {};
}

std::string measurementDefinition(ViewMeasurement::Kind kind, bool forPeople)
{
    const LocalizedWhen localized{forPeople};
    switch (kind)
    {
    case ViewMeasurement::Kind::Ruler:
        return localized("vsim::ViewMeasurement", "straight distance between the two points in the patient frame (mm)");
    case ViewMeasurement::Kind::Angle:
        return localized("vsim::ViewMeasurement", "angle at the middle point between the two arms (degrees)");
    case ViewMeasurement::Kind::Roi:
        return localized("vsim::ViewMeasurement",
                         "CT values (HU) of the voxels nearest the in-plane samples inside the "
                         "ellipse, one sample per finest voxel spacing squared: mean and sample "
                         "standard deviation; area of the ellipse, pi a b (mm2)");
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
