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
    Eigen::Vector3f offset;

    /// Trilinear sample at `p` (in cells from the domain's corner), clamped to the lattice; the range of the
    /// eight values used.
    float sample(const Eigen::Vector3f& p, float* low = nullptr, float* high = nullptr) const
    {
        // The lattices here have at least two nodes per axis.
        const float fx = std::clamp(p.x() - offset.x(), 0.0f, float(sx - 1));
        const float fy = std::clamp(p.y() - offset.y(), 0.0f, float(sy - 1));
        const float fz = std::clamp(p.z() - offset.z(), 0.0f, float(sz - 1));
        const int i = std::min(int(fx), sx - 2), j = std::min(int(fy), sy - 2), k = std::min(int(fz), sz - 2);
        const float a = fx - float(i), b = fy - float(j), c = fz - float(k);
        const std::size_t row = std::size_t(sx), slab = std::size_t(sx) * std::size_t(sy);
        const float* base = data->data() + std::size_t(i) + row * std::size_t(j) + slab * std::size_t(k);
        const float v000 = base[0], v100 = base[1], v010 = base[row], v110 = base[row + 1];
        const float v001 = base[slab], v101 = base[slab + 1], v011 = base[slab + row], v111 = base[slab + row + 1];
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
    Eigen::Vector3f at(const Eigen::Vector3f& p) const { return {u.sample(p), v.sample(p), w.sample(p)}; }
};

/// Where the point at `p` (cells) came from over the step, by the midpoint rule, given the velocity at p itself;
/// `dtCells` = dt / h (s/m).
Eigen::Vector3f traceBack(const Velocity& velocity, const Eigen::Vector3f& p, const Eigen::Vector3f& atP, float dtCells)
{
    const Eigen::Vector3f middle = p - 0.5f * dtCells * atP;
    return p - dtCells * velocity.at(middle);
}

/// The velocity at node (i, j, k) of a face lattice (`axis` 0, 1, 2: the u, v, w faces) or of the cells (3): the
/// node's own component exactly, the others the mean of the two or four faces around it (what trilinear
/// interpolation gives there, without its general work). Faces beyond the domain take the nearest ones.
template <int axis>
Eigen::Vector3f nodeVelocity(const Velocity& velocity, int i, int j, int k)
{
    const Lattice* components[3] = {&velocity.u, &velocity.v, &velocity.w};
    Eigen::Vector3f result;
#pragma GCC unroll 3
    for (int c = 0; c < 3; ++c)
    {
        const Lattice& lattice = *components[c];
        const auto at = [&](int x, int y, int z) {
            x = std::clamp(x, 0, lattice.sx - 1), y = std::clamp(y, 0, lattice.sy - 1), z = std::clamp(z, 0, lattice.sz - 1);
            return (*lattice.data)[std::size_t(x) + std::size_t(lattice.sx) * (y + std::size_t(lattice.sy) * z)];
        };
        if (c == axis)
            result[c] = at(i, j, k);
        else if (axis == 3) // a cell centre: the mean of its two faces along c
            result[c] = 0.5f * (at(i, j, k) + at(i + (c == 0), j + (c == 1), k + (c == 2)));
        else
        {
            // A face of `axis`: component c lives half a cell back along `axis` and half a cell forward along c.
            const int ba = axis, bc = c;
            const int d1[3] = {ba == 0 ? -1 : 0, ba == 1 ? -1 : 0, ba == 2 ? -1 : 0};
            const int d2[3] = {bc == 0 ? 1 : 0, bc == 1 ? 1 : 0, bc == 2 ? 1 : 0};
            result[c] = 0.25f * (at(i + d1[0], j + d1[1], k + d1[2]) + at(i, j, k) +
                                at(i + d1[0] + d2[0], j + d1[1] + d2[1], k + d1[2] + d2[2]) + at(i + d2[0], j + d2[1], k + d2[2]));
        }
    }
    return result;
}

