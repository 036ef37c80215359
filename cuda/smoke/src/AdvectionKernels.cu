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
    return __ldg(data + nodeIndex(x, y, z, s.sx, s.sy));
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

/// Where node (i, j, k) came from over the step (dtCells = dt / h; negative: the forward trace), in cells.
__device__ float3 traceBack(const Velocity& vel, const LatticeShape& shape, int kind, int i, int j, int k, float dtCells)
{
    const float px = float(i) + shape.ox, py = float(j) + shape.oy, pz = float(k) + shape.oz;
    const float3 at = nodeVelocity(vel, kind, i, j, k);
    const float half = 0.5f * dtCells;
    const float3 mid = velocityAtCells(vel, px - half * at.x, py - half * at.y, pz - half * at.z);
    return make_float3(px - dtCells * mid.x, py - dtCells * mid.y, pz - dtCells * mid.z);
}

__global__ void semiLagrangianKernel(Velocity vel, LatticeShape shape, int kind, float* field, const float* old, float dtCells)
{
    int i, j, k;
    if (!threadNode(shape.sx, shape.sy, shape.sz, i, j, k))
        return;
    const float3 from = traceBack(vel, shape, kind, i, j, k, dtCells);
    field[nodeIndex(i, j, k, shape.sx, shape.sy)] = sampleLattice(old, shape, from.x, from.y, from.z);
}

__global__ void forwardKernel(Velocity vel, LatticeShape shape, int kind, const float* field, float* forward, float dtCells)
{
    int i, j, k;
    if (!threadNode(shape.sx, shape.sy, shape.sz, i, j, k))
        return;
    const float3 to = traceBack(vel, shape, kind, i, j, k, -dtCells);
    forward[nodeIndex(i, j, k, shape.sx, shape.sy)] = sampleLattice(field, shape, to.x, to.y, to.z);
}

