#include "vsim/sim/smoke/Advection.h"

#include <algorithm>
#include <cmath>

namespace vsim::sim::smoke {
namespace {

/// A field on an sx x sy x sz lattice whose node (0,0,0) lies `offset` cells from the domain's corner.
struct Lattice
{
    const std::vector<float>* data;
    int sx, sy, sz;
    Eigen::Vector3d offset;

    /// Trilinear sample at `p` (in cells from the domain's corner), clamped to the lattice; the range of the
    /// eight values used.
    float sample(const Eigen::Vector3d& p, float* low = nullptr, float* high = nullptr) const
    {
        const double fx = std::clamp(p.x() - offset.x(), 0.0, double(sx - 1));
        const double fy = std::clamp(p.y() - offset.y(), 0.0, double(sy - 1));
        const double fz = std::clamp(p.z() - offset.z(), 0.0, double(sz - 1));
        const int i = std::min(int(fx), std::max(sx - 2, 0)), j = std::min(int(fy), std::max(sy - 2, 0)),
                  k = std::min(int(fz), std::max(sz - 2, 0));
        const int i1 = std::min(i + 1, sx - 1), j1 = std::min(j + 1, sy - 1), k1 = std::min(k + 1, sz - 1);
        const float a = float(fx - i), b = float(fy - j), c = float(fz - k);
        const auto at = [&](int x, int y, int z) {
            return (*data)[std::size_t(x) + std::size_t(sx) * (y + std::size_t(sy) * z)];
        };
        const float v000 = at(i, j, k), v100 = at(i1, j, k), v010 = at(i, j1, k), v110 = at(i1, j1, k);
        const float v001 = at(i, j, k1), v101 = at(i1, j, k1), v011 = at(i, j1, k1), v111 = at(i1, j1, k1);
        if (low)
        {
            *low = std::min({v000, v100, v010, v110, v001, v101, v011, v111});
            *high = std::max({v000, v100, v010, v110, v001, v101, v011, v111});
        }
        const float c00 = v000 + a * (v100 - v000), c10 = v010 + a * (v110 - v010);
        const float c01 = v001 + a * (v101 - v001), c11 = v011 + a * (v111 - v011);
        const float c0 = c00 + b * (c10 - c00), c1 = c01 + b * (c11 - c01);
        return c0 + c * (c1 - c0);
    }
};

struct Velocity
{
    Lattice u, v, w;
    Eigen::Vector3d at(const Eigen::Vector3d& p) const { return {u.sample(p), v.sample(p), w.sample(p)}; }
};

/// Where the point at `p` (cells) came from over the step, by the midpoint rule; `dtCells` = dt / h (s/m).
Eigen::Vector3d traceBack(const Velocity& velocity, const Eigen::Vector3d& p, double dtCells)
{
    const Eigen::Vector3d middle = p - 0.5 * dtCells * velocity.at(p);
    return p - dtCells * velocity.at(middle);
}

/// Advects one lattice field in place. `dtCells` = dt / h.
void advectField(std::vector<float>& field, const Lattice& shape, const Velocity& velocity, double dtCells,
                 AdvectionScheme scheme)
{
    const std::vector<float> old = field;
    Lattice source = shape;
    source.data = &old;
    std::vector<float> forward;
    if (scheme == AdvectionScheme::MacCormack)
        forward.resize(field.size());
    const int sx = shape.sx, sy = shape.sy, sz = shape.sz;
#pragma omp parallel for schedule(static)
    for (int k = 0; k < sz; ++k)
        for (int j = 0; j < sy; ++j)
            for (int i = 0; i < sx; ++i)
            {
                const std::size_t n = std::size_t(i) + std::size_t(sx) * (j + std::size_t(sy) * k);
                const Eigen::Vector3d p = Eigen::Vector3d(i, j, k) + shape.offset;
                field[n] = source.sample(traceBack(velocity, p, dtCells));
            }
    if (scheme != AdvectionScheme::MacCormack)
        return;
    // The forward trace of the semi-Lagrangian result back to the old time: its difference from the old field is
    // twice the scheme's error there.
    Lattice advected = shape;
    advected.data = &field;
#pragma omp parallel for schedule(static)
    for (int k = 0; k < sz; ++k)
        for (int j = 0; j < sy; ++j)
            for (int i = 0; i < sx; ++i)
            {
                const std::size_t n = std::size_t(i) + std::size_t(sx) * (j + std::size_t(sy) * k);
                const Eigen::Vector3d p = Eigen::Vector3d(i, j, k) + shape.offset;
                forward[n] = advected.sample(traceBack(velocity, p, -dtCells));
            }
#pragma omp parallel for schedule(static)
    for (int k = 0; k < sz; ++k)
        for (int j = 0; j < sy; ++j)
            for (int i = 0; i < sx; ++i)
            {
                const std::size_t n = std::size_t(i) + std::size_t(sx) * (j + std::size_t(sy) * k);
                const Eigen::Vector3d p = Eigen::Vector3d(i, j, k) + shape.offset;
                float low = 0.0f, high = 0.0f;
                source.sample(traceBack(velocity, p, dtCells), &low, &high);
                const float corrected = field[n] + 0.5f * (old[n] - forward[n]);
                if (corrected >= low && corrected <= high) // the limiter: else the semi-Lagrangian value stays
                    field[n] = corrected;
            }
}

double minmod(double a, double b)
{
    return a * b <= 0.0 ? 0.0 : (std::abs(a) < std::abs(b) ? a : b);
}

/// Conservative transport of a cell field by the face velocities over dt: explicit sub-steps of at most half a cell
/// (the sum over the axes), fluxes u_face phi_upwind with a minmod-limited slope; no flux through solid faces or
/// walls, outflow through open faces, ambient (0) inflow.
void transportConservative(std::vector<float>& field, const SmokeGrid& grid, const std::vector<float>& u,
                           const std::vector<float>& v, const std::vector<float>& w, double dt)
{
    const int nx = grid.nx, ny = grid.ny, nz = grid.nz;
    double fastest = 0.0; // the largest |u| + |v| + |w| of a cell's faces
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i)
                fastest = std::max(fastest, double(std::max(std::abs(u[grid.uFace(i, j, k)]), std::abs(u[grid.uFace(i + 1, j, k)])) +
                                                   std::max(std::abs(v[grid.vFace(i, j, k)]), std::abs(v[grid.vFace(i, j + 1, k)])) +
                                                   std::max(std::abs(w[grid.wFace(i, j, k)]), std::abs(w[grid.wFace(i, j, k + 1)]))));
    const int substeps = std::max(1, int(std::ceil(fastest * dt / grid.h / 0.5)));
    const double ratio = dt / substeps / grid.h;
    const auto value = [&](int i, int j, int k) -> double {
        // Outside the domain or inside a solid there is no smoke.
        return grid.inside(i, j, k) && !grid.isSolid(i, j, k) ? double(field[grid.cell(i, j, k)]) : 0.0;
    };
    // The value on a face from the upwind side: the upwind cell plus half its limited slope towards the face.
    const auto faceValue = [&](double velocity, int ia, int ja, int ka, int ib, int jb, int kb) {
        // a is the lower cell, b the upper one along the axis.
        const int di = ib - ia, dj = jb - ja, dk = kb - ka;
        if (velocity >= 0.0)
        {
            const double centre = value(ia, ja, ka);
            return centre + 0.5 * minmod(centre - value(ia - di, ja - dj, ka - dk), value(ib, jb, kb) - centre);
        }
        const double centre = value(ib, jb, kb);
        return centre - 0.5 * minmod(value(ib + di, jb + dj, kb + dk) - centre, centre - value(ia, ja, ka));
    };
    // A face carries smoke when neither side is solid and it is not a wall.
    const auto passes = [&](int ia, int ja, int ka, int ib, int jb, int kb, int lowFace) {
        const bool a = grid.inside(ia, ja, ka), b = grid.inside(ib, jb, kb);
        if ((a && grid.isSolid(ia, ja, ka)) || (b && grid.isSolid(ib, jb, kb)))
            return false;
        if (!a)
            return grid.boundaries[std::size_t(lowFace)] == DomainBoundary::Open;
        if (!b)
            return grid.boundaries[std::size_t(lowFace + 1)] == DomainBoundary::Open;
        return true;
    };
    std::vector<double> fluxU(u.size(), 0.0), fluxV(v.size(), 0.0), fluxW(w.size(), 0.0);
    for (int sub = 0; sub < substeps; ++sub)
    {
#pragma omp parallel for schedule(static)
        for (int k = 0; k <= nz; ++k)
            for (int j = 0; j <= ny; ++j)
                for (int i = 0; i <= nx; ++i)
                {
                    if (j < ny && k < nz)
                    {
                        const std::size_t f = grid.uFace(i, j, k);
                        fluxU[f] = passes(i - 1, j, k, i, j, k, 0) ? u[f] * faceValue(u[f], i - 1, j, k, i, j, k) : 0.0;
                    }
                    if (i < nx && k < nz)
                    {
                        const std::size_t f = grid.vFace(i, j, k);
                        fluxV[f] = passes(i, j - 1, k, i, j, k, 2) ? v[f] * faceValue(v[f], i, j - 1, k, i, j, k) : 0.0;
                    }
                    if (i < nx && j < ny)
                    {
                        const std::size_t f = grid.wFace(i, j, k);
                        fluxW[f] = passes(i, j, k - 1, i, j, k, 4) ? w[f] * faceValue(w[f], i, j, k - 1, i, j, k) : 0.0;
                    }
                }
#pragma omp parallel for schedule(static)
        for (int k = 0; k < nz; ++k)
            for (int j = 0; j < ny; ++j)
                for (int i = 0; i < nx; ++i)
                {
                    const std::size_t c = grid.cell(i, j, k);
                    if (grid.solid[c])
                        continue;
                    const double net = fluxU[grid.uFace(i + 1, j, k)] - fluxU[grid.uFace(i, j, k)] +
                                       fluxV[grid.vFace(i, j + 1, k)] - fluxV[grid.vFace(i, j, k)] +
                                       fluxW[grid.wFace(i, j, k + 1)] - fluxW[grid.wFace(i, j, k)];
                    field[c] = float(field[c] - ratio * net);
                }
    }
}

} // namespace

