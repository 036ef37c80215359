#pragma once

// A measurement drawn on a view, as reading workstations keep them: a ruler (distance between two points), an
// angle (at a vertex between two arms) or an elliptical ROI (CT statistics inside an ellipse in the view's plane).
// Points are in the patient frame (LPS, mm); the plane is the view's when it was drawn. The figures are filled by
// measure() (imaging/ViewMeasurements.h) and carry their definition in measurementText().

#include <Eigen/Core>

#include <string>
#include <vector>

namespace vsim {

struct ViewMeasurement
{
    enum class Kind
    {
        Ruler, ///< two points: the straight distance between them (mm)
        Angle, ///< three points, the vertex second: the angle between the arms (degrees, 0-180)
        Roi,   ///< two opposite corners of the ellipse's box in the plane: HU mean, SD and area
    };
    Kind kind = Kind::Ruler;
    std::vector<Eigen::Vector3d> pointsMm;
    Eigen::Vector3d planeRight = Eigen::Vector3d::UnitX(); ///< unit, in the plane (the view's right when drawn)
    Eigen::Vector3d planeUp = Eigen::Vector3d::UnitY();    ///< unit, in the plane (the view's up when drawn)

    // Figures (measure()).
    double lengthMm = 0.0;     ///< ruler
    double angleDegrees = 0.0; ///< angle
    double meanHu = 0.0;       ///< ROI: mean CT value of the voxels sampled inside the ellipse
    double sdHu = 0.0;         ///< ROI: their sample standard deviation
    double areaMm2 = 0.0;      ///< ROI: the ellipse's area, pi a b
    long long samples = 0;     ///< ROI: in-plane samples taken (one per finest voxel spacing squared)
};

/// The number of points a kind takes.
int pointCount(ViewMeasurement::Kind kind);
/// "ruler", "angle", "roi".
std::string kindName(ViewMeasurement::Kind kind);
/// The kind for its name; throws vsim::Error for another.
ViewMeasurement::Kind measurementKindFromName(const std::string& name);
/// The measurement's figures in words with their units, e.g. "45.2 mm", "32.5 deg", "mean 245 HU, SD 12 HU, area
/// 154 mm2 (ellipse)".
std::string measurementText(const ViewMeasurement& measurement, bool forPeople = false);
/// What the figures mean (for tooltips and the report).
std::string measurementDefinition(ViewMeasurement::Kind kind, bool forPeople = false);

/// The ROI ellipse: centre, semi-axes (mm) along planeRight and planeUp.
struct RoiEllipse
{
    Eigen::Vector3d centreMm;
    double semiAxisRightMm = 0.0, semiAxisUpMm = 0.0;
};
RoiEllipse roiEllipse(const ViewMeasurement& roi);

} // namespace vsim
