#include "AorticSections.h"

#include "SlicePieces.h"

#include "vsim/core/Error.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace vsim::imaging::detail {
namespace {

constexpr double kFatLevelHu = -30.0;     ///< half-way between thrombus (30..60 HU) and fat (-100 HU)
constexpr double kBrightLevelHu = 150.0;  ///< bone or another contrast-filled vessel beyond the wall
constexpr double kLeftLumenHu = 120.0;    ///< below this the ray has left the lumen's blurred edge
constexpr double kDenserHu = 35.0;        ///< a rise this far above the wall's level: a touching denser structure
constexpr double kRayStepMm = 0.25;

/// Smoothed HU (bilinear between the in-plane binomial 3 x 3 means) at a continuous index of slice k.
class SliceSampler
{
public:
    SliceSampler(const CtVolume& ct, int k, const Vector2d& centre)
        : m_ct(ct), m_k(k), m_radius(int(std::ceil(kMaxRadiusMm / ct.geometry().spacing.head<2>().minCoeff())) + 2),
          m_low(int(std::floor(centre.x())) - m_radius, int(std::floor(centre.y())) - m_radius),
          m_cache(std::size_t(2 * m_radius + 2) * std::size_t(2 * m_radius + 2), std::numeric_limits<float>::quiet_NaN())
    {
    }

    double at(const Vector2d& index)
    {
        const int i = int(std::floor(index.x())), j = int(std::floor(index.y()));
        const double fx = index.x() - i, fy = index.y() - j;
        return (1 - fx) * (1 - fy) * voxel(i, j) + fx * (1 - fy) * voxel(i + 1, j) + (1 - fx) * fy * voxel(i, j + 1) +
               fx * fy * voxel(i + 1, j + 1);
    }

private:
    double voxel(int i, int j)
    {
        const VolumeGeometry& g = m_ct.geometry();
        i = std::clamp(i, 0, g.dims[0] - 1), j = std::clamp(j, 0, g.dims[1] - 1);
        const int ci = i - m_low.x(), cj = j - m_low.y();
        if (ci < 0 || cj < 0 || ci >= 2 * m_radius + 2 || cj >= 2 * m_radius + 2)
            return inPlaneSmoothed(i, j);
        float& cached = m_cache[std::size_t(ci) + std::size_t(2 * m_radius + 2) * std::size_t(cj)];
        if (std::isnan(cached))
            cached = float(inPlaneSmoothed(i, j));
        return cached;
    }

    /// The 3 x 3 binomial mean in the slice: enough against the noise, without blurring the thin wall across slices.
    double inPlaneSmoothed(int i, int j) const
    {
        const VolumeGeometry& g = m_ct.geometry();
        double sum = 0.0;
        for (int dj = -1; dj <= 1; ++dj)
            for (int di = -1; di <= 1; ++di)
                sum += double((2 - std::abs(di)) * (2 - std::abs(dj))) *
                       m_ct.at(std::clamp(i + di, 0, g.dims[0] - 1), std::clamp(j + dj, 0, g.dims[1] - 1), m_k);
        return sum / 16.0;
    }

    const CtVolume& m_ct;
    int m_k, m_radius;
    Eigen::Vector2i m_low;
    std::vector<float> m_cache;
};

} // namespace

std::vector<std::vector<std::uint32_t>> slicePieces(const LabelVolume& lumen, int k)
{
    return detail::slicePieces(lumen.geometry().dims[0], lumen.geometry().dims[1],
                               [&](int i, int j) { return lumen.at(i, j, k) != 0; });
}

Vector2d centroidOf(const std::vector<std::uint32_t>& pixels, int nx)
{
    Vector2d sum = Vector2d::Zero();
    for (std::uint32_t p : pixels)
        sum += Vector2d(double(p % std::uint32_t(nx)), double(p / std::uint32_t(nx)));
    return sum / double(pixels.size());
}

