#include "vsim/sim/smoke/SmokeScenes.h"

#include "vsim/core/Error.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace vsim::sim::smoke {
namespace {

constexpr double kMm = 1e-3; // m per mm

/// A grid over [low, high] (m) with `cells` along the longest edge; all walls.
SmokeGrid gridOver(const Eigen::Vector3d& low, const Eigen::Vector3d& high, int cells)
{
    const Eigen::Vector3d size = high - low;
    const double h = size.maxCoeff() / cells;
    SmokeGrid grid = SmokeGrid::make(std::max(2, int(std::ceil(size.x() / h))), std::max(2, int(std::ceil(size.y() / h))),
                                     std::max(2, int(std::ceil(size.z() / h))), h);
    grid.origin = low;
    return grid;
}

/// Marks the fluid cells within `radius` of `centre` as vents.
void vent(SmokeGrid& grid, const Eigen::Vector3d& centre, double radius)
{
    for (int k = 0; k < grid.nz; ++k)
        for (int j = 0; j < grid.ny; ++j)
            for (int i = 0; i < grid.nx; ++i)
                if (grid.isFluid(grid.cell(i, j, k)) && (grid.centre(i, j, k) - centre).norm() <= radius)
                    grid.solid[grid.cell(i, j, k)] = kVent;
}

/// Distance from x to the polyline.
double distanceToPolyline(const std::vector<Eigen::Vector3d>& line, const Eigen::Vector3d& x)
{
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t s = 0; s + 1 < line.size(); ++s)
    {
        const Eigen::Vector3d a = line[s], b = line[s + 1], ab = b - a;
        const double t = std::clamp((x - a).dot(ab) / std::max(ab.squaredNorm(), 1e-30), 0.0, 1.0);
        best = std::min(best, (x - (a + t * ab)).norm());
    }
    return best;
}

/// The point at arc length `s` (m) along the polyline.
Eigen::Vector3d pointAt(const std::vector<Eigen::Vector3d>& line, double s)
{
    for (std::size_t n = 0; n + 1 < line.size(); ++n)
    {
        const double length = (line[n + 1] - line[n]).norm();
        if (s <= length || n + 2 == line.size())
            return line[n] + std::clamp(s / std::max(length, 1e-30), 0.0, 1.0) * (line[n + 1] - line[n]);
        s -= length;
    }
    return line.back();
}

double lengthOf(const std::vector<Eigen::Vector3d>& line)
{
    double length = 0.0;
    for (std::size_t n = 0; n + 1 < line.size(); ++n)
        length += (line[n + 1] - line[n]).norm();
    return length;
}

/// The camera at `from` looking at `target`, with the picture's up as close to `up` as the view allows.
SmokeCamera cameraLookingAt(const Eigen::Vector3d& from, const Eigen::Vector3d& target, const Eigen::Vector3d& up)
{
    SmokeCamera camera;
    camera.position = from;
    camera.direction = (target - from).normalized();
    Eigen::Vector3d pictureUp = up - up.dot(camera.direction) * camera.direction;
    if (pictureUp.norm() < 1e-6)
        pictureUp = camera.direction.unitOrthogonal();
    camera.up = pictureUp.normalized();
    return camera;
}

} // namespace

SmokeScene ballDropScene(int cells)
{
    SmokeScene scene;
    scene.name = "ball-drop";
    scene.description = "the thesis demo (ch. 7.3): a 1 m box open at the top, smoke rising from a source on the floor, "
                        "a rigid ball of 0.08 m radius dropped through it at 1 s (illustrative)";
    DomainBoundaries boundaries{};
    boundaries[5] = DomainBoundary::Open;
    scene.grid = SmokeGrid::make(cells, cells, cells, 1.0 / cells, boundaries);
    scene.up = Eigen::Vector3d::UnitZ();
    scene.source.centre = {0.5, 0.5, 0.08};
    scene.source.radius = 0.06;
    // Dropped through the plume's edge, so that it comes to rest on the floor beside the source, not on it.
    scene.ball = MovingSphere{{0.66, 0.5, 0.85}, 0.08, Eigen::Vector3d::Zero(), false};
    scene.ballReleaseS = 1.0;
    scene.camera = cameraLookingAt({0.05, 0.5, 0.45}, {0.5, 0.5, 0.45}, scene.up);
    return scene;
}

