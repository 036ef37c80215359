// PressureProjection.cpp and PoissonMultigrid.cpp's operator, smoother and transfers on the device.

#include "BlockReduce.cuh"
#include "SmokeKernels.cuh"

#include "vsim/cuda_common/CudaCheck.h"

namespace vsim::cuda::smoke {
namespace {

/// Cell or face c's (i, j, k) on an nx x ny x ... lattice, in 32 bits (64-bit division costs many instructions;
/// the backend refuses grids of 2^31 cells or more).
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

/// False past the lattice's end.
template <int axis>
__device__ bool faceAt(const GridView& g, std::size_t f, FaceSite& site)
{
    const LatticeShape shape = latticeOf(g, axis);
    if (f >= nodes(shape))
        return false;
    unpack(f, shape.sx, shape.sy, site.i, site.j, site.k);
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
    const std::size_t f = blockIdx.x * std::size_t(blockDim.x) + threadIdx.x;
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
    const std::size_t high = highInside ? g.cell(i, j, k) : 0;
    const std::size_t low = lowInside ? g.cell(i - (axis == 0), j - (axis == 1), k - (axis == 2)) : 0;
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

__device__ float divergenceAt(const GridView& g, std::size_t c, int i, int j, int k, float inverse)
{
    const std::size_t ux = std::size_t(i) + std::size_t(g.nx + 1) * (j + std::size_t(g.ny) * k);
    const std::size_t vy = std::size_t(i) + std::size_t(g.nx) * (j + std::size_t(g.ny + 1) * k);
    return inverse * (g.u[ux + 1] - g.u[ux] + g.v[vy + std::size_t(g.nx)] - g.v[vy] + g.w[c + std::size_t(g.nx) * g.ny] - g.w[c]);
}

__global__ void rightSideKernel(GridView g, const std::uint8_t* fluid, const float* sink, float* b, float* psi)
{
    const std::size_t c = blockIdx.x * std::size_t(blockDim.x) + threadIdx.x;
    if (c >= g.cells())
        return;
    if (!fluid[c])
        psi[c] = 0.0f;
    int i, j, k;
    unpack(c, g.nx, g.ny, i, j, k);
    const float div = g.solid[c] ? 0.0f : divergenceAt(g, c, i, j, k, float(1.0 / g.h));
    b[c] = float(-g.h * g.h) * (div - (sink ? sink[c] : 0.0f));
}

__global__ void divergenceLeftKernel(GridView g, const float* sink, float* out)
{
    const std::size_t c = blockIdx.x * std::size_t(blockDim.x) + threadIdx.x;
    if (c >= g.cells())
        return;
    int i, j, k;
    unpack(c, g.nx, g.ny, i, j, k);
    const float div = g.solid[c] ? 0.0f : divergenceAt(g, c, i, j, k, float(1.0 / g.h));
    out[c] = fabsf(div - (sink ? sink[c] : 0.0f));
}

/// A side of a face: 1 fluid (psi of the cell), 2 ambient (psi 0: an open face, a vent), 0 a wall or a solid.
__device__ int sideOf(const GridView& g, std::size_t c)
{
    return g.solid[c] == kFluid ? 1 : g.solid[c] == kVent ? 2 : 0;
}

template <int axis>
__global__ void correctKernel(GridView g, const float* psi)
{
    const std::size_t f = blockIdx.x * std::size_t(blockDim.x) + threadIdx.x;
    FaceSite site;
    if (!faceAt<axis>(g, f, site))
        return;
    const int i = site.i, j = site.j, k = site.k, at = site.at, n = site.n;
    const std::size_t high = at < n ? g.cell(i, j, k) : 0;
    const std::size_t low = at > 0 ? g.cell(i - (axis == 0), j - (axis == 1), k - (axis == 2)) : 0;
    const int lowSide = at > 0 ? sideOf(g, low) : (g.open[2 * axis] ? 2 : 0);
    const int highSide = at < n ? sideOf(g, high) : (g.open[2 * axis + 1] ? 2 : 0);
    if ((lowSide == 1 && highSide != 0) || (highSide == 1 && lowSide != 0))
    {
        float* face = axis == 0 ? g.u : axis == 1 ? g.v : g.w;
        face[f] -= float(1.0 / g.h) * ((highSide == 1 ? psi[high] : 0.0f) - (lowSide == 1 ? psi[low] : 0.0f));
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
    const std::size_t c = blockIdx.x * std::size_t(blockDim.x) + threadIdx.x;
    if (c >= std::size_t(cx) * cy * cz)
        return;
    int I, J, K;
    unpack(c, cx, cy, I, J, K);
    bool anyFluid = false, anyAmbient = false;
    for (int k = 2 * K; k < min(2 * K + 2, fz); ++k)
        for (int j = 2 * J; j < min(2 * J + 2, fy); ++j)
            for (int i = 2 * I; i < min(2 * I + 2, fx); ++i)
            {
                const std::size_t child = std::size_t(i) + std::size_t(fx) * (j + std::size_t(fy) * k);
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

__global__ void diagonalKernel(int nx, int ny, int nz, const std::uint8_t* fluid, const std::uint8_t* ambient, OpenFaces faces,
                               std::uint8_t* diagonal)
{
    const std::size_t c = blockIdx.x * std::size_t(blockDim.x) + threadIdx.x;
    if (c >= std::size_t(nx) * ny * nz)
        return;
    if (!fluid[c])
    {
        diagonal[c] = 0;
        return;
    }
    int i, j, k;
    unpack(c, nx, ny, i, j, k);
    const int at[6][3] = {{i - 1, j, k}, {i + 1, j, k}, {i, j - 1, k}, {i, j + 1, k}, {i, j, k - 1}, {i, j, k + 1}};
    int count = 0;
    for (int f = 0; f < 6; ++f)
    {
        const int a = at[f][0], b = at[f][1], d = at[f][2];
        if (a < 0 || b < 0 || d < 0 || a >= nx || b >= ny || d >= nz)
            count += faces.open[f] ? 1 : 0;
        else
        {
            const std::size_t n = std::size_t(a) + std::size_t(nx) * (b + std::size_t(ny) * d);
            count += fluid[n] || ambient[n] ? 1 : 0;
        }
    }
    diagonal[c] = std::uint8_t(count);
}

/// (A x)_c, 0 outside the fluid.
__device__ float applyAt(const LevelView& level, std::size_t c, const float* x)
{
    if (!level.fluid[c])
        return 0.0f;
    int i, j, k;
    unpack(c, level.nx, level.ny, i, j, k);
    const std::size_t row = std::size_t(level.nx), slab = row * level.ny;
    float sum = float(level.diagonal[c]) * x[c];
    if (i > 0)
        sum -= x[c - 1];
    if (i + 1 < level.nx)
        sum -= x[c + 1];
    if (j > 0)
        sum -= x[c - row];
    if (j + 1 < level.ny)
        sum -= x[c + row];
    if (k > 0)
        sum -= x[c - slab];
    if (k + 1 < level.nz)
        sum -= x[c + slab];
    return sum;
}

__global__ void applyKernel(LevelView level, const float* x, float* y)
{
    const std::size_t c = blockIdx.x * std::size_t(blockDim.x) + threadIdx.x;
    if (c < level.cells())
        y[c] = applyAt(level, c, x);
}

/// y = A x and the sum of x . y (every thread reaches the block's sum).
__global__ void applyDotKernel(LevelView level, const float* x, float* y, double* out)
{
    const std::size_t c = blockIdx.x * std::size_t(blockDim.x) + threadIdx.x;
    double product = 0.0;
    if (c < level.cells())
    {
        const float value = applyAt(level, c, x);
        y[c] = value;
        product = double(x[c]) * double(value);
    }
    product = blockSum(product);
    if (threadIdx.x == 0)
        atomicAdd(out, product);
}

/// Gauss-Seidel at cell c (its neighbours of the other colour fixed).
__device__ void relax(const LevelView& level, std::size_t c, int i, int j, int k, float* x, const float* b)
{
    if (!level.fluid[c] || level.diagonal[c] == 0)
        return;
    const std::size_t row = std::size_t(level.nx), slab = row * level.ny;
    float sum = b[c];
    if (i > 0)
        sum += x[c - 1];
    if (i + 1 < level.nx)
        sum += x[c + 1];
    if (j > 0)
        sum += x[c - row];
    if (j + 1 < level.ny)
        sum += x[c + row];
    if (k > 0)
        sum += x[c - slab];
    if (k + 1 < level.nz)
        sum += x[c + slab];
    x[c] = sum / float(level.diagonal[c]);
}

/// The cells of one colour: i = 2 t + (j + k + colour) % 2.
__global__ void smoothKernel(LevelView level, float* x, const float* b, int colour)
{
    const unsigned half = unsigned(level.nx + 1) / 2, ny = unsigned(level.ny);
    const unsigned t = blockIdx.x * blockDim.x + threadIdx.x;
    if (t >= half * ny * unsigned(level.nz))
        return;
    const int j = int((t / half) % ny), k = int(t / (half * ny));
    const int i = 2 * int(t % half) + (j + k + colour) % 2;
    if (i >= level.nx)
        return;
    relax(level, std::size_t(i) + std::size_t(level.nx) * (j + std::size_t(level.ny) * k), i, j, k, x, b);
}

/// The coarsest level's sweeps in one block. With `inShared` the level (x, b, its flags: 10 bytes a cell) is
/// copied to shared memory first and x back at the end: each pass then waits on shared memory, not on global.
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
        std::uint8_t* flags = reinterpret_cast<std::uint8_t*>(shared + 2 * cells);
        for (std::size_t c = threadIdx.x; c < cells; c += blockDim.x)
            sharedB[c] = globalB[c], flags[c] = global.fluid[c], flags[cells + c] = global.diagonal[c];
        x = shared, b = sharedB, level.fluid = flags, level.diagonal = flags + cells;
    }
    for (std::size_t c = threadIdx.x; c < cells; c += blockDim.x)
        x[c] = 0.0f;
    __syncthreads();
    for (int first = 0; first < 2; ++first)
        for (int sweep = 0; sweep < sweeps; ++sweep)
            for (int pass = 0; pass < 2; ++pass)
            {
                const int colour = (first + pass) % 2;
                for (std::size_t c = threadIdx.x; c < cells; c += blockDim.x)
                {
                    int i, j, k;
                    unpack(c, level.nx, level.ny, i, j, k);
                    if ((i + j + k + colour) % 2 == 0)
                        relax(level, c, i, j, k, x, b);
                }
                __syncthreads();
            }
    if (inShared)
        for (std::size_t c = threadIdx.x; c < cells; c += blockDim.x)
            globalX[c] = x[c];
}

__global__ void restrictKernel(LevelView fine, const float* b, const float* r, LevelView coarse, float* coarseB)
{
    const std::size_t c = blockIdx.x * std::size_t(blockDim.x) + threadIdx.x;
    if (c >= coarse.cells())
        return;
    int I, J, K;
    unpack(c, coarse.nx, coarse.ny, I, J, K);
    float sum = 0.0f;
    for (int k = 2 * K; k < min(2 * K + 2, fine.nz); ++k)
        for (int j = 2 * J; j < min(2 * J + 2, fine.ny); ++j)
            for (int i = 2 * I; i < min(2 * I + 2, fine.nx); ++i)
            {
                const std::size_t f = std::size_t(i) + std::size_t(fine.nx) * (j + std::size_t(fine.ny) * k);
                if (fine.fluid[f])
                    sum += b[f] - r[f];
            }
    coarseB[c] = 0.5f * sum;
}

__global__ void prolongKernel(LevelView fine, float* x, LevelView coarse, const float* coarseX)
{
    const std::size_t c = blockIdx.x * std::size_t(blockDim.x) + threadIdx.x;
    if (c >= fine.cells() || !fine.fluid[c])
        return;
    int i, j, k;
    unpack(c, fine.nx, fine.ny, i, j, k);
    x[c] += coarseX[std::size_t(i / 2) + std::size_t(coarse.nx) * (j / 2 + std::size_t(coarse.ny) * (k / 2))];
}

__global__ void subtractKernel(LevelView level, float* x, float mean)
{
    const std::size_t c = blockIdx.x * std::size_t(blockDim.x) + threadIdx.x;
    if (c < level.cells() && level.fluid[c])
        x[c] -= mean;
}

__global__ void updateSolutionKernel(std::size_t n, float alpha, const float* p, const float* q, float* psi, float* r,
                                     double* out)
{
    const std::size_t c = blockIdx.x * std::size_t(blockDim.x) + threadIdx.x;
    double squared = 0.0;
    if (c < n)
    {
        psi[c] += alpha * p[c];
        const float next = r[c] - alpha * q[c];
        r[c] = next;
        squared = double(next) * double(next);
    }
    squared = blockSum(squared);
    if (threadIdx.x == 0)
        atomicAdd(out, squared);
}

__global__ void differenceKernel(std::size_t n, const float* b, const float* q, float* r)
{
    const std::size_t c = blockIdx.x * std::size_t(blockDim.x) + threadIdx.x;
    if (c < n)
        r[c] = b[c] - q[c];
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
    solidBoundaryKernel<0><<<blocksFor(nodes(latticeOf(g, 0))), kBlock>>>(g);
    solidBoundaryKernel<1><<<blocksFor(nodes(latticeOf(g, 1))), kBlock>>>(g);
    solidBoundaryKernel<2><<<blocksFor(nodes(latticeOf(g, 2))), kBlock>>>(g);
}

void projectionRightSide(const GridView& g, const std::uint8_t* fluid, const float* sink, float* b, float* psi)
{
    rightSideKernel<<<blocksFor(g.cells()), kBlock>>>(g, fluid, sink, b, psi);
}

void correctVelocity(const GridView& g, const float* psi)
{
    correctKernel<0><<<blocksFor(nodes(latticeOf(g, 0))), kBlock>>>(g, psi);
    correctKernel<1><<<blocksFor(nodes(latticeOf(g, 1))), kBlock>>>(g, psi);
    correctKernel<2><<<blocksFor(nodes(latticeOf(g, 2))), kBlock>>>(g, psi);
}

void divergenceLeft(const GridView& g, const float* sink, float* out)
{
    divergenceLeftKernel<<<blocksFor(g.cells()), kBlock>>>(g, sink, out);
}

void finestFlags(const GridView& g, std::uint8_t* fluid, std::uint8_t* ambient)
{
    finestFlagsKernel<<<blocksFor(g.cells()), kBlock>>>(g, fluid, ambient);
}

void coarsenFlags(int fx, int fy, int fz, const std::uint8_t* fineFluid, const std::uint8_t* fineAmbient, int cx, int cy,
                  int cz, std::uint8_t* fluid, std::uint8_t* ambient)
{
    coarsenKernel<<<blocksFor(std::size_t(cx) * cy * cz), kBlock>>>(fx, fy, fz, fineFluid, fineAmbient, cx, cy, cz, fluid, ambient);
}

void levelDiagonal(int nx, int ny, int nz, const std::uint8_t* fluid, const std::uint8_t* ambient, const std::uint8_t open[6],
                   std::uint8_t* diagonal)
{
    OpenFaces faces;
    for (int f = 0; f < 6; ++f)
        faces.open[f] = open[f];
    diagonalKernel<<<blocksFor(std::size_t(nx) * ny * nz), kBlock>>>(nx, ny, nz, fluid, ambient, faces, diagonal);
}

void applyLevel(const LevelView& level, const float* x, float* y)
{
    applyKernel<<<blocksFor(level.cells()), kBlock>>>(level, x, y);
}

void smoothLevel(const LevelView& level, float* x, const float* b, int colourFirst)
{
    const unsigned blocks = blocksFor(std::size_t((level.nx + 1) / 2) * level.ny * level.nz);
    smoothKernel<<<blocks, kBlock>>>(level, x, b, colourFirst);
    smoothKernel<<<blocks, kBlock>>>(level, x, b, (colourFirst + 1) % 2);
}

void solveCoarsest(const LevelView& level, float* x, const float* b, int sweeps)
{
    constexpr std::size_t kSharedBytes = 40 * 1024; // within the 48 KiB a block has without opting in
    const std::size_t bytes = level.cells() * (2 * sizeof(float) + 2);
    const bool inShared = bytes <= kSharedBytes;
    coarsestKernel<<<1, 1024, inShared ? bytes : 0>>>(level, x, b, sweeps, inShared);
}

void restrictResidual(const LevelView& fine, const float* b, const float* r, const LevelView& coarse, float* coarseB)
{
    restrictKernel<<<blocksFor(coarse.cells()), kBlock>>>(fine, b, r, coarse, coarseB);
}

void prolongCorrection(const LevelView& fine, float* x, const LevelView& coarse, const float* coarseX)
{
    prolongKernel<<<blocksFor(fine.cells()), kBlock>>>(fine, x, coarse, coarseX);
}

void subtractOnFluid(const LevelView& level, float* x, float mean)
{
    subtractKernel<<<blocksFor(level.cells()), kBlock>>>(level, x, mean);
}

double updateSolution(std::size_t n, float alpha, const float* p, const float* q, float* psi, float* r, double* scratch)
{
    VSIM_CUDA_CHECK(cudaMemsetAsync(scratch, 0, sizeof(double)));
    updateSolutionKernel<<<blocksFor(n), kBlock>>>(n, alpha, p, q, psi, r, scratch);
    return fetchScalar(scratch);
}

double applyLevelDot(const LevelView& level, const float* x, float* y, double* scratch)
{
    VSIM_CUDA_CHECK(cudaMemsetAsync(scratch, 0, sizeof(double)));
    applyDotKernel<<<blocksFor(level.cells()), kBlock>>>(level, x, y, scratch);
    return fetchScalar(scratch);
}

void difference(std::size_t n, const float* b, const float* q, float* r)
{
    differenceKernel<<<blocksFor(n), kBlock>>>(n, b, q, r);
}

void updateDirection(std::size_t n, float beta, const float* z, float* p)
{
    directionKernel<<<blocksFor(n), kBlock>>>(n, beta, z, p);
}

} // namespace vsim::cuda::smoke
