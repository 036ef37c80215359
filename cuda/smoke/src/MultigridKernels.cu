// PoissonMultigrid.cpp on the device: the levels' cell codes, the operator (A x, A p with p . q), the red-black
// smoother (the finest level by colour: SmokeKernels.cuh's LevelView), the restriction of the residual and the
// prolongation of the correction. The V-cycle's bottom in one block: OneBlockKernels.cu.

#include "BlockReduce.cuh"
#include "MultigridDevice.cuh"
#include "SmokeKernels.cuh"

#include "vsim/cuda_common/CudaCheck.h"

namespace vsim::cuda::smoke {
namespace {

__global__ void finestFlagsKernel(GridView g, LevelView finest, std::uint8_t* fluid, std::uint8_t* ambient)
{
    int i, j, k;
    if (!threadNode(g.nx, g.ny, g.nz, i, j, k))
        return;
    const std::uint8_t kind = g.solid[nodeIndex(i, j, k, g.nx, g.ny)];
    const unsigned s = finest.slot(i, j, k);
    fluid[s] = kind == kFluid, ambient[s] = kind == kVent;
}

__global__ void coarsenKernel(LevelView fine, const std::uint8_t* fineFluid, const std::uint8_t* fineAmbient, LevelView coarse,
                              std::uint8_t* fluid, std::uint8_t* ambient)
{
    int I, J, K;
    if (!threadNode(coarse.nx, coarse.ny, coarse.nz, I, J, K))
        return;
    const unsigned c = coarse.slot(I, J, K);
    bool anyFluid = false, anyAmbient = false;
    for (int k = 2 * K; k < min(2 * K + 2, fine.nz); ++k)
        for (int j = 2 * J; j < min(2 * J + 2, fine.ny); ++j)
            for (int i = 2 * I; i < min(2 * I + 2, fine.nx); ++i)
            {
                const unsigned child = fine.slot(i, j, k);
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

__global__ void codeKernel(LevelView level, const std::uint8_t* fluid, const std::uint8_t* ambient, OpenFaces faces,
                           std::uint8_t* code)
{
    const int nx = level.nx, ny = level.ny, nz = level.nz;
    int i, j, k;
    if (!threadNode(nx, ny, nz, i, j, k))
        return;
    const unsigned c = level.slot(i, j, k);
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
            const unsigned n = level.slot(a, b, d);
            count += fluid[n] || ambient[n] ? 1 : 0;
        }
    }
    code[c] = std::uint8_t(kFluidCode | count);
}

/// The cells one thread of launchCells(level) takes: x fastest, one; by colour, the red and the black cell at
/// place t of their rows (i = 2t and 2t + 1), so that a warp reads and writes runs of each colour's slots and a
/// thread has two cells' loads in flight. Each kernel below computes its cells' values first and stores them after.
struct ThreadCells
{
    int count = 0, j = 0, k = 0;
    int i[2] = {0, 0};
    unsigned slot[2] = {0, 0};
};

__device__ bool threadCells(const LevelView& level, ThreadCells& cells)
{
    if (!level.byColour)
    {
        if (!threadNode(level.nx, level.ny, level.nz, cells.i[0], cells.j, cells.k))
            return false;
        cells.count = 1, cells.slot[0] = level.slot(cells.i[0], cells.j, cells.k);
        return true;
    }
    int t;
    if (!threadNode(int(level.half()), level.ny, level.nz, t, cells.j, cells.k))
        return false;
    const unsigned place = unsigned(t) + level.half() * (unsigned(cells.j) + unsigned(level.ny) * unsigned(cells.k));
#pragma unroll
    for (int colour = 0; colour < 2; ++colour)
    {
        const int i = 2 * t + ((cells.j + cells.k + colour) & 1);
        if (i < level.nx)
            cells.i[cells.count] = i, cells.slot[cells.count] = unsigned(colour) * level.colourSlots() + place, ++cells.count;
    }
    return true;
}

/// The launch for ThreadCells: over the level's cells, or by colour over (half, ny, nz), two cells a thread.
LatticeLaunch launchCells(const LevelView& level)
{
    return level.byColour ? launchOver(int(level.half()), level.ny, level.nz) : launchOver(level.nx, level.ny, level.nz);
}

/// r = b - A x (the same floats as A x first, then the difference).
__global__ void residualKernel(LevelView level, const float* __restrict__ b, const float* __restrict__ x, float* __restrict__ r)
{
    ThreadCells cells;
    if (!threadCells(level, cells))
        return;
    float value[2];
#pragma unroll
    for (int n = 0; n < 2; ++n)
        if (n < cells.count)
            value[n] = b[cells.slot[n]] - applyAt(level, cells.slot[n], cells.i[n], cells.j, cells.k, x);
#pragma unroll
    for (int n = 0; n < 2; ++n)
        if (n < cells.count)
            r[cells.slot[n]] = value[n];
}

/// y = A x, and each block's sum of x . y in partials[its place] (every thread reaches the block's sum).
__global__ void applyDotKernel(LevelView level, const float* __restrict__ x, float* __restrict__ y, double* partials)
{
    ThreadCells cells;
    double product = 0.0;
    if (threadCells(level, cells))
    {
        float value[2], own[2];
#pragma unroll
        for (int n = 0; n < 2; ++n)
            if (n < cells.count)
                value[n] = applyAt(level, cells.slot[n], cells.i[n], cells.j, cells.k, x), own[n] = x[cells.slot[n]];
#pragma unroll
        for (int n = 0; n < 2; ++n)
            if (n < cells.count)
                y[cells.slot[n]] = value[n], product += double(own[n]) * double(value[n]);
    }
    product = blockSum(product);
    if (threadInBlock() == 0)
        partials[blockInGrid()] = product;
}

/// The cells of one colour, launched over ((nx + 1) / 2, ny, nz): i = 2 t + (j + k + colour) % 2.
__global__ void smoothKernel(LevelView level, float* __restrict__ x, const float* __restrict__ b, int colour)
{
    int t, j, k;
    if (!threadNode((level.nx + 1) / 2, level.ny, level.nz, t, j, k))
        return;
    const int i = 2 * t + (j + k + colour) % 2;
    if (i < level.nx)
        relax(level, level.slot(i, j, k), i, j, k, x, b);
}

/// The first pass of colour `colour` from x = 0, over every cell: a relaxed cell of that colour has no neighbour
/// of its colour, so its value is b / diagonal (relax's sum of b and six zeros, the same float); every other cell
/// takes 0. It stands for zeroing x and that pass (one write of x, no read of it).
__global__ void smoothFromZeroKernel(LevelView level, float* __restrict__ x, const float* __restrict__ b, int colour)
{
    ThreadCells cells;
    if (!threadCells(level, cells))
        return;
    float value[2];
#pragma unroll
    for (int n = 0; n < 2; ++n)
        if (n < cells.count)
        {
            const int diagonal = diagonalOf(level.code[cells.slot[n]]);
            const float rhs = b[cells.slot[n]];
            value[n] = (cells.i[n] + cells.j + cells.k + colour) % 2 == 0 && diagonal != 0 ? quotient(rhs + 0.0f, diagonal)
                                                                                          : 0.0f;
        }
#pragma unroll
    for (int n = 0; n < 2; ++n)
        if (n < cells.count)
            x[cells.slot[n]] = value[n];
}

/// coarseB = half the sum over each coarse cell's fluid children of the fine residual b - A x, computed here (the
/// same floats as A x first, then the difference).
__global__ void restrictResidualKernel(LevelView fine, const float* __restrict__ b, const float* __restrict__ x, LevelView coarse,
                                       float* __restrict__ coarseB)
{
    int I, J, K;
    if (!threadNode(coarse.nx, coarse.ny, coarse.nz, I, J, K))
        return;
    coarseB[coarse.slot(I, J, K)] = restrictedAt(fine, b, x, I, J, K);
}

__global__ void prolongKernel(LevelView fine, float* __restrict__ x, LevelView coarse, const float* __restrict__ coarseX)
{
    ThreadCells cells;
    if (!threadCells(fine, cells))
        return;
    float value[2];
    bool fluid[2];
#pragma unroll
    for (int n = 0; n < 2; ++n)
        if (n < cells.count)
        {
            const unsigned c = cells.slot[n];
            value[n] = x[c] + coarseX[coarse.slot(cells.i[n] / 2, cells.j / 2, cells.k / 2)];
            fluid[n] = fine.code[c] != 0;
        }
#pragma unroll
    for (int n = 0; n < 2; ++n)
        if (n < cells.count && fluid[n])
            x[cells.slot[n]] = value[n];
}

__global__ void subtractKernel(LevelView level, float* x, float mean)
{
    const std::size_t c = blockIdx.x * std::size_t(blockDim.x) + threadIdx.x;
    if (c < level.slots() && level.code[c])
        x[c] -= mean;
}

} // namespace

void finestFlags(const GridView& g, const LevelView& finest, std::uint8_t* fluid, std::uint8_t* ambient)
{
    const LatticeLaunch cells = launchOver(g.nx, g.ny, g.nz);
    finestFlagsKernel<<<cells.blocks, cells.threads>>>(g, finest, fluid, ambient);
}

void coarsenFlags(const LevelView& fine, const std::uint8_t* fineFluid, const std::uint8_t* fineAmbient,
                  const LevelView& coarse, std::uint8_t* fluid, std::uint8_t* ambient)
{
    const LatticeLaunch cells = launchOver(coarse.nx, coarse.ny, coarse.nz);
    coarsenKernel<<<cells.blocks, cells.threads>>>(fine, fineFluid, fineAmbient, coarse, fluid, ambient);
}

void levelCodes(const LevelView& level, const std::uint8_t* fluid, const std::uint8_t* ambient, const std::uint8_t open[6],
                std::uint8_t* code)
{
    OpenFaces faces;
    for (int f = 0; f < 6; ++f)
        faces.open[f] = open[f];
    const LatticeLaunch cells = launchOver(level.nx, level.ny, level.nz);
    codeKernel<<<cells.blocks, cells.threads>>>(level, fluid, ambient, faces, code);
}

void residualOf(const LevelView& level, const float* b, const float* x, float* r)
{
    const LatticeLaunch cells = launchCells(level);
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
    const LatticeLaunch cells = launchCells(level);
    smoothFromZeroKernel<<<cells.blocks, cells.threads>>>(level, x, b, colourFirst);
    const LatticeLaunch half = launchOver((level.nx + 1) / 2, level.ny, level.nz);
    smoothKernel<<<half.blocks, half.threads>>>(level, x, b, (colourFirst + 1) % 2);
}

void restrictResidual(const LevelView& fine, const float* b, const float* x, const LevelView& coarse, float* coarseB)
{
    const LatticeLaunch cells = launchOver(coarse.nx, coarse.ny, coarse.nz);
    restrictResidualKernel<<<cells.blocks, cells.threads>>>(fine, b, x, coarse, coarseB);
}

void prolongCorrection(const LevelView& fine, float* x, const LevelView& coarse, const float* coarseX)
{
    const LatticeLaunch cells = launchCells(fine);
    prolongKernel<<<cells.blocks, cells.threads>>>(fine, x, coarse, coarseX);
}

void subtractOnFluid(const LevelView& level, float* x, float mean)
{
    subtractKernel<<<blocksFor(level.slots()), kBlock>>>(level, x, mean);
}

std::size_t partialCount(const LevelView& level)
{
    const LatticeLaunch cells = launchCells(level);
    return std::size_t(cells.blocks.x) * cells.blocks.y * cells.blocks.z;
}

double applyLevelDot(const LevelView& level, const float* x, float* y, double* partials, double* scratch)
{
    const LatticeLaunch cells = launchCells(level);
    applyDotKernel<<<cells.blocks, cells.threads>>>(level, x, y, partials);
    return sumPartials(partials, unsigned(partialCount(level)), scratch);
}

} // namespace vsim::cuda::smoke