void advect(SmokeGrid& grid, double dt, AdvectionScheme velocityScheme, AdvectionScheme scalarScheme)
{
    const std::vector<float> u = grid.u, v = grid.v, w = grid.w;
    const Velocity velocity{{&u, grid.nx + 1, grid.ny, grid.nz, {0.0, 0.5, 0.5}},
                            {&v, grid.nx, grid.ny + 1, grid.nz, {0.5, 0.0, 0.5}},
                            {&w, grid.nx, grid.ny, grid.nz + 1, {0.5, 0.5, 0.0}}};
    const double dtCells = dt / grid.h;
    const AdvectionScheme forVelocity =
        velocityScheme == AdvectionScheme::Conservative ? AdvectionScheme::MacCormack : velocityScheme;
    advectField(grid.u, velocity.u, velocity, dtCells, forVelocity);
    advectField(grid.v, velocity.v, velocity, dtCells, forVelocity);
    advectField(grid.w, velocity.w, velocity, dtCells, forVelocity);
    if (scalarScheme == AdvectionScheme::Conservative)
    {
        transportConservative(grid.density, grid, u, v, w, dt);
        transportConservative(grid.temperature, grid, u, v, w, dt);
    }
    else
    {
        const Lattice cells{nullptr, grid.nx, grid.ny, grid.nz, {0.5, 0.5, 0.5}};
        advectField(grid.density, cells, velocity, dtCells, scalarScheme);
        advectField(grid.temperature, cells, velocity, dtCells, scalarScheme);
    }
    for (std::size_t c = 0; c < grid.cells(); ++c)
        if (grid.solid[c])
            grid.density[c] = 0.0f, grid.temperature[c] = 0.0f;
}

} // namespace vsim::sim::smoke
