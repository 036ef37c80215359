#include "SacLandmarks.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vsim::imaging::detail {
namespace {

constexpr double kOstiumReachMm = 3.5;     ///< a renal origin: the lumen piece reaches this far beyond its radius
constexpr int kOstiumPixels = 3;           ///< ... with at least this many pixels
constexpr double kIliacSearchMm = 40.0;    ///< iliac pieces start within this of the aorta's last centre
constexpr double kIliacStepMm = 10.0;      ///< and move at most this much from slice to slice
constexpr double kMinIliacAreaMm2 = 20.0;
constexpr double kIliacLengthMm = 50.0;
constexpr double kIliacFromMm = 10.0, kIliacToMm = 40.0; ///< where the iliac diameter is measured, below the crotch

Vector2d mmOffset(const Vector2d& index, const Vector2d& from, const VolumeGeometry& g)
{
    return (index - from).cwiseProduct(g.spacing.head<2>());
}

/// The median of the perpendicular outer diameters between `fromMm` and `toMm` of centerline along `sections`
/// (superior first, contours traced); 0 when the sections do not reach `toMm`.
double medianOuterDiameter(std::vector<Section>& sections, const VolumeGeometry& g, double fromMm, double toMm)
{
    std::vector<Vector3d> centres(sections.size());
    for (std::size_t s = 0; s < sections.size(); ++s)
        centres[s] = g.indexToPatient(Vector3d(sections[s].lumenCentre.x(), sections[s].lumenCentre.y(), sections[s].k));
    std::vector<double> diameters;
    double arc = 0.0;
    for (std::size_t s = 0; s < sections.size(); ++s)
    {
        if (s > 0)
            arc += (centres[s] - centres[s - 1]).norm();
        if (arc < fromMm || arc > toMm)
            continue;
        const std::size_t a = s >= 3 ? s - 3 : 0, b = std::min(sections.size() - 1, s + 3);
        const Vector3d tangent = (centres[b] - centres[a]).normalized();
        const double diameter = perpendicularSection(sections, g, &Section::outer, centres[s], tangent).first;
        if (diameter > 0.0)
            diameters.push_back(diameter);
    }
    if (arc < toMm || diameters.empty())
        return 0.0;
    std::nth_element(diameters.begin(), diameters.begin() + std::ptrdiff_t(diameters.size() / 2), diameters.end());
    return diameters[diameters.size() / 2];
}

} // namespace

std::optional<std::size_t> lowestRenalSection(const std::vector<Section>& sections, const VolumeGeometry& g,
                                              std::size_t peak)
{
    const int nx = g.dims[0];
    // The patient's left-right axis in the slice's index plane (LPS x).
    const Vector2d lateral = Vector2d(g.direction(0, 0), g.direction(0, 1)).normalized();
    for (std::size_t s = peak + 1; s-- > 0;)
    {
        const Section& section = sections[s];
        const double radius =
            std::sqrt(double(section.lumenPixels.size()) * g.spacing.x() * g.spacing.y() / std::numbers::pi);
        int reaching = 0;
        for (std::uint32_t p : section.lumenPixels)
        {
            const Vector2d d = mmOffset(Vector2d(double(p % std::uint32_t(nx)), double(p / std::uint32_t(nx))),
                                        section.lumenCentre, g);
            reaching += d.norm() > radius + kOstiumReachMm && std::abs(d.normalized().dot(lateral)) > std::sqrt(0.5);
        }
        if (reaching >= kOstiumPixels)
            return s;
    }
    return std::nullopt;
}

std::map<std::string, double> commonIliacDiameters(const CtVolume& ct, const LabelVolume& lumen,
                                                   const std::vector<Section>& aorta)
{
    const VolumeGeometry& g = lumen.geometry();
    const int nx = g.dims[0];
    const double pixelArea = g.spacing.x() * g.spacing.y();
    std::map<std::string, double> diameters;
    if (aorta.empty())
        return diameters;
    // The crotch: going down the tracked sections (which follow one iliac past the bifurcation), the first slice
    // holding another piece near the tracked one and at least half its size: the other common iliac.
    std::vector<std::vector<std::uint32_t>> pieces;
    std::vector<std::size_t> near;
    int start = -1;
    for (const Section& section : aorta)
    {
        pieces = slicePieces(lumen, section.k);
        near.clear();
        for (std::size_t n = 0; n < pieces.size(); ++n)
        {
            const double area = double(pieces[n].size()) * pixelArea;
            if (area >= kMinIliacAreaMm2 && 2.0 * double(pieces[n].size()) >= double(section.lumenPixels.size()) &&
                mmOffset(centroidOf(pieces[n], nx), section.lumenCentre, g).norm() <= kIliacSearchMm)
                near.push_back(n);
        }
        if (near.size() >= 2)
        {
            start = section.k;
            break;
        }
    }
    if (start < 0)
        return diameters;
    const int down = g.direction(2, 2) >= 0.0 ? -1 : 1; // inferior: -z in LPS
    std::sort(near.begin(), near.end(), [&](std::size_t a, std::size_t b) { return pieces[a].size() > pieces[b].size(); });
    for (std::size_t side = 0; side < 2; ++side)
    {
        std::vector<Section> iliac{makeSection(start, pieces[near[side]], nx)};
        for (int k = start + down; k >= 0 && k < g.dims[2] && std::abs(k - start) * g.spacing.z() <= kIliacLengthMm;
             k += down)
        {
            const std::vector<std::vector<std::uint32_t>> below = slicePieces(lumen, k);
            const std::vector<std::uint32_t>* best = nullptr;
            double nearest = kIliacStepMm;
            for (const auto& piece : below)
            {
                const double d = mmOffset(centroidOf(piece, nx), iliac.back().lumenCentre, g).norm();
                if (double(piece.size()) * pixelArea >= kMinIliacAreaMm2 && d < nearest)
                    nearest = d, best = &piece;
            }
            if (!best)
                break;
            iliac.push_back(makeSection(k, *best, nx));
        }
        for (Section& section : iliac)
            castRays(ct, lumen, section);
        smoothAcrossSections(iliac);
        const double diameter = medianOuterDiameter(iliac, g, kIliacFromMm, kIliacToMm);
        if (diameter <= 0.0)
            continue;
        // Patient left (+x in LPS) of the point between the two iliacs at the crotch.
        const Vector2d between = 0.5 * (centroidOf(pieces[near[0]], nx) + centroidOf(pieces[near[1]], nx));
        const Vector3d own = g.indexToPatient(Vector3d(iliac.front().lumenCentre.x(), iliac.front().lumenCentre.y(), start));
        const Vector3d middle = g.indexToPatient(Vector3d(between.x(), between.y(), start));
        diameters[own.x() > middle.x() ? "left_common_iliac_diameter_mm" : "right_common_iliac_diameter_mm"] = diameter;
    }
    return diameters;
}

} // namespace vsim::imaging::detail
