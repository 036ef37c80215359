#pragma once

// sim::fem::AggregationMultigrid on the GPU: its coarse levels uploaded as they were set up on the host, and one
// V-cycle recorded into a stream under capture (the PCG's graph), the same cycle as AggregationMultigrid::apply.

#include "vsim/cuda_common/DeviceBuffer.cuh"
#include "MultigridKernels.cuh"
#include "vsim/sim/fem/AggregationMultigrid.h"

#include <cuda_runtime.h>

#include <vector>

namespace vsim::cuda {

class DeviceMultigrid
{
public:
    explicit DeviceMultigrid(const sim::fem::AggregationMultigrid& host);

    /// Records z = V-cycle(r) on `stream`: the finest level is `model` with the PCG's masked inverse diagonal.
    void record(cudaStream_t stream, const fem::DeviceModel& model, const double* inverseDiagonal, const double* r,
                double* z, fem::CycleGuard guard) const;
    std::size_t bytes() const { return m_bytes; }

private:
    struct Csr
    {
        Buffer<int> start, columns;
        Buffer<double> values;
        fem::DeviceCsr view;
    };
    struct Level
    {
        int dofs = 0;
        double upper = 0.0, lower = 0.0; ///< the Chebyshev interval of D^-1 A
        Csr matrix, prolongation, restriction;
        Buffer<int> blockFirst, blockSize, inverseRow;
        Buffer<double> inverses;
        fem::DeviceBlockInverse inverse;
        Buffer<double> b, xA, xB, r, dA, dB, w; ///< work vectors (level 0: b unused, the PCG's r is the right side)
    };

    void cycle(cudaStream_t stream, std::size_t level, const fem::DeviceModel& model, const double* inverseDiagonal,
               const double* b, double* x, const fem::CycleGuard& guard) const;
    void upload(Csr& csr, const sim::fem::SparseRows& m);

    std::vector<Level> m_levels;
    Buffer<double> m_coarsestInverse;
    int m_degree = 2;
    std::size_t m_bytes = 0;
};

} // namespace vsim::cuda
