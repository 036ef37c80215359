// The V-cycle's bottom on the device, each in one block with a barrier in place of a launch (the small levels'
// launches cost 2-3 us each, most of it the launch): the coarsest level's sweeps, and the level above it with the
// coarsest together (PoissonMultigrid.cpp's vcycle there, the same floats).

#include "MultigridDevice.cuh"
#include "SmokeKernels.cuh"

#include "vsim/cuda_common/CudaCheck.h"

namespace vsim::cuda::smoke {
namespace {

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

constexpr int kPlacedPerThread = 4;
constexpr int kOneBlockThreads = 1024; ///< the one-block kernels' largest block (coarsestKernel, bottomKernel)
constexpr std::size_t kBottomSharedBytes = 48 * 1024; // what a block has without opting in

/// The cells of an x-fastest level a block's thread takes (t, t + blockDim, ...), placed once.
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

std::size_t bottomBytes(const LevelView& upper, const LevelView& coarsest)
{
    return (upper.slots() + coarsest.slots()) * (2 * sizeof(float) + 1);
}

} // namespace

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

bool bottomFits(const LevelView& upper, const LevelView& coarsest)
{
    return !upper.byColour && !coarsest.byColour && upper.cells() <= std::size_t(kPlacedPerThread) * kOneBlockThreads &&
           coarsest.cells() <= std::size_t(kPlacedPerThread) * kOneBlockThreads && bottomBytes(upper, coarsest) <= kBottomSharedBytes;
}

void solveBottom(const LevelView& upper, const LevelView& coarsest, const float* rhs, float* x, int sweeps, int coarsestSweeps)
{
    bottomKernel<<<1, kOneBlockThreads, bottomBytes(upper, coarsest)>>>(upper, coarsest, rhs, x, sweeps, coarsestSweeps);
}

} // namespace vsim::cuda::smoke