Section makeSection(int k, const std::vector<std::uint32_t>& pixels, int nx)
{
    Section section;
    section.k = k;
    section.lumenPixels = pixels;
    section.lumenCentre = centroidOf(pixels, nx);
    return section;
}

/// The aortic lumen slice by slice: from the widest piece up and down, the piece nearest the last one, until none
/// is near or it halves (the bifurcation).
std::vector<Section> trackAorta(const LabelVolume& lumen)
{
    const VolumeGeometry& g = lumen.geometry();
    const double pixelArea = g.spacing.x() * g.spacing.y();
    std::vector<std::vector<std::vector<std::uint32_t>>> pieces(std::size_t(g.dims[2]));
    int startK = -1;
    std::size_t startPiece = 0, widest = 0;
    for (int k = 0; k < g.dims[2]; ++k)
    {
        pieces[std::size_t(k)] = slicePieces(lumen, k);
        for (std::size_t n = 0; n < pieces[std::size_t(k)].size(); ++n)
            if (pieces[std::size_t(k)][n].size() > widest)
                widest = pieces[std::size_t(k)][n].size(), startK = k, startPiece = n;
    }
    if (startK < 0 || double(widest) * pixelArea < kMinAorticAreaMm2)
        throw Error("the label holds no aorta-sized cross-section (50 mm2 or more): segment the aorta first "
                    "(vascusim-cli segment --target aorta)");
    std::vector<Section> sections;
    const auto follow = [&](int step) {
        std::vector<std::uint32_t> previous = pieces[std::size_t(startK)][startPiece];
        std::vector<double> areas{double(previous.size())};
        for (int k = startK + step; k >= 0 && k < g.dims[2]; k += step)
        {
            const Vector2d last = centroidOf(previous, g.dims[0]);
            const std::vector<std::uint32_t>* best = nullptr;
            double nearest = 15.0; // mm
            for (const auto& piece : pieces[std::size_t(k)])
            {
                const Vector2d d = (centroidOf(piece, g.dims[0]) - last).cwiseProduct(g.spacing.head<2>());
                if (double(piece.size()) * pixelArea >= kMinAorticAreaMm2 && d.norm() < nearest)
                    nearest = d.norm(), best = &piece;
            }
            std::vector<double> recent(areas.end() - std::ptrdiff_t(std::min<std::size_t>(areas.size(), 10)), areas.end());
            std::nth_element(recent.begin(), recent.begin() + std::ptrdiff_t(recent.size() / 2), recent.end());
            if (!best || double(best->size()) < 0.5 * recent[recent.size() / 2])
                break;
            sections.push_back(makeSection(k, *best, g.dims[0]));
            areas.push_back(double(best->size()));
            previous = *best;
        }
    };
    sections.push_back(makeSection(startK, pieces[std::size_t(startK)][startPiece], g.dims[0]));
    follow(1);
    follow(-1);
    std::sort(sections.begin(), sections.end(), [](const Section& a, const Section& b) { return a.k > b.k; });
    return sections; // superior first
}

