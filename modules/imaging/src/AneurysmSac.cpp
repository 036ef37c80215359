#include "vsim/imaging/AneurysmSac.h"

#include "AorticSections.h"
#include "SacLandmarks.h"

#include "vsim/core/Error.h"
#include "vsim/core/Localized.h"
#include "vsim/core/StoredText.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace vsim::imaging {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;
using namespace detail;

constexpr double kMaxEscapedShare = 0.2; ///< rays without an edge within kMaxRadiusMm, over all sections: no contour
constexpr double kNeckSearchMm = 80.0;
constexpr std::pair<double, double> kNeckBelowOriginMm{3.0, 8.0}; ///< where the neck diameter is read (mm below the origin)
constexpr double kSacNeckFactor = 1.5, kSacFallbackMm = 30.0;

} // namespace

std::map<std::string, std::string> aneurysmSacDefinitions(bool forPeople)
{
    const LocalizedWhen localized{forPeople};
    return {
        {"max_outer_diameter_mm",
         localized("vsim::imaging::AneurysmSac",
                   "largest outer-wall to outer-wall caliper perpendicular to the centerline of the outer "
                   "contour, thrombus and wall included (SVS 2018)")},
        {"max_outer_diameter_z_mm",
         localized("vsim::imaging::AneurysmSac", "patient position (LPS) of the centre of that cross-section")},
        {"lumen_diameter_at_max_mm",
         localized("vsim::imaging::AneurysmSac",
                   "equivalent diameter of the contrast lumen's perpendicular cross-section there")},
        {"neck_diameter_mm",
         localized("vsim::imaging::AneurysmSac",
                   "outer diameter perpendicular to the centerline at the origin of the lowest renal artery "
                   "(the median 3 to 8 mm below it, clear of the branch; without the renal arteries in the "
                   "label: the narrowest within 80 mm above the widest section)")},
        {"neck_length_mm",
         localized("vsim::imaging::AneurysmSac",
                   "centerline length from the lowest renal artery's origin to the start of the sac")},
        {"neck_angulation_deg",
         localized("vsim::imaging::AneurysmSac",
                   "angle between the neck axis (lowest renal artery to the sac's start) and the sac axis "
                   "(the sac's start to its end)")},
        {"lowest_renal_z_mm",
         localized("vsim::imaging::AneurysmSac", "patient position (LPS z) of the lowest renal artery's origin")},
        {"left_common_iliac_diameter_mm",
         localized("vsim::imaging::AneurysmSac", "outer diameter of the left common iliac artery perpendicular to its "
                                                 "centerline: the median 10 to 40 mm below the crotch")},
        {"right_common_iliac_diameter_mm",
         localized("vsim::imaging::AneurysmSac", "outer diameter of the right common iliac artery perpendicular to its "
                                                 "centerline: the median 10 to 40 mm below the crotch")},
        {"sac_threshold_diameter_mm",
         localized("vsim::imaging::AneurysmSac", "1.5 x the neck diameter (30 mm without a neck)")},
        {"wall_thickness_mm", localized("vsim::imaging::AneurysmSac",
                                        "assumed, not measured: the wall is that shell inside the outer contour")},
        {"sac_volume_ml",
         localized("vsim::imaging::AneurysmSac",
                   "volume inside the outer contour between the perpendicular planes at the sac's ends")},
        {"sac_length_mm", localized("vsim::imaging::AneurysmSac",
                                    "centerline length of the sac (outer diameter over the threshold, contiguous)")},
        {"max_thrombus_thickness_mm",
         localized("vsim::imaging::AneurysmSac",
                   "largest distance from the lumen to the wall's inner surface along the rays of an "
                   "axial section, within the sac")},
    };
}