/// body(n, i, j, k, p) for every node of the lattice, in parallel: n its index, p its place in cells.
template <class Body>
void forEachNode(const Lattice& shape, const Body& body)
{
    const int sx = shape.sx, sy = shape.sy, sz = shape.sz;
#pragma omp parallel for schedule(static)
    for (int k = 0; k < sz; ++k)
        for (int j = 0; j < sy; ++j)
            for (int i = 0; i < sx; ++i)
                body(std::size_t(i) + std::size_t(sx) * (j + std::size_t(sy) * k), i, j, k,
                     Eigen::Vector3f(float(i), float(j), float(k)) + shape.offset);
}

/// Advects one lattice field in place (`kind`: 0, 1, 2 the u, v, w faces, 3 the cells) from `old`, its values at
/// the start of the step (a copy: `field` is overwritten). `dtCells` = dt / h.
template <int kind>
void advectField(std::vector<float>& field, const std::vector<float>& old, const Lattice& shape,
                 const Velocity& velocity, float dtCells, AdvectionScheme scheme)
{
    Lattice source = shape;
    source.data = &old;
    forEachNode(shape, [&](std::size_t n, int i, int j, int k, const Eigen::Vector3f& p) {
        field[n] = source.sample(traceBack(velocity, p, nodeVelocity<kind>(velocity, i, j, k), dtCells));
    });
    if (scheme != AdvectionScheme::MacCormack)
        return;
    // The forward trace of the semi-Lagrangian result back to the old time: its difference from the old field is
    // twice the scheme's error there.
    std::vector<float> forward(field.size());
    Lattice advected = shape;
    advected.data = &field;
    forEachNode(shape, [&](std::size_t n, int i, int j, int k, const Eigen::Vector3f& p) {
        forward[n] = advected.sample(traceBack(velocity, p, nodeVelocity<kind>(velocity, i, j, k), -dtCells));
    });
    forEachNode(shape, [&](std::size_t n, int i, int j, int k, const Eigen::Vector3f& p) {
        float low = 0.0f, high = 0.0f;
        source.sample(traceBack(velocity, p, nodeVelocity<kind>(velocity, i, j, k), dtCells), &low, &high);
        const float corrected = field[n] + 0.5f * (old[n] - forward[n]);
        if (corrected >= low && corrected <= high) // the limiter: else the semi-Lagrangian value stays
            field[n] = corrected;
    });
}

float minmod(float a, float b)
{
    return a * b <= 0.0f ? 0.0f : (std::abs(a) < std::abs(b) ? a : b);
}

