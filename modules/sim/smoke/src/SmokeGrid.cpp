#include "vsim/sim/smoke/SmokeGrid.h"

#include "vsim/core/Error.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace vsim::sim::smoke {
namespace {

/// Trilinear sample of a field stored on an (sx, sy, sz) lattice whose node (0,0,0) sits at `offset` cells from
/// the domain's corner; positions beyond the lattice take its edge values.
float trilinear(const std::vector<float>& field, int sx, int sy, int sz, const Eigen::Vector3d& cellCoordinates,
                const Eigen::Vector3d& offset)
{
    const Eigen::Vector3d p = cellCoordinates - offset;
    const double fx = std::clamp(p.x(), 0.0, double(sx - 1)), fy = std::clamp(p.y(), 0.0, double(sy - 1)),
                 fz = std::clamp(p.z(), 0.0, double(sz - 1));
    const int i = std::min(int(fx), std::max(sx - 2, 0)), j = std::min(int(fy), std::max(sy - 2, 0)),
              k = std::min(int(fz), std::max(sz - 2, 0));
    const double a = fx - i, b = fy - j, c = fz - k;
    const int i1 = std::min(i + 1, sx - 1), j1 = std::min(j + 1, sy - 1), k1 = std::min(k + 1, sz - 1);
    auto at = [&](int x, int y, int z) { return double(field[std::size_t(x) + std::size_t(sx) * (y + std::size_t(sy) * z)]); };
    const double c00 = at(i, j, k) * (1 - a) + at(i1, j, k) * a, c10 = at(i, j1, k) * (1 - a) + at(i1, j1, k) * a;
    const double c01 = at(i, j, k1) * (1 - a) + at(i1, j, k1) * a, c11 = at(i, j1, k1) * (1 - a) + at(i1, j1, k1) * a;
    return float((c00 * (1 - b) + c10 * b) * (1 - c) + (c01 * (1 - b) + c11 * b) * c);
}

} // namespace

SmokeGrid SmokeGrid::make(int nx, int ny, int nz, double h, const DomainBoundaries& boundaries)
{
    if (nx < 2 || ny < 2 || nz < 2 || !(h > 0.0))
        throw Error(Pattern{"a smoke grid needs at least 2 cells along each axis and a positive cell size (got %1 x "
                            "%2 x %3)",
                            {std::to_string(nx), std::to_string(ny), std::to_string(nz)}});
    SmokeGrid grid;
    grid.nx = nx, grid.ny = ny, grid.nz = nz, grid.h = h, grid.boundaries = boundaries;
    grid.u.assign(std::size_t(nx + 1) * ny * nz, 0.0f);
    grid.v.assign(std::size_t(nx) * (ny + 1) * nz, 0.0f);
    grid.w.assign(std::size_t(nx) * ny * (nz + 1), 0.0f);
    grid.density.assign(grid.cells(), 0.0f);
    grid.temperature.assign(grid.cells(), 0.0f);
    grid.solid.assign(grid.cells(), 0);
    grid.solidVelocity.assign(grid.cells(), Eigen::Vector3f::Zero());
    return grid;
}

float SmokeGrid::sampleCells(const std::vector<float>& field, const Eigen::Vector3d& x) const
{
    return trilinear(field, nx, ny, nz, (x - origin) / h, Eigen::Vector3d(0.5, 0.5, 0.5));
}

Eigen::Vector3d SmokeGrid::velocityAt(const Eigen::Vector3d& x) const
{
    const Eigen::Vector3d p = (x - origin) / h;
    return {trilinear(u, nx + 1, ny, nz, p, Eigen::Vector3d(0.0, 0.5, 0.5)),
            trilinear(v, nx, ny + 1, nz, p, Eigen::Vector3d(0.5, 0.0, 0.5)),
            trilinear(w, nx, ny, nz + 1, p, Eigen::Vector3d(0.5, 0.5, 0.0))};
}

Eigen::Vector3d SmokeGrid::cellVelocity(int i, int j, int k) const
{
    return {0.5 * (u[uFace(i, j, k)] + u[uFace(i + 1, j, k)]), 0.5 * (v[vFace(i, j, k)] + v[vFace(i, j + 1, k)]),
            0.5 * (w[wFace(i, j, k)] + w[wFace(i, j, k + 1)])};
}

double SmokeGrid::maxSpeed() const
{
    float largest = 0.0f;
    for (const std::vector<float>* component : {&u, &v, &w})
        for (float value : *component)
            largest = std::max(largest, std::abs(value));
    return largest;
}

double SmokeGrid::smokeMass() const
{
    double mass = 0.0;
    for (std::size_t c = 0; c < cells(); ++c)
        if (!solid[c])
            mass += density[c];
    return mass * h * h * h;
}

} // namespace vsim::sim::smoke
