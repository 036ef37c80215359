#include "BlockRows.cuh"
#include "MultigridKernels.cuh"

namespace vsim::cuda::fem {
namespace {

__device__ inline bool active(const CycleGuard& g) { return cgActive(g.scalars, g.tolerance, g.maxIterations); }

/// out = inv (3x3 row-major) v.
__device__ inline void apply3(const double* inv, const double v[3], double out[3])
{
    for (int i = 0; i < 3; ++i)
        out[i] = inv[3 * i] * v[0] + inv[3 * i + 1] * v[1] + inv[3 * i + 2] * v[2];
}

/// The finest level's product S (A v) at the calling row group's node (kLanes threads a row): true, with the
/// node and the product, in lane 0 of a group whose node exists.
__device__ inline bool fineRowProduct(const DeviceModel& m, const double* v, int& node, double w[3])
{
    const int thread = int(blockIdx.x * blockDim.x + threadIdx.x), lane = thread % kLanes;
    node = thread / kLanes;
    rowProduct(m, v, node, lane, w);
    if (node >= m.nodes || lane != 0)
        return false;
    for (int i = 0; i < 3; ++i)
        w[i] *= m.freeMask[3 * node + i];
    return true;
}

/// Row `row` of `a` times `x` by kCsrLanes neighbouring threads; every lane gets the sum.
__device__ inline double csrRow(const DeviceCsr& a, const double* x, int row, int lane)
{
    double sum = 0.0;
    if (row < a.rows)
        for (int k = __ldg(a.start + row) + lane, end = __ldg(a.start + row + 1); k < end; k += kCsrLanes)
            sum += __ldg(a.values + k) * x[__ldg(a.columns + k)];
    for (int offset = kCsrLanes / 2; offset > 0; offset /= 2)
        sum += __shfl_xor_sync(0xffffffffu, sum, offset, kCsrLanes);
    return sum;
}

/// Row i of the block inverse times v.
__device__ inline double blockRow(const DeviceBlockInverse& inverse, const double* v, int i)
{
    const int first = __ldg(inverse.blockFirst + i), size = __ldg(inverse.blockSize + i);
    const double* row = inverse.inverses + __ldg(inverse.inverseRow + i);
    double sum = 0.0;
    for (int j = 0; j < size; ++j)
        sum += __ldg(row + j) * v[first + j];
    return sum;
}

} // namespace

__global__ void fineStartKernel(DeviceModel m, const double* inverseDiagonal, const double* b, double* r, double* d,
                                double* x, double inverseCentre, CycleGuard g)
{
    const int node = int(blockIdx.x * blockDim.x + threadIdx.x);
    if (!active(g) || node >= m.nodes)
        return;
    const double bn[3] = {b[3 * node], b[3 * node + 1], b[3 * node + 2]};
    double rn[3];
    apply3(inverseDiagonal + 9 * std::size_t(node), bn, rn);
    for (int i = 0; i < 3; ++i)
    {
        r[3 * node + i] = rn[i];
        d[3 * node + i] = x[3 * node + i] = rn[i] * inverseCentre;
    }
}

__global__ void fineChebyshevKernel(DeviceModel m, const double* inverseDiagonal, const double* dIn, double* dOut,
                                    double* r, double* x, double c1, double c2, CycleGuard g)
{
    int node;
    double w[3];
    if (!active(g) || !fineRowProduct(m, dIn, node, w))
        return;
    double scaled[3];
    apply3(inverseDiagonal + 9 * std::size_t(node), w, scaled);
    for (int i = 0; i < 3; ++i)
    {
        const std::size_t k = 3 * std::size_t(node) + std::size_t(i);
        const double rk = r[k] - scaled[i], dk = c1 * dIn[k] + c2 * rk;
        r[k] = rk;
        dOut[k] = dk;
        x[k] += dk;
    }
}

__global__ void fineResidualKernel(DeviceModel m, const double* b, const double* x, double* out, CycleGuard g)
{
    int node;
    double w[3];
    if (!active(g) || !fineRowProduct(m, x, node, w))
        return;
    for (int i = 0; i < 3; ++i)
        out[3 * node + i] = b[3 * node + i] - w[i];
}

__global__ void fineRestartKernel(DeviceModel m, const double* inverseDiagonal, const double* b, const double* xIn,
                                  double* xOut, double* r, double* d, double inverseCentre, CycleGuard g)
{
    int node;
    double w[3];
    if (!active(g) || !fineRowProduct(m, xIn, node, w))
        return;
    double residual[3], rn[3];
    for (int i = 0; i < 3; ++i)
        residual[i] = b[3 * node + i] - w[i];
    apply3(inverseDiagonal + 9 * std::size_t(node), residual, rn);
    for (int i = 0; i < 3; ++i)
    {
        const std::size_t k = 3 * std::size_t(node) + std::size_t(i);
        r[k] = rn[i];
        d[k] = rn[i] * inverseCentre;
        xOut[k] = xIn[k] + d[k];
    }
}

__global__ void csrResidualKernel(DeviceCsr a, const double* b, const double* x, double* out, CycleGuard g)
{
    if (!active(g))
        return;
    const int thread = int(blockIdx.x * blockDim.x + threadIdx.x), row = thread / kCsrLanes, lane = thread % kCsrLanes;
    const double sum = csrRow(a, x, row, lane);
    if (row < a.rows && lane == 0)
        out[row] = b ? b[row] - sum : sum;
}

__global__ void csrProductKernel(DeviceCsr p, const double* in, double* out, bool accumulate, CycleGuard g)
{
    if (!active(g))
        return;
    const int thread = int(blockIdx.x * blockDim.x + threadIdx.x), row = thread / kCsrLanes, lane = thread % kCsrLanes;
    const double sum = csrRow(p, in, row, lane);
    if (row < p.rows && lane == 0)
        out[row] = accumulate ? out[row] + sum : sum;
}

__global__ void blockStartKernel(DeviceBlockInverse inverse, const double* b, double* r, double* d, double* x,
                                 double inverseCentre, CycleGuard g)
{
    const int i = int(blockIdx.x * blockDim.x + threadIdx.x);
    if (!active(g) || i >= inverse.dofs)
        return;
    const double ri = blockRow(inverse, b, i);
    r[i] = ri;
    d[i] = x[i] = ri * inverseCentre;
}

__global__ void blockChebyshevKernel(DeviceBlockInverse inverse, const double* w, double* r, const double* dIn,
                                     double* dOut, double* x, double c1, double c2, CycleGuard g)
{
    const int i = int(blockIdx.x * blockDim.x + threadIdx.x);
    if (!active(g) || i >= inverse.dofs)
        return;
    const double ri = r[i] - blockRow(inverse, w, i), di = c1 * dIn[i] + c2 * ri;
    r[i] = ri;
    dOut[i] = di;
    x[i] += di;
}

__global__ void blockRestartKernel(DeviceBlockInverse inverse, const double* res, double* r, double* d,
                                   const double* xIn, double* xOut, double inverseCentre, CycleGuard g)
{
    const int i = int(blockIdx.x * blockDim.x + threadIdx.x);
    if (!active(g) || i >= inverse.dofs)
        return;
    const double ri = blockRow(inverse, res, i);
    r[i] = ri;
    d[i] = ri * inverseCentre;
    xOut[i] = xIn[i] + d[i];
}

__global__ void denseProductKernel(int n, const double* matrix, const double* in, double* out, CycleGuard g)
{
    if (!active(g))
        return;
    const int row = int(blockIdx.x * blockDim.x + threadIdx.x) / 32, lane = int(threadIdx.x % 32);
    double sum = 0.0;
    if (row < n)
        for (int j = lane; j < n; j += 32)
            sum += __ldg(matrix + std::size_t(row) * std::size_t(n) + j) * in[j];
    for (int offset = 16; offset > 0; offset /= 2)
        sum += __shfl_xor_sync(0xffffffffu, sum, offset);
    if (row < n && lane == 0)
        out[row] = sum;
}

} // namespace vsim::cuda::fem
