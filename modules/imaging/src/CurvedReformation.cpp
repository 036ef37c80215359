#include "vsim/imaging/CurvedReformation.h"

#include "vsim/core/Error.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <optional>

namespace vsim::imaging {
namespace {

/// Any unit vector perpendicular to `t`.
Eigen::Vector3d perpendicular(const Eigen::Vector3d& t)
{
    const Eigen::Vector3d other = std::abs(t.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    return t.cross(other).normalized();
}

} // namespace

std::size_t CenterlineFrames::indexAt(double arc) const
{
    if (arcMm.empty())
        return 0;
    const double clamped = std::clamp(arc, 0.0, arcMm.back());
    return std::min(arcMm.size() - 1, std::size_t(std::lround(clamped / stepMm)));
}

CenterlineFrames centerlineFrames(const std::vector<Eigen::Vector3d>& polyline, const std::vector<double>& radiiMm,
                                  double stepMm)
{
    if (stepMm <= 0.0)
        throw Error("the centerline step must be positive");
    std::vector<double> cumulative{0.0};
    for (std::size_t i = 1; i < polyline.size(); ++i)
        cumulative.push_back(cumulative.back() + (polyline[i] - polyline[i - 1]).norm());
    if (polyline.size() < 2 || cumulative.back() < stepMm)
        throw Error(Pattern{"the centerline is shorter than one step (%1 mm)", {std::to_string(stepMm)}});
    CenterlineFrames frames;
    frames.stepMm = stepMm;
    const int count = int(std::floor(cumulative.back() / stepMm)) + 1;
    std::size_t segment = 0;
    for (int k = 0; k < count; ++k)
    {
        const double arc = k * stepMm;
        while (segment + 2 < polyline.size() && cumulative[segment + 1] < arc)
            ++segment;
        const double span = std::max(1e-12, cumulative[segment + 1] - cumulative[segment]);
        const double f = std::clamp((arc - cumulative[segment]) / span, 0.0, 1.0);
        frames.arcMm.push_back(arc);
        frames.points.push_back((1.0 - f) * polyline[segment] + f * polyline[segment + 1]);
        frames.radiiMm.push_back(radiiMm.size() == polyline.size() ? (1.0 - f) * radiiMm[segment] + f * radiiMm[segment + 1] : 0.0);
    }
    // Tangents by central differences of the resampled points; frames by double reflection.
    const std::size_t n = frames.points.size();
    for (std::size_t i = 0; i < n; ++i)
    {
        const Eigen::Vector3d ahead = frames.points[std::min(i + 1, n - 1)], behind = frames.points[i == 0 ? 0 : i - 1];
        frames.tangents.push_back((ahead - behind).normalized());
    }
    frames.normals.push_back(perpendicular(frames.tangents[0]));
    for (std::size_t i = 0; i + 1 < n; ++i)
    {
        const Eigen::Vector3d v1 = frames.points[i + 1] - frames.points[i];
        const double c1 = v1.squaredNorm();
        if (c1 < 1e-24)
        {
            frames.normals.push_back(frames.normals.back());
            continue;
        }
        const Eigen::Vector3d rL = frames.normals[i] - (2.0 / c1) * v1.dot(frames.normals[i]) * v1;
        const Eigen::Vector3d tL = frames.tangents[i] - (2.0 / c1) * v1.dot(frames.tangents[i]) * v1;
        const Eigen::Vector3d v2 = frames.tangents[i + 1] - tL;
        const double c2 = v2.squaredNorm();
        Eigen::Vector3d next = c2 < 1e-24 ? rL : Eigen::Vector3d(rL - (2.0 / c2) * v2.dot(rL) * v2);
        next -= next.dot(frames.tangents[i + 1]) * frames.tangents[i + 1]; // stay exactly perpendicular
        frames.normals.push_back(next.normalized());
    }
    for (std::size_t i = 0; i < n; ++i)
        frames.binormals.push_back(frames.tangents[i].cross(frames.normals[i]));
    return frames;
}

double sampleTrilinear(const CtVolume& ct, const Eigen::Vector3d& pointMm)
{
    const VolumeGeometry& g = ct.geometry();
    const Eigen::Vector3d index = g.patientToIndex(pointMm);
    const int i0 = int(std::floor(index.x())), j0 = int(std::floor(index.y())), k0 = int(std::floor(index.z()));
    if (i0 < 0 || j0 < 0 || k0 < 0 || i0 + 1 >= g.dims[0] || j0 + 1 >= g.dims[1] || k0 + 1 >= g.dims[2])
    {
        // On the last layer of voxels, or outside: the nearest voxel when inside.
        const int i = int(std::lround(index.x())), j = int(std::lround(index.y())), k = int(std::lround(index.z()));
        return g.contains(i, j, k) ? double(ct.at(i, j, k)) : -1024.0;
    }
    const double fx = index.x() - i0, fy = index.y() - j0, fz = index.z() - k0;
    double value = 0.0;
    for (int c = 0; c < 8; ++c)
    {
        const int di = c & 1, dj = (c >> 1) & 1, dk = (c >> 2) & 1;
        const double w = (di ? fx : 1.0 - fx) * (dj ? fy : 1.0 - fy) * (dk ? fz : 1.0 - fz);
        value += w * ct.at(i0 + di, j0 + dj, k0 + dk);
    }
    return value;
}

Eigen::Vector3d acrossDirection(const CenterlineFrames& frames, std::size_t i, double angleDegrees)
{
    const double angle = angleDegrees * M_PI / 180.0;
    return std::cos(angle) * frames.normals[i] + std::sin(angle) * frames.binormals[i];
}

PlaneImage straightenedReformation(const CtVolume& ct, const CenterlineFrames& frames, double halfWidthMm, double angleDegrees)
{
    PlaneImage image;
    image.pixelMm = frames.stepMm;
    image.width = 2 * int(std::ceil(halfWidthMm / frames.stepMm)) + 1;
    image.height = int(frames.points.size());
    image.values.resize(std::size_t(image.width) * std::size_t(image.height));
    const double centre = 0.5 * (image.width - 1);
    for (int row = 0; row < image.height; ++row)
    {
        const Eigen::Vector3d across = acrossDirection(frames, std::size_t(row), angleDegrees);
        for (int column = 0; column < image.width; ++column)
            image.values[std::size_t(row) * std::size_t(image.width) + std::size_t(column)] = float(
                sampleTrilinear(ct, frames.points[std::size_t(row)] + (column - centre) * image.pixelMm * across));
    }
    return image;
}

namespace {

/// The plane perpendicular to the centerline at `arcMm` (crossSection's layout), each pixel `sample`d at its point.
template <typename Sample>
PlaneImage perpendicularPlane(const CenterlineFrames& frames, double arcMm, double halfWidthMm, double pixelMm,
                              double angleDegrees, Sample sample)
{
    const std::size_t i = frames.indexAt(arcMm);
    const Eigen::Vector3d right = acrossDirection(frames, i, angleDegrees);
    const Eigen::Vector3d up = acrossDirection(frames, i, angleDegrees + 90.0);
    PlaneImage image;
    image.pixelMm = pixelMm;
    image.width = image.height = 2 * int(std::ceil(halfWidthMm / pixelMm)) + 1;
    image.values.resize(std::size_t(image.width) * std::size_t(image.height));
    const double centre = 0.5 * (image.width - 1);
    for (int row = 0; row < image.height; ++row)
        for (int column = 0; column < image.width; ++column)
            image.values[std::size_t(row) * std::size_t(image.width) + std::size_t(column)] =
                float(sample(Eigen::Vector3d(frames.points[i] + (column - centre) * pixelMm * right + (centre - row) * pixelMm * up)));
    return image;
}

} // namespace

PlaneImage crossSection(const CtVolume& ct, const CenterlineFrames& frames, double arcMm, double halfWidthMm, double pixelMm,
                        double angleDegrees)
{
    return perpendicularPlane(frames, arcMm, halfWidthMm, pixelMm, angleDegrees,
                              [&](const Eigen::Vector3d& p) { return sampleTrilinear(ct, p); });
}

PlaneImage labelCrossSection(const LabelVolume& labels, const CenterlineFrames& frames, double arcMm, double halfWidthMm,
                             double pixelMm, double angleDegrees)
{
    const VolumeGeometry& g = labels.geometry();
    return perpendicularPlane(frames, arcMm, halfWidthMm, pixelMm, angleDegrees, [&](const Eigen::Vector3d& p) {
        const Eigen::Vector3d index = g.patientToIndex(p);
        const int i = int(std::lround(index.x())), j = int(std::lround(index.y())), k = int(std::lround(index.z()));
        return g.contains(i, j, k) ? double(labels.at(i, j, k)) : 0.0;
    });
}

std::optional<PlaneCaliper> largestCaliper(const PlaneImage& labels)
{
    // The 4-connected region of nonzero pixels holding the centre.
    const int w = labels.width, h = labels.height;
    if (w == 0 || labels.at(w / 2, h / 2) == 0.0f)
        return std::nullopt;
    std::vector<char> inside(labels.values.size(), 0);
    std::vector<std::pair<int, int>> open{{w / 2, h / 2}};
    inside[std::size_t(h / 2) * std::size_t(w) + std::size_t(w / 2)] = 1;
    std::vector<Eigen::Vector2d> edge; // the region's boundary pixels' centres (mm from the top-left pixel's)
    while (!open.empty())
    {
        const auto [x, y] = open.back();
        open.pop_back();
        bool boundary = false;
        for (const auto& [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}})
        {
            const int nx = x + dx, ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= w || ny >= h || labels.at(nx, ny) == 0.0f)
            {
                boundary = true;
                continue;
            }
            char& seen = inside[std::size_t(ny) * std::size_t(w) + std::size_t(nx)];
            if (!seen)
                seen = 1, open.emplace_back(nx, ny);
        }
        if (boundary)
            edge.emplace_back(x * labels.pixelMm, y * labels.pixelMm);
    }
    // The farthest pair of boundary pixels; the caliper reaches their outer edges (half a pixel each way).
    PlaneCaliper best;
    double farthest = -1.0;
    for (std::size_t a = 0; a < edge.size(); ++a)
        for (std::size_t b = a + 1; b < edge.size(); ++b)
            if (const double d = (edge[a] - edge[b]).squaredNorm(); d > farthest)
                farthest = d, best.fromMm = edge[a], best.toMm = edge[b];
    if (farthest < 0.0)
        return PlaneCaliper{edge.front(), edge.front(), labels.pixelMm};
    best.lengthMm = std::sqrt(farthest) + labels.pixelMm;
    return best;
}

} // namespace vsim::imaging
