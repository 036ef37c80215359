// PressureProjection.cpp on the device: the solid and wall faces, the right side, the velocity's correction, the
// divergence left and the conjugate gradients' vector updates (the multigrid preconditioner: MultigridKernels.cu).

#include "BlockReduce.cuh"
#include "SmokeKernels.cuh"

#include "vsim/cuda_common/CudaCheck.h"

namespace vsim::cuda::smoke {
namespace {

/// Face f of the axis's lattice: (i, j, k), its place along the axis and the grid's extent there.
struct FaceSite
{
    int i, j, k, at, n;
};

/// This thread's face of the axis's lattice (launchOver(latticeOf(g, axis))) and its index f; false past the end.
template <int axis>
__device__ bool faceAt(const GridView& g, unsigned& f, FaceSite& site)
{
    const LatticeShape shape = latticeOf(g, axis);
    if (!threadNode(shape.sx, shape.sy, shape.sz, site.i, site.j, site.k))
        return false;
    f = nodeIndex(site.i, site.j, site.k, shape.sx, shape.sy);
    site.at = axis == 0 ? site.i : axis == 1 ? site.j : site.k;
    site.n = axis == 0 ? g.nx : axis == 1 ? g.ny : g.nz;
    return true;
}

/// The face of `axis` at node (i, j, k) takes 0 on a wall of the domain, else the solid's normal velocity when a
/// side is solid (two solids: their mean). (The axis is a template argument: indexing the kernel's parameters by
/// a run-time axis would copy them to local memory in every thread.)
template <int axis>
__global__ void solidBoundaryKernel(GridView g)
{
    unsigned f;
    FaceSite site;
    if (!faceAt<axis>(g, f, site))
        return;
    const int i = site.i, j = site.j, k = site.k, at = site.at, n = site.n;
    float* face = axis == 0 ? g.u : axis == 1 ? g.v : g.w;
    if ((at == 0 && !g.open[2 * axis]) || (at == n && !g.open[2 * axis + 1]))
    {
        face[f] = 0.0f;
        return;
    }
    const bool lowInside = at > 0, highInside = at < n;
    const unsigned high = highInside ? nodeIndex(i, j, k, g.nx, g.ny) : 0;
    const unsigned low = lowInside ? nodeIndex(i - (axis == 0), j - (axis == 1), k - (axis == 2), g.nx, g.ny) : 0;
    const bool a = lowInside && g.solid[low] == kSolid, b = highInside && g.solid[high] == kSolid;
    if (!a && !b)
        return;
    float sum = 0.0f;
    if (a)
        sum += g.solidVelocity[3 * low + axis];
    if (b)
        sum += g.solidVelocity[3 * high + axis];
    face[f] = sum / float(int(a) + int(b));
}

/// Without solids only the domain's walls: their faces to 0, one thread per face of the two planes across `axis`.
template <int axis>
__global__ void wallFacesKernel(GridView g)
{
    const LatticeShape shape = latticeOf(g, axis);
    const int a = axis == 0 ? shape.sy : shape.sx, b = axis == 2 ? shape.sy : shape.sz; // the plane's two extents
    const int t = int(blockIdx.x * blockDim.x + threadIdx.x);
    if (t >= a * b)
        return;
    const int p = t % a, r = t / a;
    const int n = axis == 0 ? g.nx : axis == 1 ? g.ny : g.nz;
    float* face = axis == 0 ? g.u : axis == 1 ? g.v : g.w;
    const auto index = [&](int along) {
        const int i = axis == 0 ? along : p, j = axis == 0 ? p : axis == 1 ? along : r, k = axis == 2 ? along : r;
        return std::size_t(i) + std::size_t(shape.sx) * (j + std::size_t(shape.sy) * k);
    };
    if (!g.open[2 * axis])
        face[index(0)] = 0.0f;
    if (!g.open[2 * axis + 1])
        face[index(n)] = 0.0f;
}

__device__ float divergenceAt(const GridView& g, unsigned c, int i, int j, int k, float inverse)
{
    const unsigned ux = nodeIndex(i, j, k, g.nx + 1, g.ny), vy = nodeIndex(i, j, k, g.nx, g.ny + 1);
    return inverse * (g.u[ux + 1] - g.u[ux] + g.v[vy + unsigned(g.nx)] - g.v[vy] + g.w[c + unsigned(g.nx) * unsigned(g.ny)] - g.w[c]);
}

__global__ void rightSideKernel(GridView g, LevelView finest, const std::uint8_t* fluid, const float* sink, float* b,
                                sim::smoke::PressureWarmStart::Weights start, float* psi, float* previous)
{
    int i, j, k;
    if (!threadNode(g.nx, g.ny, g.nz, i, j, k))
        return;
    const unsigned c = nodeIndex(i, j, k, g.nx, g.ny), s = finest.slot(i, j, k);
    // The first guess, in the CPU's roundings (no fused multiply-add).
    const bool inFluid = fluid[s];
    const float last = inFluid ? psi[s] : 0.0f;
    psi[s] = inFluid ? __fadd_rn(__fmul_rn(start.current, last), __fmul_rn(start.previous, previous[s])) : 0.0f;
    previous[s] = last;
    const float div = g.solid[c] ? 0.0f : divergenceAt(g, c, i, j, k, float(1.0 / g.h));
    b[s] = float(-g.h * g.h) * (div - (sink ? sink[c] : 0.0f));
}

/// *out = the largest |div u - sink| (NaN as +infinity), by a maximum per block.
__global__ void divergenceLeftKernel(GridView g, const float* sink, double* out)
{
    int i, j, k;
    double left = 0.0;
    if (threadNode(g.nx, g.ny, g.nz, i, j, k))
    {
        const unsigned c = nodeIndex(i, j, k, g.nx, g.ny);
        const float div = g.solid[c] ? 0.0f : divergenceAt(g, c, i, j, k, float(1.0 / g.h));
        const float value = fabsf(div - (sink ? sink[c] : 0.0f));
        left = isnan(value) ? double(INFINITY) : double(value);
    }
    left = blockMax(left); // every thread of the block takes part
    // Only a block above the largest so far goes to the atomic: 65,536 of them on one double would queue.
    if (threadInBlock() == 0 && left > __ldcg(out))
        atomicMaxNonNegative(out, left);
}

/// A side of a face: 1 fluid (psi of the cell), 2 ambient (psi 0: an open face, a vent), 0 a wall or a solid.
__device__ int sideOf(const GridView& g, unsigned c)
{
    return g.solid[c] == kFluid ? 1 : g.solid[c] == kVent ? 2 : 0;
}

template <int axis>
__global__ void correctKernel(GridView g, LevelView finest, const float* psi)
{
    unsigned f;
    FaceSite site;
    if (!faceAt<axis>(g, f, site))
        return;
    const int i = site.i, j = site.j, k = site.k, at = site.at, n = site.n;
    const unsigned high = at < n ? nodeIndex(i, j, k, g.nx, g.ny) : 0;
    const unsigned low = at > 0 ? nodeIndex(i - (axis == 0), j - (axis == 1), k - (axis == 2), g.nx, g.ny) : 0;
    const int lowSide = at > 0 ? sideOf(g, low) : (g.open[2 * axis] ? 2 : 0);
    const int highSide = at < n ? sideOf(g, high) : (g.open[2 * axis + 1] ? 2 : 0);
    // psi loaded with the kinds, not after them (slot 0 stands in for a cell outside: a valid place to read).
    const float psiHigh = psi[at < n ? finest.slot(i, j, k) : 0];
    const float psiLow = psi[at > 0 ? finest.slot(i - (axis == 0), j - (axis == 1), k - (axis == 2)) : 0];
    if ((lowSide == 1 && highSide != 0) || (highSide == 1 && lowSide != 0))
    {
        float* face = axis == 0 ? g.u : axis == 1 ? g.v : g.w;
        face[f] -= float(1.0 / g.h) * ((highSide == 1 ? psiHigh : 0.0f) - (lowSide == 1 ? psiLow : 0.0f));
    }
}

/// Grid-stride (reduceBlocks): few blocks, few atomic additions to `out`.
__global__ void updateSolutionKernel(std::size_t n, float alpha, const float* p, const float* q, float* psi, float* r,
                                     double* out)
{
    double squared = 0.0;
    for (std::size_t c = blockIdx.x * std::size_t(blockDim.x) + threadIdx.x; c < n; c += std::size_t(gridDim.x) * blockDim.x)
    {
        psi[c] += alpha * p[c];
        const float next = r[c] - alpha * q[c];
        r[c] = next;
        squared += double(next) * double(next);
    }
    squared = blockSum(squared);
    if (threadInBlock() == 0)
        atomicAdd(out, squared);
}

__global__ void directionKernel(std::size_t n, float beta, const float* z, float* p)
{
    const std::size_t c = blockIdx.x * std::size_t(blockDim.x) + threadIdx.x;
    if (c < n)
        p[c] = z[c] + beta * p[c];
}

} // namespace

void applySolidBoundaries(const GridView& g, bool anySolid)
{
    if (!anySolid)
    {
        wallFacesKernel<0><<<blocksFor(std::size_t(g.ny) * g.nz), kBlock>>>(g);
        wallFacesKernel<1><<<blocksFor(std::size_t(g.nx) * g.nz), kBlock>>>(g);
        wallFacesKernel<2><<<blocksFor(std::size_t(g.nx) * g.ny), kBlock>>>(g);
        return;
    }
    const LatticeLaunch u = launchOver(latticeOf(g, 0)), v = launchOver(latticeOf(g, 1)), w = launchOver(latticeOf(g, 2));
    solidBoundaryKernel<0><<<u.blocks, u.threads>>>(g);
    solidBoundaryKernel<1><<<v.blocks, v.threads>>>(g);
    solidBoundaryKernel<2><<<w.blocks, w.threads>>>(g);
}

void projectionRightSide(const GridView& g, const LevelView& finest, const std::uint8_t* fluid, const float* sink, float* b,
                         sim::smoke::PressureWarmStart::Weights start, float* psi, float* previous)
{
    const LatticeLaunch cells = launchOver(g.nx, g.ny, g.nz);
    rightSideKernel<<<cells.blocks, cells.threads>>>(g, finest, fluid, sink, b, start, psi, previous);
}

void correctVelocity(const GridView& g, const LevelView& finest, const float* psi)
{
    const LatticeLaunch u = launchOver(latticeOf(g, 0)), v = launchOver(latticeOf(g, 1)), w = launchOver(latticeOf(g, 2));
    correctKernel<0><<<u.blocks, u.threads>>>(g, finest, psi);
    correctKernel<1><<<v.blocks, v.threads>>>(g, finest, psi);
    correctKernel<2><<<w.blocks, w.threads>>>(g, finest, psi);
}

double largestDivergenceLeft(const GridView& g, const float* sink, double* scratch)
{
    VSIM_CUDA_CHECK(cudaMemsetAsync(scratch, 0, sizeof(double)));
    const LatticeLaunch cells = launchOver(g.nx, g.ny, g.nz);
    divergenceLeftKernel<<<cells.blocks, cells.threads>>>(g, sink, scratch);
    return fetchScalar(scratch);
}

double updateSolution(std::size_t n, float alpha, const float* p, const float* q, float* psi, float* r, double* scratch)
{
    VSIM_CUDA_CHECK(cudaMemsetAsync(scratch, 0, sizeof(double)));
    updateSolutionKernel<<<reduceBlocks(n), kBlock>>>(n, alpha, p, q, psi, r, scratch);
    return fetchScalar(scratch);
}

void updateDirection(std::size_t n, float beta, const float* z, float* p)
{
    directionKernel<<<blocksFor(n), kBlock>>>(n, beta, z, p);
}

} // namespace vsim::cuda::smoke