/// One axis's sweep of the conservative transport (see transportConservative) of the two fields (the smoke and
/// the heat): sub-steps of at most half a cell along the axis; `start` holds each field at the start of the step.
template <int axis>
void transportAlong(const std::vector<std::vector<float>*>& fields, const std::vector<std::vector<float>>& start,
                    const SmokeGrid& grid, const std::vector<float>& velocity, double dt)
{
    const int n[3] = {grid.nx, grid.ny, grid.nz};
    // The face of cell (i, j, k) on its low side along the axis.
    const auto faceIndex = [&](int i, int j, int k) {
        if constexpr (axis == 0)
            return grid.uFace(i, j, k);
        else if constexpr (axis == 1)
            return grid.vFace(i, j, k);
        else
            return grid.wFace(i, j, k);
    };
    float fastest = 0.0f;
    for (float value : velocity)
        fastest = std::max(fastest, std::abs(value));
    const int substeps = transportSubsteps(fastest, dt, grid.h);
    const float ratio = float(dt / substeps / grid.h);
    const int extent[3] = {n[0] + (axis == 0), n[1] + (axis == 1), n[2] + (axis == 2)};
    // 1 where smoke passes the face: neither side solid, and not a wall of the domain.
    std::vector<std::uint8_t> passes(velocity.size(), 0);
#pragma omp parallel for schedule(static)
    for (int k = 0; k < extent[2]; ++k)
        for (int j = 0; j < extent[1]; ++j)
            for (int i = 0; i < extent[0]; ++i)
            {
                const int at = axis == 0 ? i : axis == 1 ? j : k;
                const bool lowInside = at > 0, highInside = at < n[axis];
                std::uint8_t through = 1;
                if ((lowInside && grid.isSolid(i - (axis == 0), j - (axis == 1), k - (axis == 2))) ||
                    (highInside && grid.isSolid(i, j, k)))
                    through = 0;
                else if (!lowInside)
                    through = grid.boundaries[std::size_t(2 * axis)] == DomainBoundary::Open;
                else if (!highInside)
                    through = grid.boundaries[std::size_t(2 * axis + 1)] == DomainBoundary::Open;
                passes[faceIndex(i, j, k)] = through;
            }
    constexpr std::size_t kFields = 2; // the smoke and the heat, swept together
    std::vector<float> carried(velocity.size()), flux(kFields * velocity.size());
    const std::ptrdiff_t stride = axis == 0 ? 1 : axis == 1 ? std::ptrdiff_t(n[0]) : std::ptrdiff_t(n[0]) * n[1];
    // The velocity through each face where smoke passes (0 elsewhere): its difference across a cell is the
    // sweep's own divergence.
    for (std::size_t f = 0; f < velocity.size(); ++f)
        carried[f] = passes[f] ? velocity[f] : 0.0f;
    float* values[kFields] = {fields[0]->data(), fields[1]->data()};
    const float* before[kFields] = {start[0].data(), start[1].data()};
    const std::size_t faces = velocity.size();
    for (int sub = 0; sub < substeps; ++sub)
    {
#pragma omp parallel for schedule(static)
        for (int k = 0; k < extent[2]; ++k)
            for (int j = 0; j < extent[1]; ++j)
                for (int i = 0; i < extent[0]; ++i)
                {
                    const std::size_t f = faceIndex(i, j, k);
                    if (!passes[f])
                    {
                        for (std::size_t m = 0; m < kFields; ++m)
                            flux[m * faces + f] = 0.0f;
                        continue;
                    }
                    const int at = axis == 0 ? i : axis == 1 ? j : k;
                    // The index is linear in (i, j, k): cell (i, j, k) shifted by `offset` along the axis; outside
                    // the domain and in solids there is nothing (the face's high cell is offset 0).
                    const std::ptrdiff_t here = std::ptrdiff_t(i) + std::ptrdiff_t(n[0]) * (j + std::ptrdiff_t(n[1]) * k);
                    const float speed = velocity[f];
                    const int upwind = speed >= 0.0f ? -1 : 0, direction = speed >= 0.0f ? 1 : -1;
                    // The upwind cell, the one behind it and the one ahead (towards the face and past it).
                    const int offsets[3] = {upwind, upwind - direction, upwind + direction};
                    bool present[3];
                    std::size_t cells[3];
                    for (int o = 0; o < 3; ++o)
                    {
                        const int index = at + offsets[o];
                        present[o] = index >= 0 && index < n[axis];
                        cells[o] = present[o] ? std::size_t(here + offsets[o] * stride) : 0;
                        present[o] = present[o] && !grid.solid[cells[o]];
                    }
                    for (std::size_t m = 0; m < kFields; ++m)
                    {
                        const float centre = present[0] ? values[m][cells[0]] : 0.0f;
                        const float behind = present[1] ? values[m][cells[1]] : 0.0f;
                        const float ahead = present[2] ? values[m][cells[2]] : 0.0f;
                        flux[m * faces + f] = speed * (centre + 0.5f * float(direction) *
                                                                    minmod(direction * (centre - behind), direction * (ahead - centre)));
                    }
                }
#pragma omp parallel for schedule(static)
        for (int k = 0; k < n[2]; ++k)
            for (int j = 0; j < n[1]; ++j)
                for (int i = 0; i < n[0]; ++i)
                {
                    const std::size_t c = grid.cell(i, j, k);
                    if (grid.solid[c])
                        continue;
                    const std::size_t low = faceIndex(i, j, k);
                    const std::size_t high = faceIndex(i + (axis == 0), j + (axis == 1), k + (axis == 2));
                    // The flux difference, less the start value times this sweep's divergence: summed over the
                    // three sweeps that is start x div u = 0, so the mass is kept, and a uniform field stays so.
                    const float divergence = carried[high] - carried[low];
                    for (std::size_t m = 0; m < kFields; ++m)
                        values[m][c] -= ratio * ((flux[m * faces + high] - flux[m * faces + low]) - before[m][c] * divergence);
                }
    }
}

