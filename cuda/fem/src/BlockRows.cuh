#pragma once

// The symmetric block-row storage's reads (FemKernels.cuh, DeviceModel), shared by the PCG and multigrid kernels.

#include "FemKernels.cuh"

namespace vsim::cuda::fem {

constexpr int kLanes = kRowLanes; // rows hold about 15 blocks

/// Stored block `block` of the matrix, row-major.
__device__ inline void loadBlock(const double* matrix, std::size_t block, double b[9])
{
    for (int k = 0; k < 9; ++k)
        b[k] = __ldg(matrix + kBlockStride * block + k);
}

__device__ inline void storeBlock(double* matrix, std::size_t block, const double b[9])
{
    for (int k = 0; k < 9; ++k)
        matrix[kBlockStride * block + k] = b[k];
}

/// How many passes over the rows a grid-stride kernel makes (the same in every thread, so that the shuffles of a
/// row group always find all their lanes).
__device__ inline int rowPasses(int rows, int rowsPerGrid) { return (rows + rowsPerGrid - 1) / rowsPerGrid; }

/// Row `node` of the matrix times `v`, computed by kLanes neighbouring threads and summed with shuffles: every
/// lane of the group returns the sum. The row's blocks are numbered lower (read transposed from the rows above),
/// then stored (diagonal and upper); lane l takes every kLanes-th from l. Lanes past the end contribute zeros.
__device__ inline void rowProduct(const DeviceModel& m, const double* v, int node, int lane, double out[3])
{
    out[0] = out[1] = out[2] = 0.0;
    if (node < m.nodes)
    {
        const std::uint32_t lowerBegin = m.lowerRowStart[node], lowerCount = m.lowerRowStart[node + 1] - lowerBegin;
        const std::uint32_t storedBegin = m.rowStart[node], storedCount = m.rowStart[node + 1] - storedBegin;
        for (std::uint32_t k = std::uint32_t(lane); k < lowerCount + storedCount; k += kLanes)
        {
            const bool transposed = k < lowerCount;
            const std::uint32_t block = transposed ? __ldg(m.lowerSlots + lowerBegin + k) : storedBegin + k - lowerCount;
            const std::uint32_t column = transposed ? __ldg(m.lowerColumns + lowerBegin + k) : __ldg(m.columns + block);
            const double* x = v + 3 * std::size_t(column);
            double b[9];
            loadBlock(m.matrix, block, b); // read-only during the sweep
            const double x0 = x[0], x1 = x[1], x2 = x[2];
            if (transposed)
            {
                out[0] += b[0] * x0 + b[3] * x1 + b[6] * x2;
                out[1] += b[1] * x0 + b[4] * x1 + b[7] * x2;
                out[2] += b[2] * x0 + b[5] * x1 + b[8] * x2;
            }
            else
            {
                out[0] += b[0] * x0 + b[1] * x1 + b[2] * x2;
                out[1] += b[3] * x0 + b[4] * x1 + b[5] * x2;
                out[2] += b[6] * x0 + b[7] * x1 + b[8] * x2;
            }
        }
    }
    for (int offset = kLanes / 2; offset > 0; offset /= 2)
        for (int i = 0; i < 3; ++i)
            out[i] += __shfl_xor_sync(0xffffffffu, out[i], offset, kLanes);
}

/// Whether the PCG is still iterating (the guard of every kernel inside its loop; the scalars only change between
/// kernels, so the whole grid agrees).
__device__ inline bool cgActive(const DeviceScalars* s, double tolerance, int maxIterations)
{
    return !s->done && s->residual > tolerance && s->iterations < maxIterations;
}

} // namespace vsim::cuda::fem