/// The outer contour of one section: rays from the lumen centre, then a median filter over +-10 degrees.
void castRays(const CtVolume& ct, const LabelVolume& lumen, Section& section)
{
    const VolumeGeometry& g = ct.geometry();
    SliceSampler sampler(ct, section.k, section.lumenCentre);
    std::array<double, kRays> raw{};
    for (int ray = 0; ray < kRays; ++ray)
    {
        const double angle = 2.0 * std::numbers::pi * ray / kRays;
        const Vector2d step = Vector2d(std::cos(angle) / g.spacing.x(), std::sin(angle) / g.spacing.y()) * kRayStepMm;
        double t = 0.0, previous = 0.0, base = 0.0;
        bool inLumen = true, leftEdge = false;
        std::vector<double> baseSamples;
        double outer = kMaxRadiusMm;
        for (; t < kMaxRadiusMm; t += kRayStepMm)
        {
            const Vector2d index = section.lumenCentre + (t / kRayStepMm) * step;
            const int i = int(std::lround(index.x())), j = int(std::lround(index.y()));
            if (inLumen)
            {
                if (g.contains(i, j, section.k) && lumen.at(i, j, section.k))
                    continue;
                inLumen = false;
                section.lumenEdge[std::size_t(ray)] = t;
                previous = sampler.at(index);
            }
            const double hu = sampler.at(index);
            if (!leftEdge)
            {
                if (hu < kFatLevelHu) // a thin wall straight onto fat
                {
                    outer = t - kRayStepMm * (hu - kFatLevelHu) / (hu - previous);
                    break;
                }
                leftEdge = hu < kLeftLumenHu;
                previous = hu;
                continue;
            }
            // The wall and thrombus level: the median of the first 2 mm past the lumen's edge; a rise of
            // kDenserHu above it is a touching denser structure (a disc, a vein, bone), a fall to fat the wall's edge.
            if (baseSamples.size() < std::size_t(2.0 / kRayStepMm))
            {
                baseSamples.push_back(hu);
                std::vector<double> sorted = baseSamples;
                std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(sorted.size() / 2), sorted.end());
                base = sorted[sorted.size() / 2];
            }
            const double denser = std::min(kBrightLevelHu, base + kDenserHu);
            const double level = hu < kFatLevelHu ? kFatLevelHu : hu > denser ? denser : std::nan("");
            if (!std::isnan(level))
            {
                outer = t - kRayStepMm * (hu - level) / (hu - previous); // the crossing between the two samples
                break;
            }
            previous = hu;
        }
        if (inLumen)
            section.lumenEdge[std::size_t(ray)] = t;
        section.escapedRays += t >= kMaxRadiusMm;
        raw[std::size_t(ray)] = std::max(outer, section.lumenEdge[std::size_t(ray)]);
    }
    // Rays that escaped into a touching structure of thrombus-like density (an intervertebral disc, the psoas) run
    // far beyond the rest: over 1.5 x the contour's median they are replaced by the nearest kept rays.
    std::array<double, kRays> sorted = raw;
    std::nth_element(sorted.begin(), sorted.begin() + kRays / 2, sorted.end());
    const double limit = 1.5 * sorted[kRays / 2];
    std::array<bool, kRays> kept{};
    for (int ray = 0; ray < kRays; ++ray)
        kept[std::size_t(ray)] = raw[std::size_t(ray)] <= limit;
    std::array<double, kRays> mended = raw;
    for (int ray = 0; ray < kRays; ++ray)
    {
        if (kept[std::size_t(ray)])
            continue;
        int before = 1, after = 1;
        while (before < kRays && !kept[std::size_t((ray - before + kRays) % kRays)])
            ++before;
        while (after < kRays && !kept[std::size_t((ray + after) % kRays)])
            ++after;
        if (before >= kRays)
            break; // nothing kept: leave the rays as they are
        const double a = raw[std::size_t((ray - before + kRays) % kRays)], b = raw[std::size_t((ray + after) % kRays)];
        mended[std::size_t(ray)] = a + (b - a) * double(before) / double(before + after);
    }
    for (int ray = 0; ray < kRays; ++ray)
    {
        std::array<double, 21> window{};
        for (int d = -10; d <= 10; ++d)
            window[std::size_t(d + 10)] = mended[std::size_t((ray + d + kRays) % kRays)];
        std::nth_element(window.begin(), window.begin() + 10, window.end());
        section.outer[std::size_t(ray)] = std::max(window[10], section.lumenEdge[std::size_t(ray)]);
    }
}