SmokeScene liverBoxScene(int cells)
{
    SmokeScene scene;
    scene.name = "liver-ablation";
    scene.description = "liver ablation under laparoscopy, box phantom (no liver label in the study): an insufflated "
                        "cavity of 0.24 x 0.20 x 0.12 m over a 0.03 m slab of liver, the probe's smoke at the liver's "
                        "surface, the insufflator a vent in the roof, a suction port beside the probe (illustrative)";
    scene.grid = gridOver(Eigen::Vector3d::Zero(), {0.24, 0.20, 0.15}, cells);
    scene.up = Eigen::Vector3d::UnitZ();
    for (int k = 0; k < scene.grid.nz; ++k)
        for (int j = 0; j < scene.grid.ny; ++j)
            for (int i = 0; i < scene.grid.nx; ++i)
                if (scene.grid.centre(i, j, k).z() < 0.03)
                    scene.grid.solid[scene.grid.cell(i, j, k)] = kSolid;
    const Eigen::Vector3d site(0.12, 0.10, 0.03);
    scene.source.centre = site + Eigen::Vector3d(0.0, 0.0, 0.004);
    scene.source.radius = std::max(0.005, 1.5 * scene.grid.h);
    vent(scene.grid, {0.025, 0.025, 0.15 - scene.grid.h}, std::max(0.015, 3.0 * scene.grid.h));
    scene.suction = SmokeSuction{site + Eigen::Vector3d(0.03, 0.0, 0.015), std::max(0.008, 2.0 * scene.grid.h), 0.0, 0.0};
    scene.camera = cameraLookingAt({0.12, 0.06, 0.14}, site, Eigen::Vector3d::UnitY());
    return scene;
}

SmokeScene liverDomeScene(const LabelVolume& liver, int cells)
{
    // The liver's most anterior voxel (LPS: the smallest y), the site of the ablation.
    const VolumeGeometry& g = liver.geometry();
    std::optional<Eigen::Vector3d> site;
    for (int k = 0; k < g.dims[2]; ++k)
        for (int j = 0; j < g.dims[1]; ++j)
            for (int i = 0; i < g.dims[0]; ++i)
                if (liver.at(i, j, k) > 0)
                {
                    const Eigen::Vector3d p = g.indexToPatient(Eigen::Vector3d(i, j, k));
                    if (!site || p.y() < site->y())
                        site = p;
                }
    if (!site)
        throw Error("the liver label is empty: the liver-ablation dome needs the liver's surface");
    const Eigen::Vector3d siteM = kMm * *site;
    SmokeScene scene;
    scene.name = "liver-ablation";
    scene.description = "liver ablation under laparoscopy: an insufflated dome of 0.24 x 0.12 x 0.20 m (left-right, "
                        "anterior-posterior, head-feet) over the study's liver label at its most anterior point, the "
                        "probe's smoke there, the insufflator a vent in the dome's roof, a suction port beside the "
                        "probe (illustrative: a CT shows no insufflated cavity)";
    const Eigen::Vector3d low = siteM + Eigen::Vector3d(-0.12, -0.12, -0.10), high = siteM + Eigen::Vector3d(0.12, 0.03, 0.10);
    scene.grid = gridOver(low, high, cells);
    scene.up = -Eigen::Vector3d::UnitY(); // supine: anterior is up
    for (int k = 0; k < scene.grid.nz; ++k)
        for (int j = 0; j < scene.grid.ny; ++j)
            for (int i = 0; i < scene.grid.nx; ++i)
            {
                const Eigen::Vector3d index = g.patientToIndex(scene.grid.centre(i, j, k) / kMm);
                const int a = int(std::lround(index.x())), b = int(std::lround(index.y())), c = int(std::lround(index.z()));
                if (g.contains(a, b, c) && liver.at(a, b, c) > 0)
                    scene.grid.solid[scene.grid.cell(i, j, k)] = kSolid;
            }
    scene.source.centre = siteM - Eigen::Vector3d(0.0, 0.004, 0.0);
    scene.source.radius = std::max(0.005, 1.5 * scene.grid.h);
    vent(scene.grid, low + Eigen::Vector3d(0.025, scene.grid.h, 0.025), std::max(0.015, 3.0 * scene.grid.h));
    scene.suction = SmokeSuction{siteM + Eigen::Vector3d(0.03, -0.015, 0.0), std::max(0.008, 2.0 * scene.grid.h), 0.0, 0.0};
    scene.camera = cameraLookingAt(siteM + Eigen::Vector3d(0.0, -0.11, -0.04), siteM, Eigen::Vector3d::UnitZ());
    return scene;
}

