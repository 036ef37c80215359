#include "vsim/sim/network/WorkingAngle.h"

#include "vsim/core/Error.h"
#include "vsim/core/Localized.h"
#include "vsim/sim/network/TipOrientation.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>
#include <string>

namespace vsim::sim::network {
namespace {

constexpr double kSampleMm = 0.5;     ///< path points for the overlap
constexpr double kTipClearMm = 3.0;   ///< the path's last millimetres, where the tree downstream starts
constexpr double kApartMm = 1.0;      ///< vessels this far apart in 3D (beyond their radii) overlap when projected together
constexpr double kCellMm = 4.0;       ///< the overlap's 2D grid

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

/// Distance from p to the segment ab (any dimension).
template <typename V> double toSegment(const V& p, const V& a, const V& b)
{
    const V d = b - a;
    const double t = std::clamp((p - a).dot(d) / std::max(1e-300, d.squaredNorm()), 0.0, 1.0);
    return (a + t * d - p).norm();
}

/// The pieces of a segment's centerline with radii interpolated by arc length.
void addPieces(const VesselNetwork& network, std::size_t s, std::vector<AngleScene::Piece>& pieces)
{
    const std::vector<Eigen::Vector3d> path = network.segmentPath(s);
    const auto& segment = network.segments[s];
    double total = 0.0, along = 0.0;
    for (std::size_t i = 0; i + 1 < path.size(); ++i)
        total += (path[i + 1] - path[i]).norm();
    for (std::size_t i = 0; i + 1 < path.size(); ++i)
    {
        const double length = (path[i + 1] - path[i]).norm();
        const double f = total > 0.0 ? (along + 0.5 * length) / total : 0.5;
        pieces.push_back({path[i], path[i + 1], segment.startRadiusMm + f * (segment.endRadiusMm - segment.startRadiusMm), int(s)});
        along += length;
    }
}

} // namespace

Eigen::Vector3d detectorDirection(const CArmAngles& angles)
{
    const double a = radians(angles.laoDeg), b = radians(angles.cranialDeg);
    return {std::sin(a) * std::cos(b), -std::cos(a) * std::cos(b), std::sin(b)};
}

std::pair<Eigen::Vector3d, Eigen::Vector3d> imageAxes(const Eigen::Vector3d& direction)
{
    const Eigen::Vector3d up = (Eigen::Vector3d::UnitZ() - direction.z() * direction).normalized();
    return {(-direction).cross(up), up};
}

AngleScene angleScene(const VesselNetwork& network, int tipNode)
{
    if (tipNode == network.root)
        throw Error("the working angle needs a tip away from the root: there is no path to see");
    const TipOrientation fromRoot = orientFromTip(network, network.root);
    std::vector<int> path; // tip to root
    for (int node = tipNode; node != network.root;)
    {
        const int s = fromRoot.parentSegment[std::size_t(node)];
        if (s < 0)
            throw Error(Pattern{"the catheter tip (node %1) is not connected to the root", {std::to_string(tipNode)}});
        path.push_back(s);
        node = fromRoot.upstreamNode[std::size_t(s)];
    }
    auto guiding = [&](int s) {
        std::string name = network.segments[std::size_t(s)].name;
        std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return char(std::tolower(c)); });
        return name == kGuidingVessel;
    };
    const auto first = std::find_if(path.rbegin(), path.rend(), guiding); // the guiding vessel's piece nearest the root
    AngleScene scene;
    scene.start = first == path.rend() ? network.root : fromRoot.upstreamNode[std::size_t(*first)];
    path.erase(first == path.rend() ? path.end() : first.base(), path.end());
    std::vector<char> onPath(network.segments.size(), 0), opacified(network.segments.size(), scene.start == network.root);
    for (int s : path)
        onPath[std::size_t(s)] = 1;
    if (first != path.rend()) // the tree the contrast reaches from the guiding vessel: it and what lies beyond it
        for (std::size_t s = 0; s < network.segments.size(); ++s)
            for (int up = int(s); up >= 0 && fromRoot.active(up) && !opacified[s];)
            {
                opacified[s] = up == *first;
                const int node = fromRoot.upstreamNode[std::size_t(up)];
                up = node == network.root ? -1 : fromRoot.parentSegment[std::size_t(node)];
            }
    for (std::size_t s = 0; s < network.segments.size(); ++s)
        if (onPath[s] || opacified[s])
            addPieces(network, s, onPath[s] ? scene.path : scene.others);
    const Eigen::Vector3d& tip = network.nodes[std::size_t(tipNode)].positionMm;
    for (const AngleScene::Piece& piece : scene.path)
    {
        const int steps = std::max(1, int(std::ceil((piece.b - piece.a).norm() / kSampleMm)));
        for (int k = 0; k <= steps; ++k)
        {
            const Eigen::Vector3d p = piece.a + (piece.b - piece.a) * (double(k) / steps);
            if ((p - tip).norm() > kTipClearMm)
                scene.samples.emplace_back(p, piece.radiusMm);
        }
    }
    return scene;
}

