#include "AnatomyMeasures.h"

#include "AnatomyBuilder.h"
#include "AnatomyPainter.h"

#include "vsim/core/Error.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vsim::dicom::detail {

namespace {

/// Volume (mm3) of the rendered outer solid (the union of the outer contour's frustums, sampled as the builder
/// samples them) between two planes (point, downstream normal), counted on a 0.5 mm grid: the sac's truth by
/// its definition, from the very solid the image shows.
double solidVolumeBetween(const AaaProfile& profile, const Eigen::Vector3d& topPoint, const Eigen::Vector3d& topNormal,
                          const Eigen::Vector3d& bottomPoint, const Eigen::Vector3d& bottomNormal)
{
    const SampledCurve curve = sampleCurve([&](double t) { return profile.outerCentre(profile.topZ + t * (profile.bottomZ - profile.topZ)); });
    std::vector<TubePiece> pieces;
    double widest = 0.0;
    for (std::size_t n = 1; n < curve.points.size(); ++n)
    {
        pieces.push_back({curve.points[n - 1], curve.points[n], profile.outerRadius(curve.points[n - 1].z()),
                          profile.outerRadius(curve.points[n].z()), 0.0, 0.0});
        widest = std::max(widest, pieces.back().ra);
    }
    const double zHigh = std::max(topPoint.z(), bottomPoint.z()) + widest, zLow = std::min(topPoint.z(), bottomPoint.z()) - widest;
    constexpr double kStep = 0.5;
    double volume = 0.0;
    for (double z = zLow; z <= zHigh; z += kStep)
    {
        std::vector<const TubePiece*> near;
        Eigen::Vector2d low(1e9, 1e9), high(-1e9, -1e9);
        for (const TubePiece& piece : pieces)
        {
            const double r = std::max(piece.ra, piece.rb);
            if (z < std::min(piece.a.z(), piece.b.z()) - r || z > std::max(piece.a.z(), piece.b.z()) + r)
                continue;
            near.push_back(&piece);
            const Eigen::Vector2d lowest = piece.a.head<2>().cwiseMin(piece.b.head<2>());
            const Eigen::Vector2d highest = piece.a.head<2>().cwiseMax(piece.b.head<2>());
            low = low.cwiseMin(Eigen::Vector2d(lowest.array() - r));
            high = high.cwiseMax(Eigen::Vector2d(highest.array() + r));
        }
        for (double y = low.y(); y <= high.y(); y += kStep)
            for (double x = low.x(); x <= high.x(); x += kStep)
            {
                const Eigen::Vector3d p(x, y, z);
                if ((p - topPoint).dot(topNormal) < 0.0 || (p - bottomPoint).dot(bottomNormal) > 0.0)
                    continue;
                for (const TubePiece* piece : near)
                {
                    double t = 0.0;
                    if (pieceDistance(*piece, p, t) < 0.0)
                    {
                        volume += kStep * kStep * kStep;
                        break;
                    }
                }
            }
    }
    return volume;
}

} // namespace