SmokeScene evhTunnelScene(const std::vector<Eigen::Vector3d>& centerlineMm, double vesselRadiusMm, double tunnelRadiusMm,
                          int cells)
{
    std::vector<Eigen::Vector3d> line;
    for (const Eigen::Vector3d& p : centerlineMm)
        line.push_back(kMm * p);
    const double total = lengthOf(line);
    if (line.size() < 2 || total < 0.02)
        throw Error("the EVH tunnel needs a centerline of 20 mm or more");
    // 60 mm of the vessel around its middle.
    const double span = std::min(total, 0.06), start = 0.5 * (total - span);
    std::vector<Eigen::Vector3d> stretch;
    for (int n = 0; n <= 30; ++n)
        stretch.push_back(pointAt(line, start + span * n / 30.0));
    const double vessel = kMm * vesselRadiusMm, tunnel = kMm * std::max(tunnelRadiusMm, vesselRadiusMm + 4.0);
    Eigen::Vector3d low = stretch.front(), high = stretch.front();
    for (const Eigen::Vector3d& p : stretch)
        low = low.cwiseMin(p), high = high.cwiseMax(p);
    SmokeScene scene;
    scene.name = "evh";
    scene.description = "endoscopic vessel harvesting: a CO2 tunnel around 60 mm of the study's vessel (a pre-operative "
                        "CT shows no tunnel: it is drawn around the vessel), the cautery's contact on the vessel's "
                        "anterior wall halfway along, smoke from 9 s after contact (thesis ch. 7), the insufflation port "
                        "a vent at the tunnel's entry, the endoscope 25 mm back in the tunnel (illustrative)";
    scene.grid = gridOver(low - Eigen::Vector3d::Constant(tunnel), high + Eigen::Vector3d::Constant(tunnel), cells);
    scene.up = -Eigen::Vector3d::UnitY(); // supine: anterior is up
    for (int k = 0; k < scene.grid.nz; ++k)
        for (int j = 0; j < scene.grid.ny; ++j)
            for (int i = 0; i < scene.grid.nx; ++i)
            {
                const double d = distanceToPolyline(stretch, scene.grid.centre(i, j, k));
                if (d > tunnel || d < vessel)
                    scene.grid.solid[scene.grid.cell(i, j, k)] = kSolid;
            }
    vent(scene.grid, stretch.front(), tunnel);
    const Eigen::Vector3d middle = pointAt(stretch, 0.5 * span);
    const Eigen::Vector3d anteriorWall = middle + (vessel + 0.5 * scene.grid.h) * scene.up;
    scene.source.centre = anteriorWall;
    scene.source.radius = std::max(0.002, 1.2 * scene.grid.h);
    const Eigen::Vector3d back = pointAt(stretch, std::max(0.0, 0.5 * span - 0.025));
    scene.camera = cameraLookingAt(back + (vessel + 0.5 * (tunnel - vessel)) * scene.up, anteriorWall, scene.up);
    return scene;
}

} // namespace vsim::sim::smoke