__global__ void correctionKernel(Velocity vel, LatticeShape shape, int kind, float* field, const float* old,
                                 const float* forward, float dtCells)
{
    int i, j, k;
    if (!threadNode(shape.sx, shape.sy, shape.sz, i, j, k))
        return;
    const unsigned n = nodeIndex(i, j, k, shape.sx, shape.sy);
    const float3 from = traceBack(vel, shape, kind, i, j, k, dtCells);
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

/// A thread's two cells' neighbourhood along the sweep's axis, offsets -2 ... 3 from the first: inside the
/// domain, its kind, its smoke and heat.
struct AxisStencil
{
    bool inside[6];
    std::uint8_t kind[6];
    float value[2][6];

    /// Whether cell o holds smoke (inside, fluid: a solid or a vent holds none).
    __device__ bool present(int o) const { return inside[o + 2] && kind[o + 2] == kFluid; }
};

/// The flux of smoke and heat through the face between stencil cells q and q + 1 (q = -1: the first cell's low
/// face, 0: the face between the two cells, 1: the second cell's high face): the face velocity times the upwind cell's value with its minmod-limited slope
/// (Advection.cpp's transportAlong); 0 where smoke does not pass (a solid on either side, a wall of the domain).
/// Returns whether it passes. q and the axis are template arguments: every index below is known when compiled
/// (a run-time index into the stencil, or into the kernel's parameters, would go through local memory).
template <int axis, int q>
__device__ bool faceFlux(const GridView& g, const AxisStencil& s, float speed, float flux[2])
{
    const bool lowInside = s.inside[q + 2], highInside = s.inside[q + 3];
    bool through = !((lowInside && s.kind[q + 2] == kSolid) || (highInside && s.kind[q + 3] == kSolid));
    if (through && !lowInside)
        through = g.open[2 * axis];
    else if (through && !highInside)
        through = g.open[2 * axis + 1];
    if (!through)
    {
        flux[0] = flux[1] = 0.0f;
        return false;
    }
#pragma unroll
    for (int m = 0; m < 2; ++m)
    {
        const auto at = [&](int o) { return s.present(o) ? s.value[m][o + 2] : 0.0f; };
        if (speed >= 0.0f) // upwind: cell q; behind it q - 1, ahead q + 1
        {
            const float centre = at(q), behind = at(q - 1), ahead = at(q + 1);
            flux[m] = speed * (centre + 0.5f * minmod(centre - behind, ahead - centre));
        }
        else // upwind: cell q + 1; behind it q + 2, ahead q
        {
            const float centre = at(q + 1), behind = at(q + 2), ahead = at(q);
            flux[m] = speed * (centre - 0.5f * minmod(-(centre - behind), -(ahead - centre)));
        }
    }
    return true;
}

/// The value a sub-step leaves in a cell: the fluxes through its two faces, less the step's start value times the
/// sweep's own divergence (the velocity through the faces where smoke passes); a solid or a vent keeps its value.
/// With `clamp` clampKernel's value: negative ones 0, none outside the fluid.
template <bool clamp>
__device__ float2 transported(bool fluid, float ratio, const float value[2], const float start[2], const float lowFlux[2],
                              const float highFlux[2], float divergence)
{
    float out[2];
#pragma unroll
    for (int m = 0; m < 2; ++m)
    {
        const float next = fluid ? value[m] - ratio * ((highFlux[m] - lowFlux[m]) - start[m] * divergence) : value[m];
        out[m] = clamp ? (fluid ? fmaxf(next, 0.0f) : 0.0f) : next;
    }
    return make_float2(out[0], out[1]);
}

/// One sub-step of the axis's sweep, two cells a thread along the axis (the second absent past an odd extent),
/// from the fields `in` into `out`. The face between the two is computed once for both (the CPU computes it for
/// each of its cells, alike: the same floats); the stencil is six cells where two threads of one cell each read
/// ten. With `clamp` (the advection's last sub-step) the values written are clampKernel's. 32-bit indices (the
/// backend refuses grids of 2^31 cells or more).
template <int axis, bool clamp>
__global__ void transportKernel(GridView g, const float* __restrict__ velocity, float ratio, const float* __restrict__ start,
                                const float* __restrict__ density, const float* __restrict__ temperature,
                                float* __restrict__ outDensity, float* __restrict__ outTemperature)
{
    int ti, tj, tk;
    if (!threadNode(axis == 0 ? (g.nx + 1) / 2 : g.nx, axis == 1 ? (g.ny + 1) / 2 : g.ny, axis == 2 ? (g.nz + 1) / 2 : g.nz,
                    ti, tj, tk))
        return;
    ti *= axis == 0 ? 2 : 1, tj *= axis == 1 ? 2 : 1, tk *= axis == 2 ? 2 : 1;
    const unsigned nx = unsigned(g.nx), ny = unsigned(g.ny), cells = nx * ny * unsigned(g.nz);
    const unsigned i = unsigned(ti), j = unsigned(tj), k = unsigned(tk), c = nodeIndex(ti, tj, tk, g.nx, g.ny);
    const int at = int(axis == 0 ? i : axis == 1 ? j : k), n = extentAlong<axis>(g);
    const int stride = axis == 0 ? 1 : axis == 1 ? int(nx) : int(nx * ny);
    const bool second = at + 1 < n;
    // Every load first: the loads wait on memory together.
    AxisStencil s;
#pragma unroll
    for (int o = -2; o <= 3; ++o)
    {
        const bool inside = at + o >= 0 && at + o < n;
        const unsigned cell = unsigned(int(c) + o * stride);
        s.inside[o + 2] = inside;
        s.kind[o + 2] = inside ? g.solid[cell] : kSolid;
        s.value[0][o + 2] = inside ? density[cell] : 0.0f;
        s.value[1][o + 2] = inside ? temperature[cell] : 0.0f;
    }
    // The faces' lattice: x fastest, (nx + 1, ny, nz) for u, (nx, ny + 1, nz) for v, (nx, ny, nz + 1) for w.
    const unsigned sx = nx + (axis == 0), sy = ny + (axis == 1);
    const unsigned faceStride = axis == 0 ? 1u : axis == 1 ? sx : sx * sy;
    const unsigned low = i + sx * (j + sy * k), middle = low + faceStride;
    const float lowSpeed = velocity[low], middleSpeed = velocity[middle];
    const float highSpeed = second ? velocity[middle + faceStride] : 0.0f;
    const unsigned c1 = c + unsigned(stride);
    const float start0[2] = {start[c], start[cells + c]};
    const float start1[2] = {second ? start[c1] : 0.0f, second ? start[cells + c1] : 0.0f};
    float lowFlux[2], middleFlux[2], highFlux[2] = {0.0f, 0.0f};
    const bool lowPasses = faceFlux<axis, -1>(g, s, lowSpeed, lowFlux);
    const bool middlePasses = faceFlux<axis, 0>(g, s, middleSpeed, middleFlux);
    const bool highPasses = second && faceFlux<axis, 1>(g, s, highSpeed, highFlux);
    const float value0[2] = {s.value[0][2], s.value[1][2]}, value1[2] = {s.value[0][3], s.value[1][3]};
    const float through0 = (middlePasses ? middleSpeed : 0.0f) - (lowPasses ? lowSpeed : 0.0f);
    const float2 first = transported<clamp>(s.kind[2] == kFluid, ratio, value0, start0, lowFlux, middleFlux, through0);
    outDensity[c] = first.x, outTemperature[c] = first.y;
    if (!second)
        return;
    const float through1 = (highPasses ? highSpeed : 0.0f) - (middlePasses ? middleSpeed : 0.0f);
    const float2 next = transported<clamp>(s.kind[3] == kFluid, ratio, value1, start1, middleFlux, highFlux, through1);
    outDensity[c1] = next.x, outTemperature[c1] = next.y;
}

template <int axis>
void launchTransport(const LatticeLaunch& launch, bool clamp, const GridView& g, const float* velocity, float ratio,
                     const float* start, const float* density, const float* temperature, float* outDensity,
                     float* outTemperature)
{
    if (clamp)
        transportKernel<axis, true><<<launch.blocks, launch.threads>>>(g, velocity, ratio, start, density, temperature,
                                                                      outDensity, outTemperature);
    else
        transportKernel<axis, false><<<launch.blocks, launch.threads>>>(g, velocity, ratio, start, density, temperature,
                                                                       outDensity, outTemperature);
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
    const LatticeLaunch launch = launchOver(shape);
    semiLagrangianKernel<<<launch.blocks, launch.threads>>>(vel, shape, kind, field, old, dtCells);
    if (!macCormack)
        return;
    forwardKernel<<<launch.blocks, launch.threads>>>(vel, shape, kind, field, forward, dtCells);
    correctionKernel<<<launch.blocks, launch.threads>>>(vel, shape, kind, field, old, forward, dtCells);
}

void transportAxis(GridView& g, int axis, const float* velocity, int substeps, float ratio, const float* start,
                   float*& density, float*& temperature, float*& spareDensity, float*& spareTemperature, bool clampLast)
{
    // Two cells a thread along the axis.
    const LatticeLaunch launch = launchOver(axis == 0 ? (g.nx + 1) / 2 : g.nx, axis == 1 ? (g.ny + 1) / 2 : g.ny,
                                            axis == 2 ? (g.nz + 1) / 2 : g.nz);
    for (int sub = 0; sub < substeps; ++sub)
    {
        g.density = density, g.temperature = temperature;
        const bool clamp = clampLast && sub + 1 == substeps;
        switch (axis)
        {
        case 0: launchTransport<0>(launch, clamp, g, velocity, ratio, start, density, temperature, spareDensity, spareTemperature); break;
        case 1: launchTransport<1>(launch, clamp, g, velocity, ratio, start, density, temperature, spareDensity, spareTemperature); break;
        default: launchTransport<2>(launch, clamp, g, velocity, ratio, start, density, temperature, spareDensity, spareTemperature); break;
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
