#pragma once

// The multigrid's device functions that its kernels share (MultigridKernels.cu, OneBlockKernels.cu): a cell's
// place from its index, its neighbourhood, A x at a cell, the Gauss-Seidel relaxation and the restricted residual,
// in the CPU's order of operations (PoissonMultigrid.cpp). Include only from .cu files.

#include "SmokeKernels.cuh"

namespace vsim::cuda::smoke {

/// Cell c's (i, j, k) on an nx x ny x ... lattice, in 32 bits (the coarsest level's loop in one block; the other
/// kernels take their node from launchOver's threads, without dividing).
__device__ inline void unpack(std::size_t c, int nx, int ny, int& i, int& j, int& k)
{
    const unsigned u = unsigned(c), x = unsigned(nx), y = unsigned(ny);
    i = int(u % x), j = int((u / x) % y), k = int(u / (x * y));
}

/// x at cell c and its six neighbours (0 past the level's edge), loaded together: a thread's loads then wait on
/// memory once, not one after another.
struct Neighbourhood
{
    float centre, west, east, south, north, below, above;
};

__device__ inline Neighbourhood neighbourhood(const LevelView& level, unsigned c, int i, int j, int k, const float* __restrict__ x)
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
__device__ inline float applyAt(const LevelView& level, unsigned c, int i, int j, int k, const float* __restrict__ x)
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
__device__ inline void relax(const LevelView& level, unsigned c, int i, int j, int k, float* __restrict__ x, const float* __restrict__ b)
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

/// Coarse cell (I, J, K)'s right side: half the sum over its fluid children of the fine residual b - A x (the
/// same floats as A x first, then the difference).
__device__ inline float restrictedAt(const LevelView& fine, const float* b, const float* x, int I, int J, int K)
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

} // namespace vsim::cuda::smoke
