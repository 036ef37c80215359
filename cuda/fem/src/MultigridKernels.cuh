#pragma once

// The kernels of one smoothed-aggregation V-cycle (sim::fem::AggregationMultigrid's cycle and Chebyshev smoothing,
// DeviceMultigrid.cu records them). The finest level is the step's own matrix (DeviceModel, the free mask and the
// PCG's masked 3x3 inverse diagonal); the coarse levels are scalar compressed rows with block-Jacobi inverses of
// varying size (one block per aggregate). Every kernel returns at once when the PCG has stopped (cgActive).
//
// Chebyshev step k of the CPU's smooth() is split as: start (r = D^-1 b, d = r / centre, x = d), then per further
// degree: w = A d_in; r -= D^-1 w; d_out = c1 d_in + c2 r; x += d_out. The finest level fuses the product into
// the same kernel (a row's lanes hold the whole node after their shuffles); the coarse ones take the product from
// a separate csr kernel.

#include "FemKernels.cuh"

namespace vsim::cuda::fem {

/// Scalar compressed rows (int indices), on the device.
struct DeviceCsr
{
    int rows = 0;
    const int* start = nullptr;
    const int* columns = nullptr;
    const double* values = nullptr;
};

/// Block Jacobi of a coarse level: unknown i's block starts at unknown blockFirst[i] and has blockSize[i] unknowns;
/// row i of its inverse is at inverses[inverseRow[i]], blockSize[i] doubles.
struct DeviceBlockInverse
{
    int dofs = 0;
    const int* blockFirst = nullptr;
    const int* blockSize = nullptr;
    const int* inverseRow = nullptr;
    const double* inverses = nullptr;
};

/// The PCG's guard, passed to every kernel of the cycle.
struct CycleGuard
{
    const DeviceScalars* scalars = nullptr;
    double tolerance = 0.0;
    int maxIterations = 0;
};

// The finest level (3 unknowns per node; inverseDiagonal: 9 per node, masked).
__global__ void fineStartKernel(DeviceModel m, const double* inverseDiagonal, const double* b, double* r, double* d,
                                double* x, double inverseCentre, CycleGuard g);
__global__ void fineChebyshevKernel(DeviceModel m, const double* inverseDiagonal, const double* dIn, double* dOut,
                                    double* r, double* x, double c1, double c2, CycleGuard g);
__global__ void fineResidualKernel(DeviceModel m, const double* b, const double* x, double* out, CycleGuard g);
__global__ void fineRestartKernel(DeviceModel m, const double* inverseDiagonal, const double* b, const double* xIn,
                                  double* xOut, double* r, double* d, double inverseCentre, CycleGuard g);

// The coarse levels.
/// out = b - A x, or A x with b null (kCsrLanes threads a row).
__global__ void csrResidualKernel(DeviceCsr a, const double* b, const double* x, double* out, CycleGuard g);
/// out = P in, or out += P in with accumulate (kCsrLanes threads a row).
__global__ void csrProductKernel(DeviceCsr p, const double* in, double* out, bool accumulate, CycleGuard g);
__global__ void blockStartKernel(DeviceBlockInverse inverse, const double* b, double* r, double* d, double* x,
                                 double inverseCentre, CycleGuard g);
__global__ void blockChebyshevKernel(DeviceBlockInverse inverse, const double* w, double* r, const double* dIn,
                                     double* dOut, double* x, double c1, double c2, CycleGuard g);
/// r = D^-1 res, d = r / centre, xOut = xIn + d.
__global__ void blockRestartKernel(DeviceBlockInverse inverse, const double* res, double* r, double* d,
                                   const double* xIn, double* xOut, double inverseCentre, CycleGuard g);
/// out = M in, M dense row-major n x n (the coarsest level's inverse), a warp a row.
__global__ void denseProductKernel(int n, const double* matrix, const double* in, double* out, CycleGuard g);

/// Threads per row of the coarse products.
constexpr int kCsrLanes = 8;

} // namespace vsim::cuda::fem