/// Conservative transport of cell fields by the face velocities over dt, axis by axis (the order reversed every
/// other step, Strang 1968): along each axis explicit sub-steps of at most half a cell, fluxes u_face phi_upwind
/// with a minmod-limited slope (van Leer 1979). A 1D sweep alone would change a uniform field where that axis's
/// velocity converges; each sweep therefore adds back the step's start value times the sweep's own divergence
/// (Easter 1993's correction in its simplest form), which sums to zero over the three sweeps in a divergence-free
/// flow: the smoke mass changes only through open boundaries, sources and the projection's residual divergence,
/// and a uniform field stays uniform. No flux through solid faces or walls, outflow through open faces, ambient
/// (0) inflow. Values that the correction would take below zero (a sharp front emptied within the step) are set
/// to zero.
void transportConservative(std::vector<float>& density, std::vector<float>& temperature, const SmokeGrid& grid,
                           const std::vector<float>& u, const std::vector<float>& v, const std::vector<float>& w,
                           double dt, bool reversed)
{
    const std::vector<std::vector<float>*> fields = {&density, &temperature};
    std::vector<std::vector<float>> start;
    for (const std::vector<float>* field : fields)
        start.push_back(*field);
    for (int pass = 0; pass < 3; ++pass)
        switch (reversed ? 2 - pass : pass)
        {
        case 0: transportAlong<0>(fields, start, grid, u, dt); break;
        case 1: transportAlong<1>(fields, start, grid, v, dt); break;
        default: transportAlong<2>(fields, start, grid, w, dt); break;
        }
    for (std::vector<float>* field : fields)
    {
        float* values = field->data();
        const long count = long(field->size());
#pragma omp parallel for schedule(static)
        for (long c = 0; c < count; ++c)
            values[c] = std::max(values[c], 0.0f);
    }
}

} // namespace

int transportSubsteps(double fastest, double dt, double h)
{
    return std::max(1, int(std::ceil(fastest * dt / h / 0.5 - 1e-3)));
}

void advect(SmokeGrid& grid, double dt, AdvectionScheme velocityScheme, AdvectionScheme scalarScheme,
            bool reverseSweeps)
{
    const std::vector<float> u = grid.u, v = grid.v, w = grid.w;
    const Velocity velocity{{&u, grid.nx + 1, grid.ny, grid.nz, {0.0, 0.5, 0.5}},
                            {&v, grid.nx, grid.ny + 1, grid.nz, {0.5, 0.0, 0.5}},
                            {&w, grid.nx, grid.ny, grid.nz + 1, {0.5, 0.5, 0.0}}};
    const float dtCells = float(dt / grid.h);
    const AdvectionScheme forVelocity =
        velocityScheme == AdvectionScheme::Conservative ? AdvectionScheme::MacCormack : velocityScheme;
    advectField<0>(grid.u, u, velocity.u, velocity, dtCells, forVelocity);
    advectField<1>(grid.v, v, velocity.v, velocity, dtCells, forVelocity);
    advectField<2>(grid.w, w, velocity.w, velocity, dtCells, forVelocity);
    if (scalarScheme == AdvectionScheme::Conservative)
    {
        transportConservative(grid.density, grid.temperature, grid, u, v, w, dt, reverseSweeps);
    }
    else
    {
        const Lattice cells{nullptr, grid.nx, grid.ny, grid.nz, {0.5, 0.5, 0.5}};
        const std::vector<float> density = grid.density, temperature = grid.temperature;
        advectField<3>(grid.density, density, cells, velocity, dtCells, scalarScheme);
        advectField<3>(grid.temperature, temperature, cells, velocity, dtCells, scalarScheme);
    }
    for (std::size_t c = 0; c < grid.cells(); ++c)
        if (grid.solid[c])
            grid.density[c] = 0.0f, grid.temperature[c] = 0.0f;
}

} // namespace vsim::sim::smoke