ViewQuality viewQuality(const AngleScene& scene, const Eigen::Vector3d& direction)
{
    const auto [right, up] = imageAxes(direction);
    auto project = [&](const Eigen::Vector3d& p) { return Eigen::Vector2d(p.dot(right), p.dot(up)); };
    ViewQuality quality;
    double length = 0.0, projected = 0.0;
    for (const AngleScene::Piece& piece : scene.path)
    {
        length += (piece.b - piece.a).norm();
        projected += (project(piece.b) - project(piece.a)).norm();
    }
    quality.foreshortening = length > 0.0 ? std::max(0.0, 1.0 - projected / length) : 0.0;
    if (scene.samples.empty() || scene.others.empty())
        return quality;

    // The other vessels' projections binned on a 2D grid (their boxes grown by their radius and the largest
    // sample radius).
    double sampleRadius = 0.0;
    for (const auto& [p, r] : scene.samples)
        sampleRadius = std::max(sampleRadius, r);
    Eigen::Vector2d lower = project(scene.samples.front().first), upper = lower;
    for (const auto& [p, r] : scene.samples)
        lower = lower.cwiseMin(project(p)), upper = upper.cwiseMax(project(p));
    lower.array() -= 1.0, upper.array() += 1.0;
    const Eigen::Vector2i cells = ((upper - lower) / kCellMm).array().floor().cast<int>().matrix() + Eigen::Vector2i::Ones();
    std::vector<std::vector<int>> binned(std::size_t(cells.x()) * std::size_t(cells.y()));
    for (std::size_t i = 0; i < scene.others.size(); ++i)
    {
        const AngleScene::Piece& piece = scene.others[i];
        const double grow = piece.radiusMm + sampleRadius;
        const Eigen::Vector2d a = project(piece.a), b = project(piece.b);
        const Eigen::Vector2d lo = a.cwiseMin(b).array() - grow, hi = a.cwiseMax(b).array() + grow;
        if ((hi.array() < lower.array()).any() || (lo.array() > upper.array()).any())
            continue;
        const Eigen::Vector2i first = ((lo - lower) / kCellMm).array().floor().cast<int>().max(0).matrix();
        const Eigen::Vector2i last = ((hi - lower) / kCellMm).array().floor().cast<int>().min(cells.array() - 1).matrix();
        for (int y = first.y(); y <= last.y(); ++y)
            for (int x = first.x(); x <= last.x(); ++x)
                binned[std::size_t(x) + std::size_t(cells.x()) * std::size_t(y)].push_back(int(i));
    }
    std::size_t overlapped = 0;
    for (const auto& [p, r] : scene.samples)
    {
        const Eigen::Vector2d q = project(p);
        const Eigen::Vector2i c = ((q - lower) / kCellMm).array().floor().cast<int>().max(0).min(cells.array() - 1).matrix();
        for (int i : binned[std::size_t(c.x()) + std::size_t(cells.x()) * std::size_t(c.y())])
        {
            const AngleScene::Piece& piece = scene.others[std::size_t(i)];
            const double reach = piece.radiusMm + r;
            if (toSegment(q, project(piece.a), project(piece.b)) <= reach && toSegment(p, piece.a, piece.b) > reach + kApartMm)
            {
                ++overlapped;
                break;
            }
        }
    }
    quality.overlap = double(overlapped) / double(scene.samples.size());
    return quality;
}