void measureAaa(const AaaProfile& profile, AnatomyPhantom& phantom)
{
    constexpr double kStepMm = 0.1;
    struct Sample
    {
        double z, arc, outerDiameter;
        Eigen::Vector3d centre;
    };
    std::vector<Sample> samples; // top to bottom along the outer contour's centerline
    for (double z = profile.topZ; z >= profile.bottomZ; z -= kStepMm)
    {
        const Eigen::Vector3d centre = profile.outerCentre(z);
        const double arc = samples.empty() ? 0.0 : samples.back().arc + (centre - samples.back().centre).norm();
        samples.push_back({z, arc, 2.0 * profile.outerRadius(z), centre});
    }
    const auto nearestZ = [&](double z) {
        return std::size_t(std::clamp(std::lround((profile.topZ - z) / kStepMm), 0L, long(samples.size()) - 1));
    };
    const std::size_t neck = nearestZ(profile.lowestRenalZ);
    std::size_t peak = neck;
    for (std::size_t i = neck; i < samples.size(); ++i)
        if (samples[i].outerDiameter > samples[peak].outerDiameter)
            peak = i;
    const double neckDiameter = samples[neck].outerDiameter;
    const double threshold = kSacNeckFactor * neckDiameter;
    if (samples[peak].outerDiameter <= threshold)
        throw Error("the AAA phantom's aneurysm is smaller than 1.5 times its neck; choose a larger --max-diameter");
    std::size_t top = peak, bottom = peak;
    while (top > neck && samples[top - 1].outerDiameter > threshold)
        --top;
    while (bottom + 1 < samples.size() && samples[bottom + 1].outerDiameter > threshold)
        ++bottom;
    const auto tangentAt = [&](std::size_t i) { // downstream direction of the centerline
        return Eigen::Vector3d(samples[std::min(i + 5, samples.size() - 1)].centre - samples[i >= 5 ? i - 5 : 0].centre)
            .normalized();
    };
    const double volume = solidVolumeBetween(profile, samples[top].centre, tangentAt(top), samples[bottom].centre,
                                             tangentAt(bottom));
    double thrombus = 0.0;
    for (const Sample& s : samples)
        thrombus = std::max(thrombus, profile.outerRadius(s.z) - profile.wallMm - profile.lumenRadius(s.z) +
                                          (profile.lumenCentre(s.z) - profile.outerCentre(s.z)).norm());
    const Eigen::Vector3d neckAxis = samples[top].centre - samples[neck].centre;
    const Eigen::Vector3d sacAxis = samples[bottom].centre - samples[top].centre;
    const double angulation = std::acos(std::clamp(neckAxis.normalized().dot(sacAxis.normalized()), -1.0, 1.0)) *
                              180.0 / std::numbers::pi;

    auto& m = phantom.measures;
    auto& d = phantom.definitions;
    m["max_outer_diameter_mm"] = samples[peak].outerDiameter;
    d["max_outer_diameter_mm"] = "largest outer-wall to outer-wall diameter perpendicular to the centerline of the "
                                 "aorta's outer contour, thrombus and wall included (SVS 2018)";
    m["max_outer_diameter_x_mm"] = samples[peak].centre.x();
    m["max_outer_diameter_y_mm"] = samples[peak].centre.y();
    m["max_outer_diameter_z_mm"] = samples[peak].centre.z();
    d["max_outer_diameter_z_mm"] = "patient position of the centre of that cross-section";
    m["lumen_diameter_at_max_mm"] = 2.0 * profile.lumenRadius(samples[peak].z);
    d["lumen_diameter_at_max_mm"] = "equivalent diameter of the contrast lumen's cross-section at the maximum";
    m["max_thrombus_thickness_mm"] = thrombus;
    d["max_thrombus_thickness_mm"] = "largest distance from the lumen to the inner surface of the wall in a "
                                     "cross-section";
    m["neck_diameter_mm"] = neckDiameter;
    d["neck_diameter_mm"] = "outer diameter perpendicular to the centerline at the origin of the lowest renal artery";
    m["neck_length_mm"] = samples[top].arc - samples[neck].arc;
    d["neck_length_mm"] = "centerline length from the lowest renal artery to the start of the sac";
    m["neck_angulation_deg"] = angulation;
    d["neck_angulation_deg"] = "angle between the neck axis (lowest renal artery to sac start) and the sac axis "
                               "(sac start to sac end)";
    m["sac_threshold_diameter_mm"] = threshold;
    d["sac_threshold_diameter_mm"] = "the sac is the contiguous infrarenal aorta whose outer diameter exceeds 1.5 "
                                     "times the neck diameter (30 mm when no neck is found)";
    const auto addPoint = [&](const std::string& key, const Eigen::Vector3d& p) {
        m[key + "_x_mm"] = p.x(), m[key + "_y_mm"] = p.y(), m[key + "_z_mm"] = p.z();
    };
    addPoint("sac_top", samples[top].centre);
    addPoint("sac_bottom", samples[bottom].centre);
    addPoint("sac_top_tangent", tangentAt(top));
    addPoint("sac_bottom_tangent", tangentAt(bottom));
    d["sac_top_z_mm"] = "centre of the sac's upper end (its cross-section perpendicular to the centerline); "
                        "sac_*_tangent: the centerline's downstream direction there (unit vector, not mm)";
    m["sac_length_mm"] = samples[bottom].arc - samples[top].arc;
    m["sac_volume_ml"] = volume / 1000.0;
    d["sac_volume_ml"] = "volume inside the outer contour (lumen, thrombus and wall) between the planes "
                         "perpendicular to the centerline at the sac's ends (the rendered solid, counted on a 0.5 mm grid)";
    m["wall_thickness_mm"] = profile.wallMm;
    for (const VesselSegment& segment : phantom.arteries.segments)
        if (segment.name.find("common iliac artery") != std::string::npos)
        {
            const std::string key = segment.name.substr(0, segment.name.find(' ')) + "_common_iliac_diameter_mm";
            m[key] = 2.0 * (segment.radii.front() + profile.iliacWallMm);
            d[key] = "outer diameter of the common iliac artery (constant over its first 55 mm)";
        }
}

} // namespace vsim::dicom::detail
