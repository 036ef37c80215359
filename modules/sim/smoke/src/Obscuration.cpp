#include "vsim/sim/smoke/Obscuration.h"

#include "vsim/core/Error.h"

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>

namespace vsim::sim::smoke {
namespace {

/// The cell holding x, or false outside the domain.
bool cellOf(const SmokeGrid& grid, const Eigen::Vector3d& x, int& i, int& j, int& k)
{
    const Eigen::Vector3d p = (x - grid.origin) / grid.h;
    i = int(std::floor(p.x())), j = int(std::floor(p.y())), k = int(std::floor(p.z()));
    return grid.inside(i, j, k);
}

} // namespace

ObscurationView obscuration(const SmokeGrid& grid, const SmokeCamera& camera, double massExtinctionM2PerKg,
                            double visibleTransmittance)
{
    int ci = 0, cj = 0, ck = 0;
    if (!cellOf(grid, camera.position, ci, cj, ck) || grid.isSolid(ci, cj, ck))
        throw Error("the endoscope camera is outside the smoke's domain or inside tissue");
    const Eigen::Vector3d forward = camera.direction.normalized();
    const Eigen::Vector3d right = forward.cross(camera.up).normalized();
    const Eigen::Vector3d up = right.cross(forward);
    const double halfWidth = std::tan(0.5 * camera.fieldOfViewDeg * std::numbers::pi / 180.0);
    const double halfHeight = halfWidth * camera.height / camera.width;
    const double step = 0.5 * grid.h;
    const double longest = grid.h * (grid.nx + grid.ny + grid.nz);
    ObscurationView view;
    view.width = camera.width, view.height = camera.height;
    view.transmittance.assign(std::size_t(camera.width) * camera.height, 1.0f);
    int obscured = 0;
    double sum = 0.0;
#pragma omp parallel for reduction(+ : obscured, sum) schedule(dynamic, 4)
    for (int y = 0; y < camera.height; ++y)
        for (int x = 0; x < camera.width; ++x)
        {
            const double sx = ((x + 0.5) / camera.width * 2.0 - 1.0) * halfWidth;
            const double sy = (1.0 - (y + 0.5) / camera.height * 2.0) * halfHeight;
            const Eigen::Vector3d ray = (forward + sx * right + sy * up).normalized();
            double depth = 0.0; // integral rho ds (kg/m^2), midpoint rule
            for (double s = 0.5 * step; s < longest; s += step)
            {
                const Eigen::Vector3d point = camera.position + s * ray;
                int i = 0, j = 0, k = 0;
                if (!cellOf(grid, point, i, j, k) || grid.isSolid(i, j, k))
                    break; // the tissue it looks at, or the domain's end
                depth += double(grid.sampleCells(grid.density, point)) * step;
            }
            const double transmittance = std::exp(-massExtinctionM2PerKg * depth);
            view.transmittance[std::size_t(y) * camera.width + x] = float(transmittance);
            obscured += transmittance < visibleTransmittance ? 1 : 0;
            sum += transmittance;
        }
    view.obscuredFraction = double(obscured) / double(view.transmittance.size());
    view.meanTransmittance = sum / double(view.transmittance.size());
    return view;
}

double firstTimeReaching(const std::vector<std::pair<double, double>>& curve, double level, double fromS)
{
    for (std::size_t n = 0; n < curve.size(); ++n)
    {
        if (curve[n].first < fromS || curve[n].second < level)
            continue;
        if (n == 0 || curve[n - 1].first < fromS || curve[n - 1].second >= level)
            return curve[n].first;
        const auto& [t0, f0] = curve[n - 1];
        const auto& [t1, f1] = curve[n];
        return t0 + (level - f0) / (f1 - f0) * (t1 - t0);
    }
    return -1.0;
}

} // namespace vsim::sim::smoke
