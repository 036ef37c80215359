// Advection.cpp on the device: the semi-Lagrangian trace (midpoint rule) and MacCormack's correction with its
// limiter, one thread per lattice node; the conservative transport's flux and update, one thread per face and
// per cell.

#include "SmokeKernels.cuh"

#include "vsim/cuda_common/CudaCheck.h"

#include <utility>

namespace vsim::cuda::smoke {
namespace {

struct Velocity
{
    const float *u, *v, *w;
    LatticeShape su, sv, sw;
};

__device__ float3 velocityAtCells(const Velocity& vel, float px, float py, float pz)
{
    return make_float3(sampleLattice(vel.u, vel.su, px, py, pz), sampleLattice(vel.v, vel.sv, px, py, pz),
                       sampleLattice(vel.w, vel.sw, px, py, pz));
}

__device__ float valueAt(const float* data, const LatticeShape& s, int x, int y, int z)
{
    x = min(max(x, 0), s.sx - 1), y = min(max(y, 0), s.sy - 1), z = min(max(z, 0), s.sz - 1);
    return data[std::size_t(x) + std::size_t(s.sx) * (y + std::size_t(s.sy) * z)];
}

/// Advection.cpp's nodeVelocity: at node (i, j, k) of lattice `kind`, its own component exactly, the others the
/// mean of the two (cells) or four (faces) around it.
__device__ float3 nodeVelocity(const Velocity& vel, int kind, int i, int j, int k)
{
    const float* data[3] = {vel.u, vel.v, vel.w};
    const LatticeShape shapes[3] = {vel.su, vel.sv, vel.sw};
    float result[3];
#pragma unroll
    for (int c = 0; c < 3; ++c)
    {
        const float* d = data[c];
        const LatticeShape& s = shapes[c];
        if (c == kind)
            result[c] = valueAt(d, s, i, j, k);
        else if (kind == 3)
            result[c] = 0.5f * (valueAt(d, s, i, j, k) + valueAt(d, s, i + (c == 0), j + (c == 1), k + (c == 2)));
        else
        {
            const int a0 = kind == 0 ? -1 : 0, a1 = kind == 1 ? -1 : 0, a2 = kind == 2 ? -1 : 0;
            const int b0 = c == 0, b1 = c == 1, b2 = c == 2;
            result[c] = 0.25f * (valueAt(d, s, i + a0, j + a1, k + a2) + valueAt(d, s, i, j, k) +
                                 valueAt(d, s, i + a0 + b0, j + a1 + b1, k + a2 + b2) + valueAt(d, s, i + b0, j + b1, k + b2));
        }
    }
    return make_float3(result[0], result[1], result[2]);
}

/// Where node n came from over the step (dtCells = dt / h; negative: the forward trace), in cells.
__device__ float3 traceBack(const Velocity& vel, const LatticeShape& shape, int kind, std::size_t n, float dtCells)
{
    const int i = int(n % std::size_t(shape.sx)), j = int((n / std::size_t(shape.sx)) % std::size_t(shape.sy)),
              k = int(n / (std::size_t(shape.sx) * std::size_t(shape.sy)));
    const float px = float(i) + shape.ox, py = float(j) + shape.oy, pz = float(k) + shape.oz;
    const float3 at = nodeVelocity(vel, kind, i, j, k);
    const float half = 0.5f * dtCells;
    const float3 mid = velocityAtCells(vel, px - half * at.x, py - half * at.y, pz - half * at.z);
    return make_float3(px - dtCells * mid.x, py - dtCells * mid.y, pz - dtCells * mid.z);
}

__global__ void semiLagrangianKernel(Velocity vel, LatticeShape shape, int kind, float* field, const float* old, float dtCells)
{
    const std::size_t n = blockIdx.x * std::size_t(blockDim.x) + threadIdx.x;
    if (n >= nodes(shape))
        return;
    const float3 from = traceBack(vel, shape, kind, n, dtCells);
    field[n] = sampleLattice(old, shape, from.x, from.y, from.z);
}

__global__ void forwardKernel(Velocity vel, LatticeShape shape, int kind, const float* field, float* forward, float dtCells)
{
    const std::size_t n = blockIdx.x * std::size_t(blockDim.x) + threadIdx.x;
    if (n >= nodes(shape))
        return;
    const float3 to = traceBack(vel, shape, kind, n, -dtCells);
    forward[n] = sampleLattice(field, shape, to.x, to.y, to.z);
}

__global__ void correctionKernel(Velocity vel, LatticeShape shape, int kind, float* field, const float* old,
                                 const float* forward, float dtCells)
{
    const std::size_t n = blockIdx.x * std::size_t(blockDim.x) + threadIdx.x;
    if (n >= nodes(shape))
        return;
    const float3 from = traceBack(vel, shape, kind, n, dtCells);
    float low = 0.0f, high = 0.0f;
    sampleLattice(old, shape, from.x, from.y, from.z, &low, &high);
    const float corrected = field[n] + 0.5f * (old[n] - forward[n]);
    if (corrected >= low && corrected <= high) // the limiter: else the semi-Lagrangian value stays
        field[n] = corrected;
}

__device__ float minmod(float a, float b)
{
    return a * b <= 0.0f ? 0.0f : (fabsf(a) < fabsf(b) ? a : b);
}

/// The extent of the grid along `axis` (cells).
template <int axis>
__device__ int extentAlong(const GridView& g)
{
    return axis == 0 ? g.nx : axis == 1 ? g.ny : g.nz;
}

/// Whether smoke passes face (i, j, k) of the axis's lattice: neither side solid, not a wall of the domain. (The
/// axis is a template argument throughout: indexing the kernel's parameters by a run-time axis would copy them
/// to local memory in every thread.)
template <int axis>
__device__ bool passes(const GridView& g, int i, int j, int k)
{
    const int at = axis == 0 ? i : axis == 1 ? j : k, n = extentAlong<axis>(g);
    const bool lowInside = at > 0, highInside = at < n;
    if ((lowInside && g.solid[g.cell(i - (axis == 0), j - (axis == 1), k - (axis == 2))] == kSolid) ||
        (highInside && g.solid[g.cell(i, j, k)] == kSolid))
        return false;
    if (!lowInside)
        return g.open[2 * axis];
    if (!highInside)
        return g.open[2 * axis + 1];
    return true;
}

/// The flux of smoke and heat through face (i, j, k) of the axis's lattice: the face velocity times the upwind
/// cell's value with its minmod-limited slope (Advection.cpp's transportAlong), from the fields `in`.
template <int axis>
__device__ void faceFlux(const GridView& g, const float* velocity, const float* const in[2], int i, int j, int k,
                         std::size_t f, float flux[2])
{
    if (!passes<axis>(g, i, j, k))
    {
        flux[0] = flux[1] = 0.0f;
        return;
    }
    const int n = extentAlong<axis>(g);
    const int at = axis == 0 ? i : axis == 1 ? j : k;
    const long long stride = axis == 0 ? 1 : axis == 1 ? (long long)(g.nx) : (long long)(g.nx) * g.ny;
    const long long here = (long long)(i) + (long long)(g.nx) * (j + (long long)(g.ny) * k);
    const float speed = velocity[f];
    const int upwind = speed >= 0.0f ? -1 : 0, direction = speed >= 0.0f ? 1 : -1;
    const int offsets[3] = {upwind, upwind - direction, upwind + direction};
    bool present[3];
    std::size_t cells[3];
#pragma unroll
    for (int o = 0; o < 3; ++o)
    {
        const int index = at + offsets[o];
        present[o] = index >= 0 && index < n;
        cells[o] = present[o] ? std::size_t(here + offsets[o] * stride) : 0;
        present[o] = present[o] && !g.solid[cells[o]];
    }
#pragma unroll
    for (int m = 0; m < 2; ++m)
    {
        const float centre = present[0] ? in[m][cells[0]] : 0.0f;
        const float behind = present[1] ? in[m][cells[1]] : 0.0f;
        const float ahead = present[2] ? in[m][cells[2]] : 0.0f;
        flux[m] = speed * (centre + 0.5f * float(direction) * minmod(direction * (centre - behind), direction * (ahead - centre)));
    }
}

/// One sub-step of the axis's sweep at each cell, from the fields `in` into `out`: the fluxes through its two
/// faces (each face's computed by both its cells, alike), less the step's start value times the sweep's own
/// divergence. Solid cells keep their values.
template <int axis>
__global__ void transportKernel(GridView g, const float* velocity, float ratio, const float* start, const float* density,
                                const float* temperature, float* outDensity, float* outTemperature)
{
    const std::size_t cells = g.cells(), c = blockIdx.x * std::size_t(blockDim.x) + threadIdx.x;
    if (c >= cells)
        return;
    const float* const in[2] = {density, temperature};
    float* const out[2] = {outDensity, outTemperature};
    if (g.solid[c])
    {
        out[0][c] = in[0][c], out[1][c] = in[1][c];
        return;
    }
    const int i = int(c % std::size_t(g.nx)), j = int((c / std::size_t(g.nx)) % std::size_t(g.ny)),
              k = int(c / (std::size_t(g.nx) * std::size_t(g.ny)));
    const LatticeShape shape = latticeOf(g, axis);
    const auto faceIndex = [&](int x, int y, int z) { return std::size_t(x) + std::size_t(shape.sx) * (y + std::size_t(shape.sy) * z); };
    const int hi = i + (axis == 0), hj = j + (axis == 1), hk = k + (axis == 2);
    const std::size_t low = faceIndex(i, j, k), high = faceIndex(hi, hj, hk);
    float lowFlux[2], highFlux[2];
    faceFlux<axis>(g, velocity, in, i, j, k, low, lowFlux);
    faceFlux<axis>(g, velocity, in, hi, hj, hk, high, highFlux);
    // The sweep's own divergence: the velocity through the faces where smoke passes.
    const float divergence =
        (passes<axis>(g, hi, hj, hk) ? velocity[high] : 0.0f) - (passes<axis>(g, i, j, k) ? velocity[low] : 0.0f);
#pragma unroll
    for (int m = 0; m < 2; ++m)
        out[m][c] = in[m][c] - ratio * ((highFlux[m] - lowFlux[m]) - start[m * cells + c] * divergence);
}

__global__ void clampKernel(GridView g)
{
    const std::size_t c = blockIdx.x * std::size_t(blockDim.x) + threadIdx.x;
    if (c >= g.cells())
        return;
    if (g.solid[c])
        g.density[c] = g.temperature[c] = 0.0f;
    else
        g.density[c] = fmaxf(g.density[c], 0.0f), g.temperature[c] = fmaxf(g.temperature[c], 0.0f);
}

} // namespace

void advectLattice(const GridView& g, int kind, float* field, const float* old, const float* u0, const float* v0,
                   const float* w0, float dtCells, bool macCormack, float* forward)
{
    const Velocity vel{u0, v0, w0, latticeOf(g, 0), latticeOf(g, 1), latticeOf(g, 2)};
    const LatticeShape shape = latticeOf(g, kind);
    const unsigned blocks = blocksFor(nodes(shape));
    semiLagrangianKernel<<<blocks, kBlock>>>(vel, shape, kind, field, old, dtCells);
    if (!macCormack)
        return;
    forwardKernel<<<blocks, kBlock>>>(vel, shape, kind, field, forward, dtCells);
    correctionKernel<<<blocks, kBlock>>>(vel, shape, kind, field, old, forward, dtCells);
}

void transportAxis(GridView& g, int axis, const float* velocity, int substeps, float ratio, const float* start,
                   float*& density, float*& temperature, float*& spareDensity, float*& spareTemperature)
{
    const unsigned blocks = blocksFor(g.cells());
    for (int sub = 0; sub < substeps; ++sub)
    {
        g.density = density, g.temperature = temperature;
        switch (axis)
        {
        case 0: transportKernel<0><<<blocks, kBlock>>>(g, velocity, ratio, start, density, temperature, spareDensity, spareTemperature); break;
        case 1: transportKernel<1><<<blocks, kBlock>>>(g, velocity, ratio, start, density, temperature, spareDensity, spareTemperature); break;
        default: transportKernel<2><<<blocks, kBlock>>>(g, velocity, ratio, start, density, temperature, spareDensity, spareTemperature); break;
        }
        std::swap(density, spareDensity);
        std::swap(temperature, spareTemperature);
    }
    g.density = density, g.temperature = temperature;
}

void clampScalars(const GridView& g)
{
    clampKernel<<<blocksFor(g.cells()), kBlock>>>(g);
}

} // namespace vsim::cuda::smoke