WorkingAngle workingAngle(const VesselNetwork& network, int tipNode, const Progress& progress)
{
    const AngleScene scene = angleScene(network, tipNode);
    WorkingAngle best;
    best.pathStart = scene.start;
    best.frontal = viewQuality(scene, detectorDirection({}));
    best.quality = best.frontal;
    best.evaluated = 1;
    auto consider = [&](double lao, double cranial) {
        lao = std::clamp(lao, -kLaoRangeDeg, kLaoRangeDeg);
        cranial = std::clamp(cranial, -kCranialRangeDeg, kCranialRangeDeg);
        const ViewQuality q = viewQuality(scene, detectorDirection({lao, cranial}));
        ++best.evaluated;
        if (q.objective() < best.quality.objective() - 1e-12)
            best.angles = {lao, cranial}, best.quality = q;
    };
    for (double lao = -kLaoRangeDeg; lao <= kLaoRangeDeg + 1e-9; lao += 5.0)
    {
        progress.throwIfCancelled();
        for (double cranial = -kCranialRangeDeg; cranial <= kCranialRangeDeg + 1e-9; cranial += 5.0)
            consider(lao, cranial);
        progress.report(0.8 * (lao + kLaoRangeDeg) / (2.0 * kLaoRangeDeg), localized("vsim::Progress", "working angle"));
    }
    for (const auto& [step, reach] : {std::pair{1.0, 5.0}, std::pair{0.25, 1.0}})
    {
        const CArmAngles centre = best.angles;
        for (double dl = -reach; dl <= reach + 1e-9; dl += step)
            for (double dc = -reach; dc <= reach + 1e-9; dc += step)
                consider(centre.laoDeg + dl, centre.cranialDeg + dc);
    }
    progress.report(1.0, localized("vsim::Progress", "working angle"));
    return best;
}

ProjectionImage dsaProjection(const VesselNetwork& network, int tipNode, const CArmAngles& angles, double pixelMm)
{
    const AngleScene scene = angleScene(network, tipNode);
    const Eigen::Vector3d d = detectorDirection(angles);
    const auto [right, up] = imageAxes(d);
    auto project = [&](const Eigen::Vector3d& p) { return Eigen::Vector2d(p.dot(right), p.dot(up)); };
    Eigen::Vector2d lower = project(scene.path.front().a), upper = lower;
    for (const auto* pieces : {&scene.path, &scene.others})
        for (const AngleScene::Piece& piece : *pieces)
            for (const Eigen::Vector3d& p : {piece.a, piece.b})
                lower = lower.cwiseMin(project(p)), upper = upper.cwiseMax(project(p));
    lower.array() -= 5.0, upper.array() += 5.0;
    ProjectionImage image;
    image.pixelMm = pixelMm;
    image.width = int(std::ceil((upper.x() - lower.x()) / pixelMm));
    image.height = int(std::ceil((upper.y() - lower.y()) / pixelMm));
    std::vector<float> iodine(std::size_t(image.width) * std::size_t(image.height), 0.0f); // mm of contrast
    std::vector<float> vessel(iodine.size(), 0.0f); // one segment's, its pieces' joints counted once
    std::vector<std::size_t> touched;
    auto addVessel = [&] {
        for (std::size_t i : touched)
            iodine[i] += vessel[i], vessel[i] = 0.0f;
        touched.clear();
    };
    int current = -1;
    for (const auto* pieces : {&scene.path, &scene.others})
        for (const AngleScene::Piece& piece : *pieces)
        {
            if (piece.segment != current)
                addVessel(), current = piece.segment;
            const double density = pieces == &scene.path ? 2.0 : 1.0;
            const Eigen::Vector3d axis = (piece.b - piece.a).normalized();
            const double across = std::max(0.2, axis.cross(d).norm()); // the beam's slant through the tube
            const Eigen::Vector2d a = project(piece.a), b = project(piece.b);
            const double r = piece.radiusMm;
            const int x0 = std::max(0, int((std::min(a.x(), b.x()) - r - lower.x()) / pixelMm));
            const int x1 = std::min(image.width - 1, int((std::max(a.x(), b.x()) + r - lower.x()) / pixelMm));
            const int y0 = std::max(0, int((upper.y() - std::max(a.y(), b.y()) - r) / pixelMm));
            const int y1 = std::min(image.height - 1, int((upper.y() - std::min(a.y(), b.y()) + r) / pixelMm));
            for (int y = y0; y <= y1; ++y)
                for (int x = x0; x <= x1; ++x)
                {
                    const Eigen::Vector2d q(lower.x() + (x + 0.5) * pixelMm, upper.y() - (y + 0.5) * pixelMm);
                    const double s = toSegment(q, a, b);
                    if (s < r)
                    {
                        const std::size_t i = std::size_t(x) + std::size_t(image.width) * std::size_t(y);
                        if (vessel[i] == 0.0f)
                            touched.push_back(i);
                        vessel[i] = std::max(vessel[i], float(density * 2.0 * std::sqrt(r * r - s * s) / across));
                    }
                }
        }
    addVessel();
    image.transmission.resize(iodine.size());
    for (std::size_t i = 0; i < iodine.size(); ++i)
        image.transmission[i] = float(std::exp(-0.1 * iodine[i]));
    return image;
}

} // namespace vsim::sim::network