/// Per direction, the median of the outer radius over +-4 neighbouring sections: a slice through an intervertebral
/// disc or a partial-volume gap is pulled back to its neighbours.
void smoothAcrossSections(std::vector<Section>& sections)
{
    std::vector<std::array<double, kRays>> original(sections.size());
    for (std::size_t s = 0; s < sections.size(); ++s)
        original[s] = sections[s].outer;
    for (std::size_t s = 0; s < sections.size(); ++s)
        for (int ray = 0; ray < kRays; ++ray)
        {
            std::vector<double> window;
            for (long d = -4; d <= 4; ++d)
                if (long(s) + d >= 0 && long(s) + d < long(sections.size()))
                    window.push_back(original[std::size_t(long(s) + d)][std::size_t(ray)]);
            std::nth_element(window.begin(), window.begin() + std::ptrdiff_t(window.size() / 2), window.end());
            sections[s].outer[std::size_t(ray)] = std::max(window[window.size() / 2], sections[s].lumenEdge[std::size_t(ray)]);
        }
}

/// The contour radius (mm) in the direction of an in-plane offset (mm), interpolated between rays.
double contourRadius(const std::array<double, kRays>& radii, const Vector2d& offsetMm)
{
    double angle = std::atan2(offsetMm.y(), offsetMm.x()) * kRays / (2.0 * std::numbers::pi);
    if (angle < 0.0)
        angle += kRays;
    const int a = int(std::floor(angle)) % kRays, b = (a + 1) % kRays;
    const double f = angle - std::floor(angle);
    return (1 - f) * radii[std::size_t(a)] + f * radii[std::size_t(b)];
}

/// The largest caliper (mm) and area (mm2) of the cross-section perpendicular to `normal` through `centre` of the
/// contours `radii` (per section and ray, from each section's lumen centre): where the plane cuts the surface
/// between neighbouring sections' contours, ray by ray (continuous, no voxel quantization).
std::pair<double, double> perpendicularSection(const std::vector<Section>& sections, const VolumeGeometry& g,
                                               const std::array<double, kRays> Section::*radii,
                                               const Vector3d& centre, const Vector3d& normal)
{
    const Vector3d u = normal.unitOrthogonal(), v = normal.cross(u);
    const auto contourPoint = [&](const Section& section, int ray) {
        const double angle = 2.0 * std::numbers::pi * ray / kRays, r = (section.*radii)[std::size_t(ray)];
        return Vector3d(g.indexToPatient(Vector3d(section.lumenCentre.x(), section.lumenCentre.y(), section.k)) +
                        g.direction * Vector3d(r * std::cos(angle), r * std::sin(angle), 0.0));
    };
    // Where the plane cuts the surface between two neighbouring sections' contours, ray by ray.
    std::vector<Vector2d> points;
    for (std::size_t s = 0; s + 1 < sections.size(); ++s)
    {
        if (std::abs(sections[s].k - sections[s + 1].k) != 1)
            continue;
        for (int ray = 0; ray < kRays; ++ray)
        {
            const Vector3d a = contourPoint(sections[s], ray), b = contourPoint(sections[s + 1], ray);
            const double da = (a - centre).dot(normal), db = (b - centre).dot(normal);
            if (da * db > 0.0 || da == db)
                continue;
            const Vector3d p = a + (b - a) * (da / (da - db));
            if ((p - centre).norm() <= kMaxRadiusMm)
                points.emplace_back((p - centre).dot(u), (p - centre).dot(v));
        }
    }
    if (points.size() < 3)
        return {0.0, 0.0};
    double caliper = 0.0;
    for (std::size_t a = 0; a < points.size(); ++a)
        for (std::size_t b = a + 1; b < points.size(); ++b)
            caliper = std::max(caliper, (points[a] - points[b]).squaredNorm());
    std::sort(points.begin(), points.end(), [](const Vector2d& a, const Vector2d& b) {
        return std::atan2(a.y(), a.x()) < std::atan2(b.y(), b.x());
    });
    double area = 0.0;
    for (std::size_t a = 0; a < points.size(); ++a)
    {
        const Vector2d& p = points[a];
        const Vector2d& q = points[(a + 1) % points.size()];
        area += p.x() * q.y() - q.x() * p.y();
    }
    return {std::sqrt(caliper), 0.5 * std::abs(area)};
}

} // namespace vsim::imaging::detail
