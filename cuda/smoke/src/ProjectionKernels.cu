// PressureProjection.cpp and PoissonMultigrid.cpp's operator, smoother and transfers on the device.

#include "BlockReduce.cuh"
#include "SmokeKernels.cuh"

#include "vsim/cuda_common/CudaCheck.h"

namespace vsim::cuda::smoke {
namespace {

/// Cell c's (i, j, k) on an nx x ny x ... lattice, in 32 bits (the coarsest level's loop in one block; the other
/// kernels take their node from launchOver's threads, without dividing).
__device__ void unpack(std::size_t c, int nx, int ny, int& i, int& j, int& k)
{
    const unsigned u = unsigned(c), x = unsigned(nx), y = unsigned(ny);
    i = int(u % x), j = int((u / x) % y), k = int(u / (x * y));
}

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

__global__ void rightSideKernel(GridView g, const std::uint8_t* fluid, const float* sink, float* b, float* psi)
{
    int i, j, k;
    if (!threadNode(g.nx, g.ny, g.nz, i, j, k))
        return;
    const unsigned c = nodeIndex(i, j, k, g.nx, g.ny);
    if (!fluid[c])
        psi[c] = 0.0f;
    const float div = g.solid[c] ? 0.0f : divergenceAt(g, c, i, j, k, float(1.0 / g.h));
    b[c] = float(-g.h * g.h) * (div - (sink ? sink[c] : 0.0f));
}

__global__ void divergenceLeftKernel(GridView g, const float* sink, float* out)
{
    int i, j, k;
    if (!threadNode(g.nx, g.ny, g.nz, i, j, k))
        return;
    const unsigned c = nodeIndex(i, j, k, g.nx, g.ny);
    const float div = g.solid[c] ? 0.0f : divergenceAt(g, c, i, j, k, float(1.0 / g.h));
    out[c] = fabsf(div - (sink ? sink[c] : 0.0f));
}

/// A side of a face: 1 fluid (psi of the cell), 2 ambient (psi 0: an open face, a vent), 0 a wall or a solid.
__device__ int sideOf(const GridView& g, unsigned c)
{
    return g.solid[c] == kFluid ? 1 : g.solid[c] == kVent ? 2 : 0;
}

template <int axis>
__global__ void correctKernel(GridView g, const float* psi)
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
    const float psiHigh = psi[high], psiLow = psi[low]; // loaded with the kinds, not after them (0: a valid cell)
    if ((lowSide == 1 && highSide != 0) || (highSide == 1 && lowSide != 0))
    {
        float* face = axis == 0 ? g.u : axis == 1 ? g.v : g.w;
        face[f] -= float(1.0 / g.h) * ((highSide == 1 ? psiHigh : 0.0f) - (lowSide == 1 ? psiLow : 0.0f));
    }
}

// ---- the operator's levels

__global__ void finestFlagsKernel(GridView g, std::uint8_t* fluid, std::uint8_t* ambient)
{
    const std::size_t c = blockIdx.x * std::size_t(blockDim.x) + threadIdx.x;
    if (c < g.cells())
        fluid[c] = g.solid[c] == kFluid, ambient[c] = g.solid[c] == kVent;
}

__global__ void coarsenKernel(int fx, int fy, int fz, const std::uint8_t* fineFluid, const std::uint8_t* fineAmbient, int cx,
                              int cy, int cz, std::uint8_t* fluid, std::uint8_t* ambient)
{
    int I, J, K;
    if (!threadNode(cx, cy, cz, I, J, K))
        return;
    const unsigned c = nodeIndex(I, J, K, cx, cy);
    bool anyFluid = false, anyAmbient = false;
    for (int k = 2 * K; k < min(2 * K + 2, fz); ++k)
        for (int j = 2 * J; j < min(2 * J + 2, fy); ++j)
            for (int i = 2 * I; i < min(2 * I + 2, fx); ++i)
            {
                const unsigned child = nodeIndex(i, j, k, fx, fy);
                anyFluid = anyFluid || fineFluid[child];
                anyAmbient = anyAmbient || (!fineFluid[child] && fineAmbient[child]);
            }
    fluid[c] = anyFluid;
    ambient[c] = anyAmbient && !anyFluid;
}

struct OpenFaces
{
    std::uint8_t open[6];
};

__global__ void codeKernel(int nx, int ny, int nz, const std::uint8_t* fluid, const std::uint8_t* ambient, OpenFaces faces,
                           std::uint8_t* code)
{
    int i, j, k;
    if (!threadNode(nx, ny, nz, i, j, k))
        return;
    const unsigned c = nodeIndex(i, j, k, nx, ny);
    if (!fluid[c])
    {
        code[c] = 0;
        return;
    }
    const int at[6][3] = {{i - 1, j, k}, {i + 1, j, k}, {i, j - 1, k}, {i, j + 1, k}, {i, j, k - 1}, {i, j, k + 1}};
    int count = 0;
    for (int f = 0; f < 6; ++f)
    {
        const int a = at[f][0], b = at[f][1], d = at[f][2];
        if (a < 0 || b < 0 || d < 0 || a >= nx || b >= ny || d >= nz)
            count += faces.open[f] ? 1 : 0;
        else
        {
            const unsigned n = nodeIndex(a, b, d, nx, ny);
            count += fluid[n] || ambient[n] ? 1 : 0;
        }
    }
    code[c] = std::uint8_t(kFluidCode | count);
}

/// x at cell c and its six neighbours (0 past the level's edge), loaded together: a thread's loads then wait on
/// memory once, not one after another.
struct Neighbourhood
{
    float centre, west, east, south, north, below, above;
};

__device__ Neighbourhood neighbourhood(const LevelView& level, unsigned c, int i, int j, int k, const float* __restrict__ x)
{
    const unsigned row = unsigned(level.nx), slab = row * unsigned(level.ny);
    return {x[c],
            i > 0 ? x[c - 1] : 0.0f,
            i + 1 < level.nx ? x[c + 1] : 0.0f,
            j > 0 ? x[c - row] : 0.0f,
            j + 1 < level.ny ? x[c + row] : 0.0f,
            k > 0 ? x[c - slab] : 0.0f,
            k + 1 < level.nz ? x[c + slab] : 0.0f};
}

/// (A x)_c at cell c = (i, j, k), 0 outside the fluid (the terms in PoissonMultigrid.cpp's order).
__device__ float applyAt(const LevelView& level, unsigned c, int i, int j, int k, const float* __restrict__ x)
{
    const std::uint8_t code = level.code[c];
    const Neighbourhood n = neighbourhood(level, c, i, j, k, x);
    if (!code)
        return 0.0f;
    float sum = float(diagonalOf(code)) * n.centre;
    if (i > 0)
        sum -= n.west;
    if (i + 1 < level.nx)
        sum -= n.east;
    if (j > 0)
        sum -= n.south;
    if (j + 1 < level.ny)
        sum -= n.north;
    if (k > 0)
        sum -= n.below;
    if (k + 1 < level.nz)
        sum -= n.above;
    return sum;
}

/// r = b - A x (the same floats as A x first, then the difference).
__global__ void residualKernel(LevelView level, const float* __restrict__ b, const float* __restrict__ x, float* __restrict__ r)
{
    int i, j, k;
    if (!threadNode(level.nx, level.ny, level.nz, i, j, k))
        return;
    const unsigned c = nodeIndex(i, j, k, level.nx, level.ny);
    r[c] = b[c] - applyAt(level, c, i, j, k, x);
}

/// y = A x, and each block's sum of x . y in partials[its place] (every thread reaches the block's sum).
__global__ void applyDotKernel(LevelView level, const float* __restrict__ x, float* __restrict__ y, double* partials)
{
    int i, j, k;
    double product = 0.0;
    if (threadNode(level.nx, level.ny, level.nz, i, j, k))
    {
        const unsigned c = nodeIndex(i, j, k, level.nx, level.ny);
        const float value = applyAt(level, c, i, j, k, x);
        y[c] = value;
        product = double(x[c]) * double(value);
    }
    product = blockSum(product);
    if (threadInBlock() == 0)
        partials[blockInGrid()] = product;
}

/// Gauss-Seidel at cell c (its neighbours of the other colour fixed).
__device__ void relax(const LevelView& level, unsigned c, int i, int j, int k, float* __restrict__ x, const float* __restrict__ b)
{
    const int diagonal = diagonalOf(level.code[c]); // 0 outside the fluid
    const float rhs = b[c];
    const Neighbourhood n = neighbourhood(level, c, i, j, k, x);
    if (diagonal == 0)
        return;
    float sum = rhs;
    if (i > 0)
        sum += n.west;
    if (i + 1 < level.nx)
        sum += n.east;
    if (j > 0)
        sum += n.south;
    if (j + 1 < level.ny)
        sum += n.north;
    if (k > 0)
        sum += n.below;
    if (k + 1 < level.nz)
        sum += n.above;
    x[c] = sum / float(diagonal);
}

/// The cells of one colour, launched over ((nx + 1) / 2, ny, nz): i = 2 t + (j + k + colour) % 2.
__global__ void smoothKernel(LevelView level, float* __restrict__ x, const float* __restrict__ b, int colour)
{
    int t, j, k;
    if (!threadNode((level.nx + 1) / 2, level.ny, level.nz, t, j, k))
        return;
    const int i = 2 * t + (j + k + colour) % 2;
    if (i < level.nx)
        relax(level, nodeIndex(i, j, k, level.nx, level.ny), i, j, k, x, b);
}

/// The first pass of colour `colour` from x = 0, over every cell: a relaxed cell of that colour has no neighbour
/// of its colour, so its value is b / diagonal (relax's sum of b and six zeros, the same float); every other cell
/// takes 0. It stands for zeroing x and that pass (one write of x, no read of it).
__global__ void smoothFromZeroKernel(LevelView level, float* __restrict__ x, const float* __restrict__ b, int colour)
{
    int i, j, k;
    if (!threadNode(level.nx, level.ny, level.nz, i, j, k))
        return;
    const unsigned c = nodeIndex(i, j, k, level.nx, level.ny);
    const int diagonal = diagonalOf(level.code[c]);
    const float rhs = b[c];
    x[c] = (i + j + k + colour) % 2 == 0 && diagonal != 0 ? (rhs + 0.0f) / float(diagonal) : 0.0f;
}

/// The coarsest level's sweeps in one block. With `inShared` the level (x, b, its codes: 9 bytes a cell) is
/// copied to shared memory first and x back at the end: each pass then waits on shared memory, not on global.
/// A level of no more cells than the block's threads gives each thread one cell, placed once.
__global__ void coarsestKernel(LevelView global, float* globalX, const float* globalB, int sweeps, bool inShared)
{
    extern __shared__ float shared[];
    const std::size_t cells = global.cells();
    LevelView level = global;
    float* x = globalX;
    const float* b = globalB;
    if (inShared)
    {
        float* sharedB = shared + cells;
        std::uint8_t* codes = reinterpret_cast<std::uint8_t*>(shared + 2 * cells);
        for (std::size_t c = threadIdx.x; c < cells; c += blockDim.x)
            sharedB[c] = globalB[c], codes[c] = global.code[c];
        x = shared, b = sharedB, level.code = codes;
    }
    for (std::size_t c = threadIdx.x; c < cells; c += blockDim.x)
        x[c] = 0.0f;
    const bool oneEach = cells <= blockDim.x;
    int mine[3] = {0, 0, 0};
    if (oneEach && threadIdx.x < cells)
        unpack(threadIdx.x, level.nx, level.ny, mine[0], mine[1], mine[2]);
    __syncthreads();
    for (int first = 0; first < 2; ++first)
        for (int sweep = 0; sweep < sweeps; ++sweep)
            for (int pass = 0; pass < 2; ++pass)
            {
                const int colour = (first + pass) % 2;
                if (oneEach)
                {
                    if (threadIdx.x < cells && (mine[0] + mine[1] + mine[2] + colour) % 2 == 0)
                        relax(level, threadIdx.x, mine[0], mine[1], mine[2], x, b);
                }
                else
                    for (std::size_t c = threadIdx.x; c < cells; c += blockDim.x)
                    {
                        int i, j, k;
                        unpack(c, level.nx, level.ny, i, j, k);
                        if ((i + j + k + colour) % 2 == 0)
                            relax(level, unsigned(c), i, j, k, x, b);
                    }
                __syncthreads();
            }
    if (inShared)
        for (std::size_t c = threadIdx.x; c < cells; c += blockDim.x)
            globalX[c] = x[c];
}

/// coarseB = half the sum over each coarse cell's fluid children of the fine residual b - A x, computed here (the
/// same floats as A x first, then the difference).
__global__ void restrictResidualKernel(LevelView fine, const float* __restrict__ b, const float* __restrict__ x, LevelView coarse,
                                       float* __restrict__ coarseB)
{
    int I, J, K;
    if (!threadNode(coarse.nx, coarse.ny, coarse.nz, I, J, K))
        return;
    float sum = 0.0f;
    for (int k = 2 * K; k < min(2 * K + 2, fine.nz); ++k)
        for (int j = 2 * J; j < min(2 * J + 2, fine.ny); ++j)
            for (int i = 2 * I; i < min(2 * I + 2, fine.nx); ++i)
            {
                const unsigned f = nodeIndex(i, j, k, fine.nx, fine.ny);
                const float residual = b[f] - applyAt(fine, f, i, j, k, x);
                if (fine.code[f])
                    sum += residual;
            }
    coarseB[nodeIndex(I, J, K, coarse.nx, coarse.ny)] = 0.5f * sum;
}

__global__ void prolongKernel(LevelView fine, float* __restrict__ x, LevelView coarse, const float* __restrict__ coarseX)
{
    int i, j, k;
    if (!threadNode(fine.nx, fine.ny, fine.nz, i, j, k))
        return;
    const unsigned c = nodeIndex(i, j, k, fine.nx, fine.ny);
    const float value = x[c], correction = coarseX[nodeIndex(i / 2, j / 2, k / 2, coarse.nx, coarse.ny)];
    if (fine.code[c])
        x[c] = value + correction;
}

__global__ void subtractKernel(LevelView level, float* x, float mean)
{
    const std::size_t c = blockIdx.x * std::size_t(blockDim.x) + threadIdx.x;
    if (c < level.cells() && level.code[c])
        x[c] -= mean;
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

void projectionRightSide(const GridView& g, const std::uint8_t* fluid, const float* sink, float* b, float* psi)
{
    const LatticeLaunch cells = launchOver(g.nx, g.ny, g.nz);
    rightSideKernel<<<cells.blocks, cells.threads>>>(g, fluid, sink, b, psi);
}

void correctVelocity(const GridView& g, const float* psi)
{
    const LatticeLaunch u = launchOver(latticeOf(g, 0)), v = launchOver(latticeOf(g, 1)), w = launchOver(latticeOf(g, 2));
    correctKernel<0><<<u.blocks, u.threads>>>(g, psi);
    correctKernel<1><<<v.blocks, v.threads>>>(g, psi);
    correctKernel<2><<<w.blocks, w.threads>>>(g, psi);
}

void divergenceLeft(const GridView& g, const float* sink, float* out)
{
    const LatticeLaunch cells = launchOver(g.nx, g.ny, g.nz);
    divergenceLeftKernel<<<cells.blocks, cells.threads>>>(g, sink, out);
}

void finestFlags(const GridView& g, std::uint8_t* fluid, std::uint8_t* ambient)
{
    finestFlagsKernel<<<blocksFor(g.cells()), kBlock>>>(g, fluid, ambient);
}

void coarsenFlags(int fx, int fy, int fz, const std::uint8_t* fineFluid, const std::uint8_t* fineAmbient, int cx, int cy,
                  int cz, std::uint8_t* fluid, std::uint8_t* ambient)
{
    const LatticeLaunch coarse = launchOver(cx, cy, cz);
    coarsenKernel<<<coarse.blocks, coarse.threads>>>(fx, fy, fz, fineFluid, fineAmbient, cx, cy, cz, fluid, ambient);
}

void levelCodes(int nx, int ny, int nz, const std::uint8_t* fluid, const std::uint8_t* ambient, const std::uint8_t open[6],
                std::uint8_t* code)
{
    OpenFaces faces;
    for (int f = 0; f < 6; ++f)
        faces.open[f] = open[f];
    const LatticeLaunch cells = launchOver(nx, ny, nz);
    codeKernel<<<cells.blocks, cells.threads>>>(nx, ny, nz, fluid, ambient, faces, code);
}

void residualOf(const LevelView& level, const float* b, const float* x, float* r)
{
    const LatticeLaunch cells = launchOver(level.nx, level.ny, level.nz);
    residualKernel<<<cells.blocks, cells.threads>>>(level, b, x, r);
}

void smoothLevel(const LevelView& level, float* x, const float* b, int colourFirst)
{
    const LatticeLaunch half = launchOver((level.nx + 1) / 2, level.ny, level.nz);
    smoothKernel<<<half.blocks, half.threads>>>(level, x, b, colourFirst);
    smoothKernel<<<half.blocks, half.threads>>>(level, x, b, (colourFirst + 1) % 2);
}

void smoothLevelFromZero(const LevelView& level, float* x, const float* b, int colourFirst)
{
    const LatticeLaunch cells = launchOver(level.nx, level.ny, level.nz);
    smoothFromZeroKernel<<<cells.blocks, cells.threads>>>(level, x, b, colourFirst);
    const LatticeLaunch half = launchOver((level.nx + 1) / 2, level.ny, level.nz);
    smoothKernel<<<half.blocks, half.threads>>>(level, x, b, (colourFirst + 1) % 2);
}

void solveCoarsest(const LevelView& level, float* x, const float* b, int sweeps)
{
    constexpr std::size_t kSharedBytes = 40 * 1024; // within the 48 KiB a block has without opting in
    const std::size_t bytes = level.cells() * (2 * sizeof(float) + 1);
    const bool inShared = bytes <= kSharedBytes;
    coarsestKernel<<<1, 1024, inShared ? bytes : 0>>>(level, x, b, sweeps, inShared);
}

void restrictResidual(const LevelView& fine, const float* b, const float* x, const LevelView& coarse, float* coarseB)
{
    const LatticeLaunch cells = launchOver(coarse.nx, coarse.ny, coarse.nz);
    restrictResidualKernel<<<cells.blocks, cells.threads>>>(fine, b, x, coarse, coarseB);
}

void prolongCorrection(const LevelView& fine, float* x, const LevelView& coarse, const float* coarseX)
{
    const LatticeLaunch cells = launchOver(fine.nx, fine.ny, fine.nz);
    prolongKernel<<<cells.blocks, cells.threads>>>(fine, x, coarse, coarseX);
}

void subtractOnFluid(const LevelView& level, float* x, float mean)
{
    subtractKernel<<<blocksFor(level.cells()), kBlock>>>(level, x, mean);
}

double updateSolution(std::size_t n, float alpha, const float* p, const float* q, float* psi, float* r, double* scratch)
{
    VSIM_CUDA_CHECK(cudaMemsetAsync(scratch, 0, sizeof(double)));
    updateSolutionKernel<<<reduceBlocks(n), kBlock>>>(n, alpha, p, q, psi, r, scratch);
    return fetchScalar(scratch);
}

std::size_t partialCount(int nx, int ny, int nz)
{
    const LatticeLaunch cells = launchOver(nx, ny, nz);
    return std::size_t(cells.blocks.x) * cells.blocks.y * cells.blocks.z;
}

double applyLevelDot(const LevelView& level, const float* x, float* y, double* partials, double* scratch)
{
    const LatticeLaunch cells = launchOver(level.nx, level.ny, level.nz);
    applyDotKernel<<<cells.blocks, cells.threads>>>(level, x, y, partials);
    return sumPartials(partials, unsigned(partialCount(level.nx, level.ny, level.nz)), scratch);
}

void updateDirection(std::size_t n, float beta, const float* z, float* p)
{
    directionKernel<<<blocksFor(n), kBlock>>>(n, beta, z, p);
}

} // namespace vsim::cuda::smoke