AneurysmSac measureAneurysmSac(const CtVolume& ct, const LabelVolume& lumen, double wallThicknessMm,
                               const Progress& progress)
{
    if (!ct.geometry().isClose(lumen.geometry(), 1e-6))
        throw Error("the lumen label is not on the CT's grid");
    if (!(wallThicknessMm >= 0.0 && wallThicknessMm <= 5.0))
        throw Error("the wall thickness must be 0..5 mm", {{"value", std::to_string(wallThicknessMm)}});
    const VolumeGeometry& g = ct.geometry();
    std::vector<Section> sections = trackAorta(lumen);
    progress.report(0.1, localized("vsim::Progress", "aortic lumen followed"));

    AneurysmSac sac;
    sac.labels = LabelVolume(g);
    for (std::size_t v = 0; v < g.voxelCount(); ++v)
        sac.labels.data()[v] = lumen.data()[v] ? 1 : 0;
    const int nx = g.dims[0];
    for (std::size_t s = 0; s < sections.size(); ++s)
    {
        castRays(ct, lumen, sections[s]);
        progress.report(0.1 + 0.4 * double(s + 1) / double(sections.size()), localized("vsim::Progress", "outer contour"));
    }
    // The outer wall is the aorta's edge against fat or a denser neighbour; where most rays meet neither within
    // 60 mm (no fat around the aorta: an analytic phantom, a cachectic patient) there is no contour to measure.
    std::size_t escaped = 0;
    for (const Section& section : sections)
        escaped += std::size_t(section.escapedRays);
    if (double(escaped) > kMaxEscapedShare * double(sections.size() * kRays))
        throw Error("the aorta's outer wall could not be traced: in " +
                    std::to_string(int(std::lround(100.0 * double(escaped) / double(sections.size() * kRays)))) +
                    " % of the directions no edge against fat or a denser neighbour lies within 60 mm of the lumen "
                    "(is there fat around the aorta in this image?); the sac is not measured");
    smoothAcrossSections(sections);
    for (std::size_t s = 0; s < sections.size(); ++s)
    {
        Section& section = sections[s];
        // Fill the contour: outer = within the contour; wall = its outer wallThickness; thrombus = the rest.
        const int reach = int(std::ceil(kMaxRadiusMm / g.spacing.head<2>().minCoeff()));
        Vector2d sum = Vector2d::Zero();
        std::size_t count = 0;
        for (int j = std::max(0, int(section.lumenCentre.y()) - reach); j <= std::min(g.dims[1] - 1, int(section.lumenCentre.y()) + reach); ++j)
            for (int i = std::max(0, int(section.lumenCentre.x()) - reach); i <= std::min(nx - 1, int(section.lumenCentre.x()) + reach); ++i)
            {
                const Vector2d offset = (Vector2d(i, j) - section.lumenCentre).cwiseProduct(g.spacing.head<2>());
                const double r = contourRadius(section.outer, offset), d = offset.norm();
                if (d > r)
                    continue;
                sum += Vector2d(i, j), ++count;
                if (lumen.at(i, j, section.k))
                    continue;
                sac.labels.at(i, j, section.k) = r - d < wallThicknessMm ? 5 : 4;
            }
        const Vector2d centre = sum / double(std::max<std::size_t>(count, 1));
        section.outerCentreMm = g.indexToPatient(Vector3d(centre.x(), centre.y(), section.k));
        progress.report(0.5 + 0.1 * double(s + 1) / double(sections.size()), localized("vsim::Progress", "thrombus and wall"));
    }

    // The outer contour's centerline, smoothed over +-5 mm, and the perpendicular sections.
    const int smoothing = std::max(1, int(std::lround(5.0 / g.spacing.z())));
    std::vector<Vector3d> centreline(sections.size());
    for (std::size_t s = 0; s < sections.size(); ++s)
    {
        Vector3d sum = Vector3d::Zero();
        int count = 0;
        for (int d = -smoothing; d <= smoothing; ++d)
            if (long(s) + d >= 0 && long(s) + d < long(sections.size()))
                sum += sections[std::size_t(long(s) + d)].outerCentreMm, ++count;
        centreline[s] = sum / count;
    }
    for (std::size_t s = 0; s < sections.size(); ++s)
    {
        const std::size_t a = s >= 3 ? s - 3 : 0, b = std::min(sections.size() - 1, s + 3);
        const Vector3d tangent = (centreline[b] - centreline[a]).normalized();
        std::tie(sections[s].diameterMm, sections[s].areaMm2) =
            perpendicularSection(sections, g, &Section::outer, centreline[s], tangent);
        sections[s].lumenAreaMm2 = perpendicularSection(sections, g, &Section::lumenEdge, centreline[s], tangent).second;
        sections[s].arcMm = s == 0 ? 0.0 : sections[s - 1].arcMm + (centreline[s] - centreline[s - 1]).norm();
        progress.report(0.6 + 0.35 * double(s + 1) / double(sections.size()), localized("vsim::Progress", "perpendicular diameters"));
    }

    // The widest section, the neck above it, the sac around it.
    std::size_t peak = 0;
    for (std::size_t s = 0; s < sections.size(); ++s)
        if (sections[s].diameterMm > sections[peak].diameterMm)
            peak = s;
    // The neck: the outer diameter at the lowest renal artery's origin; without the renal arteries in the label,
    // the narrowest outer diameter within 80 mm above the widest section.
    const std::optional<std::size_t> renal = lowestRenalSection(sections, g, peak);
    double neck = 0.0;
    if (renal)
    {
        // At the origin itself the contour bulges along the renal artery: the median of the sections 3 to 8 mm
        // below it stands for the aorta there.
        std::vector<double> below;
        for (std::size_t s = *renal; s < sections.size() && sections[s].arcMm - sections[*renal].arcMm <= kNeckBelowOriginMm.second; ++s)
            if (sections[s].arcMm - sections[*renal].arcMm >= kNeckBelowOriginMm.first)
                below.push_back(sections[s].diameterMm);
        if (below.empty())
            below.push_back(sections[*renal].diameterMm);
        std::nth_element(below.begin(), below.begin() + std::ptrdiff_t(below.size() / 2), below.end());
        neck = below[below.size() / 2];
    }
    else
    {
        for (std::size_t s = peak; s-- > 0 && sections[peak].arcMm - sections[s].arcMm <= kNeckSearchMm;)
            neck = neck == 0.0 ? sections[s].diameterMm : std::min(neck, sections[s].diameterMm);
        sac.warnings.push_back(storedText("the lowest renal artery was not found in the lumen label: the neck is the "
                                          "narrowest outer diameter within 80 mm above the widest section"));
    }
    const double threshold = neck > 0.0 ? kSacNeckFactor * neck : kSacFallbackMm;
    std::size_t top = peak, bottom = peak;
    while (top > 0 && sections[top - 1].diameterMm > threshold)
        --top;
    while (bottom + 1 < sections.size() && sections[bottom + 1].diameterMm > threshold)
        ++bottom;
    double volume = 0.0, thrombus = 0.0;
    for (std::size_t s = top; s <= bottom; ++s)
    {
        const double length = s + 1 < sections.size() ? sections[s + 1].arcMm - sections[s].arcMm
                                                       : sections[s].arcMm - sections[s - 1].arcMm;
        volume += sections[s].areaMm2 * length;
        for (int ray = 0; ray < kRays; ++ray)
            thrombus = std::max(thrombus, sections[s].outer[std::size_t(ray)] - wallThicknessMm -
                                              sections[s].lumenEdge[std::size_t(ray)]);
    }
    const bool isSac = sections[peak].diameterMm > threshold && bottom > top;

    auto& f = sac.figures;
    f["max_outer_diameter_mm"] = sections[peak].diameterMm;
    sac.maxDiameterCentreMm = centreline[peak];
    f["max_outer_diameter_x_mm"] = centreline[peak].x();
    f["max_outer_diameter_y_mm"] = centreline[peak].y();
    f["max_outer_diameter_z_mm"] = centreline[peak].z();
    f["lumen_diameter_at_max_mm"] = 2.0 * std::sqrt(sections[peak].lumenAreaMm2 / std::numbers::pi);
    f["neck_diameter_mm"] = neck;
    f["sac_threshold_diameter_mm"] = threshold;
    f["wall_thickness_mm"] = wallThicknessMm;
    if (isSac)
    {
        f["sac_volume_ml"] = volume / 1000.0;
        f["sac_length_mm"] = sections[bottom].arcMm - sections[top].arcMm;
        f["sac_top_z_mm"] = centreline[top].z();
        f["sac_bottom_z_mm"] = centreline[bottom].z();
        f["max_thrombus_thickness_mm"] = std::max(0.0, thrombus);
        if (renal && *renal < top)
        {
            f["neck_length_mm"] = sections[top].arcMm - sections[*renal].arcMm;
            const Vector3d neckAxis = centreline[top] - centreline[*renal], sacAxis = centreline[bottom] - centreline[top];
            f["neck_angulation_deg"] =
                std::acos(std::clamp(neckAxis.normalized().dot(sacAxis.normalized()), -1.0, 1.0)) * 180.0 / std::numbers::pi;
        }
    }
    else
        sac.warnings.push_back(storedText("no sac: the widest outer diameter does not exceed 1.5 x the neck's"));
    if (renal)
        f["lowest_renal_z_mm"] = centreline[*renal].z();
    for (const auto& [key, value] : commonIliacDiameters(ct, lumen, sections))
        f[key] = value;
    const std::map<std::string, std::string> definitions = aneurysmSacDefinitions();
    for (const auto& [key, value] : f)
        if (const auto definition = definitions.find(key); definition != definitions.end())
            sac.definitions[key] = definition->second;
    progress.report(1.0, localized("vsim::Progress", "sac measured"));
    return sac;
}

} // namespace vsim::imaging
