// PoissonMultigrid.cpp on the device: the levels' cell codes, the operator (A x, A p with p . q), the red-black
// smoother (the finest level by colour: SmokeKernels.cuh's LevelView), the coarsest level's solve in one block,
// the restriction of the residual and the prolongation of the correction.

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

/// x at cell c and its six neighbours (0 past the level's edge), loaded together: a thread's loads then wait on
/// memory once, not one after another.
struct Neighbourhood
{
    float centre, west, east, south, north, below, above;
};

__device__ Neighbourhood neighbourhood(const LevelView& level, unsigned c, int i, int j, int k, const float* __restrict__ x)
{
    // The neighbours' slots from c's, without level.slot's products: x fastest, they are c -+ 1, -+ a row, -+ a
    // slab; by colour they hold the other colour, whose slot of (i, j, k) is c -+ colourSlots, their x-neighbours
    // at (i -+ 1) / 2 of that row (each read only where it exists).
    unsigned west, east, row, slab, other;
    if (level.byColour)
    {
        const unsigned colourSlots = level.colourSlots(), t = unsigned(i >> 1);
        other = c >= colourSlots ? c - colourSlots : c + colourSlots;
        west = other - t + unsigned((i - 1) >> 1), east = other - t + unsigned((i + 1) >> 1);
        row = level.half(), slab = row * unsigned(level.ny);
    }
    else
    {
        other = c, west = c - 1, east = c + 1;
        row = unsigned(level.nx), slab = row * unsigned(level.ny);
    }
    return {x[c],
            i > 0 ? x[west] : 0.0f,
            i + 1 < level.nx ? x[east] : 0.0f,
            j > 0 ? x[other - row] : 0.0f,
            j + 1 < level.ny ? x[other + row] : 0.0f,
            k > 0 ? x[other - slab] : 0.0f,
            k + 1 < level.nz ? x[other + slab] : 0.0f};
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

/// sum / diagonal, rounded as the CPU's division. A zero sum (the quiet cells far from the flow, where b and x are
/// 0) is returned as it is: the division's range check sends a zero dividend down its slow path (about a hundred
/// instructions), which made the half pass issue-bound.
__device__ inline float quotient(float sum, int diagonal)
{
    const float dividend = sum == 0.0f ? 1.0f : sum;
    const float q = dividend / float(diagonal);
    return sum == 0.0f ? sum : q;
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
    x[c] = quotient(sum, diagonal);
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

/// smoothKernel on a level stored by colour (the finest): the layout's sizes come precomputed, and the
/// neighbours' slots follow from the thread's place. (The half pass is bound by instruction issue: 116
/// instructions a cell with quotient(), 137 before it.) Cell i = 2 t + shift of colour c sits at place t of its row in colour c's half; its
/// neighbours are of the other colour: (i -+ 1) at places t - 1 + shift and t + shift of the same row, (j -+ 1)
/// and (k -+ 1) at place t of the rows beside. The sum in relax's order, the same floats.
__global__ void smoothByColourKernel(LevelView level, unsigned half, unsigned colourSlots, float* __restrict__ x,
                                     const float* __restrict__ b, int colour)
{
    int t, j, k;
    if (!threadNode(int(half), level.ny, level.nz, t, j, k))
        return;
    const int shift = (j + k + colour) & 1, i = 2 * t + shift;
    if (i >= level.nx)
        return;
    const unsigned row = half, slab = half * unsigned(level.ny);
    const unsigned place = unsigned(t) + row * unsigned(j) + slab * unsigned(k);
    const unsigned c = (colour ? colourSlots : 0u) + place, o = (colour ? 0u : colourSlots) + place;
    const std::uint8_t code = level.code[c];
    const float rhs = b[c];
    const float west = i > 0 ? x[o - 1 + unsigned(shift)] : 0.0f;
    const float east = i + 1 < level.nx ? x[o + unsigned(shift)] : 0.0f;
    const float south = j > 0 ? x[o - row] : 0.0f, north = j + 1 < level.ny ? x[o + row] : 0.0f;
    const float below = k > 0 ? x[o - slab] : 0.0f, above = k + 1 < level.nz ? x[o + slab] : 0.0f;
    const int diagonal = diagonalOf(code);
    if (diagonal == 0)
        return;
    float sum = rhs;
    if (i > 0)
        sum += west;
    if (i + 1 < level.nx)
        sum += east;
    if (j > 0)
        sum += south;
    if (j + 1 < level.ny)
        sum += north;
    if (k > 0)
        sum += below;
    if (k + 1 < level.nz)
        sum += above;
    x[c] = quotient(sum, diagonal);
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

/// A cell of a level stored x fastest, as its thread keeps it over a block's sweeps: its slot, which of its six
/// neighbours lie inside the level (relax's order: west, east, south, north, below, above; their slots are the
/// cell's -+ 1, -+ nx, -+ nx ny), its colour and diagonal, and its right side, which the sweeps do not change. A
/// pass then costs its loads, the sum and the quotient.
struct PlacedCell
{
    unsigned slot = 0;
    unsigned flags = 0; ///< bits 0-5: neighbour inside; bit 6: colour; bits 8-10: diagonal
    float rhs = 0.0f;
    __device__ int colour() const { return int(flags >> 6) & 1; }
};

/// The six neighbours' slot offsets on an x-fastest level, in relax's order.
struct NeighbourOffsets
{
    int offset[6];
};

__device__ NeighbourOffsets offsetsOf(const LevelView& level)
{
    const int row = level.nx, slab = level.nx * level.ny;
    return {{-1, 1, -row, row, -slab, slab}};
}

__device__ PlacedCell placeCell(const LevelView& level, int i, int j, int k, const float* b)
{
    PlacedCell cell;
    cell.slot = level.slot(i, j, k);
    const bool inside[6] = {i > 0, i + 1 < level.nx, j > 0, j + 1 < level.ny, k > 0, k + 1 < level.nz};
#pragma unroll
    for (int f = 0; f < 6; ++f)
        cell.flags |= inside[f] ? 1u << f : 0u;
    cell.flags |= unsigned((i + j + k) & 1) << 6 | unsigned(diagonalOf(level.code[cell.slot])) << 8;
    cell.rhs = b[cell.slot];
    return cell;
}

/// relax() for a placed cell: the same sum in the same order, the same quotient.
__device__ void relaxPlaced(const PlacedCell& cell, const NeighbourOffsets& near, float* x)
{
    float value[6];
#pragma unroll
    for (int f = 0; f < 6; ++f)
        value[f] = (cell.flags >> f) & 1u ? x[int(cell.slot) + near.offset[f]] : 0.0f;
    const int diagonal = int(cell.flags >> 8) & 7;
    if (diagonal == 0)
        return;
    float sum = cell.rhs;
#pragma unroll
    for (int f = 0; f < 6; ++f)
        if ((cell.flags >> f) & 1u)
            sum += value[f];
    x[cell.slot] = quotient(sum, diagonal);
}

/// The cells of an x-fastest level a block's thread takes (t, t + blockDim, ...), placed once.
constexpr int kPlacedPerThread = 4;
constexpr int kOneBlockThreads = 1024; ///< the one-block kernels' largest block (coarsestKernel, bottomKernel)
struct ThreadPlacedCells
{
    PlacedCell cell[kPlacedPerThread];
    int count = 0;
};

__device__ void placeThreadCells(const LevelView& level, const float* b, ThreadPlacedCells& mine)
{
    const std::size_t cells = level.cells();
#pragma unroll
    for (int m = 0; m < kPlacedPerThread; ++m)
    {
        const std::size_t c = threadIdx.x + std::size_t(m) * blockDim.x;
        if (c < cells)
        {
            int i, j, k;
            unpack(c, level.nx, level.ny, i, j, k);
            mine.cell[m] = placeCell(level, i, j, k, b);
            mine.count = m + 1;
        }
    }
}

/// `sweeps` red-black pass pairs from `colourFirst` over the block's placed cells, a barrier after each pass.
__device__ void sweepPlaced(const ThreadPlacedCells& mine, const NeighbourOffsets& near, float* x, int sweeps, int colourFirst)
{
    for (int sweep = 0; sweep < sweeps; ++sweep)
        for (int pass = 0; pass < 2; ++pass)
        {
            const int colour = (colourFirst + pass) % 2;
#pragma unroll
            for (int m = 0; m < kPlacedPerThread; ++m)
                if (m < mine.count && mine.cell[m].colour() == colour)
                    relaxPlaced(mine.cell[m], near, x);
            __syncthreads();
        }
}

/// The coarsest level's sweeps in one block. With `inShared` the level (x, b, its codes: 9 bytes a cell) is
/// copied to shared memory first and x back at the end: each pass then waits on shared memory, not on global.
/// A level stored x fastest of no more than kPlacedPerThread cells a thread has its cells placed once
/// (PlacedCell).
__global__ void __launch_bounds__(kOneBlockThreads) coarsestKernel(LevelView global, float* globalX, const float* globalB, int sweeps, bool inShared)
{
    extern __shared__ float shared[];
    const std::size_t cells = global.cells(), slots = global.slots();
    LevelView level = global;
    float* x = globalX;
    const float* b = globalB;
    if (inShared)
    {
        float* sharedB = shared + slots;
        std::uint8_t* codes = reinterpret_cast<std::uint8_t*>(shared + 2 * slots);
        for (std::size_t c = threadIdx.x; c < slots; c += blockDim.x)
            sharedB[c] = globalB[c], codes[c] = global.code[c];
        x = shared, b = sharedB, level.code = codes;
    }
    for (std::size_t c = threadIdx.x; c < slots; c += blockDim.x)
        x[c] = 0.0f;
    __syncthreads(); // b and the codes in place
    if (!level.byColour && cells <= kPlacedPerThread * std::size_t(blockDim.x))
    {
        ThreadPlacedCells mine;
        placeThreadCells(level, b, mine);
        const NeighbourOffsets near = offsetsOf(level);
        __syncthreads();
        sweepPlaced(mine, near, x, sweeps, 0);
        sweepPlaced(mine, near, x, sweeps, 1);
    }
    else
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
                            relax(level, level.slot(i, j, k), i, j, k, x, b);
                    }
                    __syncthreads();
                }
    if (inShared)
        for (std::size_t c = threadIdx.x; c < slots; c += blockDim.x)
            globalX[c] = x[c];
}

/// Coarse cell (I, J, K)'s right side: half the sum over its fluid children of the fine residual b - A x (the
/// same floats as A x first, then the difference).
__device__ float restrictedAt(const LevelView& fine, const float* b, const float* x, int I, int J, int K)
{
    float sum = 0.0f;
    for (int k = 2 * K; k < min(2 * K + 2, fine.nz); ++k)
        for (int j = 2 * J; j < min(2 * J + 2, fine.ny); ++j)
            for (int i = 2 * I; i < min(2 * I + 2, fine.nx); ++i)
            {
                const unsigned f = fine.slot(i, j, k);
                const float residual = b[f] - applyAt(fine, f, i, j, k, x);
                if (fine.code[f])
                    sum += residual;
            }
    return 0.5f * sum;
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

/// The bottom of a V-cycle in one block: the level above the coarsest (`upper`, x fastest, at most
/// kPlacedPerThread cells a thread) and the coarsest, both in shared memory, with a barrier in place of each
/// launch (the small levels' launches cost 2-3 us each, most of it the launch). The same steps and floats as
/// vcycle() there: `sweeps` pass pairs from x = 0 from colour 0, the restriction, the coarsest's sweeps from 0
/// (`coarsestSweeps` pairs from colour 0, then from colour 1), the prolongation, `sweeps` pairs from colour 1.
__global__ void __launch_bounds__(kOneBlockThreads) bottomKernel(LevelView upper, LevelView coarsest, const float* __restrict__ rhs, float* __restrict__ globalX,
                             int sweeps, int coarsestSweeps)
{
    extern __shared__ float shared[];
    const std::size_t upperSlots = upper.slots(), coarseSlots = coarsest.slots();
    float *x = shared, *b = x + upperSlots, *coarseX = b + upperSlots, *coarseB = coarseX + coarseSlots;
    std::uint8_t* upperCode = reinterpret_cast<std::uint8_t*>(coarseB + coarseSlots);
    std::uint8_t* coarseCode = upperCode + upperSlots;
    for (std::size_t c = threadIdx.x; c < upperSlots; c += blockDim.x)
        x[c] = 0.0f, b[c] = rhs[c], upperCode[c] = upper.code[c];
    for (std::size_t c = threadIdx.x; c < coarseSlots; c += blockDim.x)
        coarseX[c] = 0.0f, coarseCode[c] = coarsest.code[c];
    LevelView up = upper, down = coarsest;
    up.code = upperCode, down.code = coarseCode;
    __syncthreads();
    ThreadPlacedCells mine;
    placeThreadCells(up, b, mine);
    const NeighbourOffsets upNear = offsetsOf(up), downNear = offsetsOf(down);
    sweepPlaced(mine, upNear, x, sweeps, 0); // from x = 0: smoothLevelFromZero's floats
    for (std::size_t c = threadIdx.x; c < down.cells(); c += blockDim.x)
    {
        int I, J, K;
        unpack(c, down.nx, down.ny, I, J, K);
        coarseB[down.slot(I, J, K)] = restrictedAt(up, b, x, I, J, K);
    }
    __syncthreads();
    ThreadPlacedCells coarseMine;
    placeThreadCells(down, coarseB, coarseMine);
    sweepPlaced(coarseMine, downNear, coarseX, coarsestSweeps, 0);
    sweepPlaced(coarseMine, downNear, coarseX, coarsestSweeps, 1);
    for (std::size_t c = threadIdx.x; c < up.cells(); c += blockDim.x)
    {
        int i, j, k;
        unpack(c, up.nx, up.ny, i, j, k);
        const unsigned f = up.slot(i, j, k);
        if (up.code[f])
            x[f] = x[f] + coarseX[down.slot(i / 2, j / 2, k / 2)];
    }
    __syncthreads();
    sweepPlaced(mine, upNear, x, sweeps, 1);
    for (std::size_t c = threadIdx.x; c < upperSlots; c += blockDim.x)
        globalX[c] = x[c];
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

namespace {

/// One half pass of `colour` over the level.
void smoothColour(const LevelView& level, float* x, const float* b, int colour)
{
    const LatticeLaunch half = launchOver((level.nx + 1) / 2, level.ny, level.nz);
    if (level.byColour)
        smoothByColourKernel<<<half.blocks, half.threads>>>(level, level.half(), level.colourSlots(), x, b, colour);
    else
        smoothKernel<<<half.blocks, half.threads>>>(level, x, b, colour);
}

} // namespace

void smoothLevel(const LevelView& level, float* x, const float* b, int colourFirst)
{
    smoothColour(level, x, b, colourFirst);
    smoothColour(level, x, b, (colourFirst + 1) % 2);
}

void smoothLevelFromZero(const LevelView& level, float* x, const float* b, int colourFirst)
{
    const LatticeLaunch cells = launchCells(level);
    smoothFromZeroKernel<<<cells.blocks, cells.threads>>>(level, x, b, colourFirst);
    smoothColour(level, x, b, (colourFirst + 1) % 2);
}

void solveCoarsest(const LevelView& level, float* x, const float* b, int sweeps)
{
    constexpr std::size_t kSharedBytes = 40 * 1024; // within the 48 KiB a block has without opting in
    const std::size_t bytes = level.slots() * (2 * sizeof(float) + 1);
    const bool inShared = bytes <= kSharedBytes;
    // Two cells a thread where the level allows (whole warps), else 1,024 threads (placed, or looping over the cells).
    const std::size_t pairs = (level.cells() + 1) / 2;
    const unsigned threads = pairs <= kOneBlockThreads ? unsigned((pairs + 31) / 32 * 32) : unsigned(kOneBlockThreads);
    coarsestKernel<<<1, threads, inShared ? bytes : 0>>>(level, x, b, sweeps, inShared);
}

namespace {

constexpr std::size_t kBottomSharedBytes = 48 * 1024; // what a block has without opting in

std::size_t bottomBytes(const LevelView& upper, const LevelView& coarsest)
{
    return (upper.slots() + coarsest.slots()) * (2 * sizeof(float) + 1);
}

} // namespace

bool bottomFits(const LevelView& upper, const LevelView& coarsest)
{
    return !upper.byColour && !coarsest.byColour && upper.cells() <= std::size_t(kPlacedPerThread) * kOneBlockThreads &&
           coarsest.cells() <= std::size_t(kPlacedPerThread) * kOneBlockThreads && bottomBytes(upper, coarsest) <= kBottomSharedBytes;
}

void solveBottom(const LevelView& upper, const LevelView& coarsest, const float* rhs, float* x, int sweeps, int coarsestSweeps)
{
    bottomKernel<<<1, kOneBlockThreads, bottomBytes(upper, coarsest)>>>(upper, coarsest, rhs, x, sweeps, coarsestSweeps);
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
