#include "vsim/sim/smoke/SmokeForces.h"

#include <Eigen/Geometry>

#include <algorithm>

namespace vsim::sim::smoke {

void addBuoyancy(SmokeGrid& grid, double dt, double alpha, double beta, const Eigen::Vector3d& up)
{
    const int n[3] = {grid.nx, grid.ny, grid.nz};
    std::vector<float>* faces[3] = {&grid.u, &grid.v, &grid.w};
    for (int axis = 0; axis < 3; ++axis)
    {
        if (up[axis] == 0.0)
            continue;
        const double scale = dt * up[axis];
        const int d[3] = {axis == 0, axis == 1, axis == 2};
        std::vector<float>& face = *faces[axis];
#pragma omp parallel for schedule(static)
        for (int k = d[2]; k < n[2]; ++k)
            for (int j = d[1]; j < n[1]; ++j)
                for (int i = d[0]; i < n[0]; ++i)
                {
                    const std::size_t below = grid.cell(i - d[0], j - d[1], k - d[2]), above = grid.cell(i, j, k);
                    if (grid.solid[below] || grid.solid[above])
                        continue;
                    const double t = 0.5 * (grid.temperature[below] + grid.temperature[above]);
                    const double rho = 0.5 * (grid.density[below] + grid.density[above]);
                    const std::size_t f = axis == 0 ? grid.uFace(i, j, k) : axis == 1 ? grid.vFace(i, j, k) : grid.wFace(i, j, k);
                    face[f] += float(scale * (beta * t - alpha * rho));
                }
    }
}

std::vector<Eigen::Vector3f> cellVorticity(const SmokeGrid& grid)
{
    const int nx = grid.nx, ny = grid.ny, nz = grid.nz;
    std::vector<Eigen::Vector3f> centres(grid.cells()), omega(grid.cells(), Eigen::Vector3f::Zero());
#pragma omp parallel for schedule(static)
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i)
                centres[grid.cell(i, j, k)] = {0.5f * (grid.u[grid.uFace(i, j, k)] + grid.u[grid.uFace(i + 1, j, k)]),
                                               0.5f * (grid.v[grid.vFace(i, j, k)] + grid.v[grid.vFace(i, j + 1, k)]),
                                               0.5f * (grid.w[grid.wFace(i, j, k)] + grid.w[grid.wFace(i, j, k + 1)])};
    const float inverse = float(1.0 / grid.h);
    const std::size_t row = std::size_t(nx), slab = std::size_t(nx) * ny;
#pragma omp parallel for schedule(static)
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i)
            {
                const std::size_t c = grid.cell(i, j, k);
                if (grid.solid[c])
                    continue;
                // d/dx_a of the cell velocity: central differences, one-sided at the domain's edge.
                const auto derivative = [&](int at, int n, std::size_t stride) -> Eigen::Vector3f {
                    const std::size_t lo = at > 0 ? c - stride : c, hi = at + 1 < n ? c + stride : c;
                    const int span = (at > 0) + (at + 1 < n);
                    return span ? Eigen::Vector3f((centres[hi] - centres[lo]) * (inverse / float(span)))
                                : Eigen::Vector3f::Zero();
                };
                const Eigen::Vector3f dx = derivative(i, nx, 1), dy = derivative(j, ny, row), dz = derivative(k, nz, slab);
                omega[c] = {dy.z() - dz.y(), dz.x() - dx.z(), dx.y() - dy.x()};
            }
    return omega;
}

void accumulateVorticityConfinement(const SmokeGrid& grid, double epsilon, std::vector<Eigen::Vector3f>& force)
{
    if (epsilon <= 0.0)
        return;
    const std::vector<Eigen::Vector3f> omega = cellVorticity(grid);
    std::vector<float> magnitude(grid.cells());
    for (std::size_t c = 0; c < grid.cells(); ++c)
        magnitude[c] = omega[c].norm();
#pragma omp parallel for schedule(static)
    for (int k = 1; k < grid.nz - 1; ++k)
        for (int j = 1; j < grid.ny - 1; ++j)
            for (int i = 1; i < grid.nx - 1; ++i)
            {
                const std::size_t c = grid.cell(i, j, k);
                if (grid.solid[c])
                    continue;
                const Eigen::Vector3f gradient(magnitude[grid.cell(i + 1, j, k)] - magnitude[grid.cell(i - 1, j, k)],
                                               magnitude[grid.cell(i, j + 1, k)] - magnitude[grid.cell(i, j - 1, k)],
                                               magnitude[grid.cell(i, j, k + 1)] - magnitude[grid.cell(i, j, k - 1)]);
                const float length = gradient.norm();
                if (length <= 1e-12f)
                    continue;
                force[c] += float(epsilon * grid.h) * (gradient / length).cross(omega[c]);
            }
}

void addCellForces(SmokeGrid& grid, const std::vector<Eigen::Vector3f>& force, double dt)
{
    const float step = float(dt);
    const auto fluid = [&](int i, int j, int k) { return !grid.isSolid(i, j, k); };
#pragma omp parallel for schedule(static)
    for (int k = 0; k < grid.nz; ++k)
        for (int j = 0; j < grid.ny; ++j)
            for (int i = 0; i < grid.nx; ++i)
            {
                if (!fluid(i, j, k))
                    continue;
                const Eigen::Vector3f& f = force[grid.cell(i, j, k)];
                // Each cell adds half its force to its upper faces; the lower half comes from the neighbour below.
                if (i + 1 < grid.nx && fluid(i + 1, j, k))
                    grid.u[grid.uFace(i + 1, j, k)] += 0.5f * step * (f.x() + force[grid.cell(i + 1, j, k)].x());
                if (j + 1 < grid.ny && fluid(i, j + 1, k))
                    grid.v[grid.vFace(i, j + 1, k)] += 0.5f * step * (f.y() + force[grid.cell(i, j + 1, k)].y());
                if (k + 1 < grid.nz && fluid(i, j, k + 1))
                    grid.w[grid.wFace(i, j, k + 1)] += 0.5f * step * (f.z() + force[grid.cell(i, j, k + 1)].z());
            }
}

} // namespace vsim::sim::smoke
