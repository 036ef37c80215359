#pragma once

// The kernels of one implicit step (CudaBackwardEuler.cu records them into a CUDA graph). Each mirrors a loop of
// the CPU path: elementKernel = CorotationalFem::updateElements, assembleKernel = CorotationalFem::assemble,
// forceKernel = CorotationalFem::elasticForces, the PCG kernels = solveConjugateGradient's three sweeps, with the
// scalar work done by the last block to finish (no extra launches) and a device flag that ends the iterations.

#include <cstdint>

namespace vsim::cuda::fem {

/// Storage of the assembled matrix and of the element blocks it is gathered from. Single precision was tried
/// (half the PCG's memory traffic): 1M tets went from 21.5 to 18.5 ms a step on the H100 but the positions left
/// the CPU path's by 1e-4..7e-4 after 100 steps, over the 1e-5 parity bound, so the matrix stays double.
using MatrixReal = double;

/// Device pointers and sizes of one model (all double precision, 3 entries per node where per dof).
struct DeviceModel
{
    int nodes = 0, elements = 0, blocks = 0, faces = 0;
    const int* tets = nullptr;              // 4 per element
    const double* rest = nullptr;           // X, 3 per node
    const double* restEdgesInverse = nullptr; // 9 per element, row-major
    const double* stiffness = nullptr;      // 144 per element, row-major, entry-major: entry c of element e at c * elements + e
    const double* mass = nullptr;           // 3 per node (lumped, per component)
    const double* freeMask = nullptr;       // 3 per node: 1 free, 0 constrained
    const int* faces3 = nullptr;            // 3 per pressure face
    double* quaternions = nullptr;          // 4 per element (w, x, y, z)
    double* elementForces = nullptr;        // 12 per element, entry-major (entry j of element e at j * elements + e)
    MatrixReal* elementBlocks = nullptr;        // 90 per element, entry-major: diagonal blocks 0-3, then (0,1) (0,2) (0,3) (1,2) (1,3) (2,3)
    const std::uint32_t* rowStart = nullptr;
    const std::uint32_t* columns = nullptr;
    const std::uint32_t* diagonalSlot = nullptr;
    MatrixReal* matrix = nullptr;               // 9 per block, row-major, component-major: entry j of block s at j * blocks + s
    const std::uint32_t* blockEntryStart = nullptr;
    const std::uint32_t* blockEntries = nullptr; // 16 * element + 4 * a + b
    const std::uint32_t* nodeEntryStart = nullptr;
    const std::uint32_t* nodeEntries = nullptr;  // 4 * element + a
};

/// Scalars of the step and of the PCG, kept on the device.
struct DeviceScalars
{
    double pressure;
    double bb, rr, rz, pq, rzNext, reference, alpha, beta, residual;
    int done, iterations, inverted;
    unsigned int blocksDone; // the last-block-done counter of the current sweep
};

__global__ void resetKernel(DeviceScalars* s);
__global__ void elementKernel(DeviceModel m, const double* x, DeviceScalars* s);
__global__ void assembleKernel(DeviceModel m, double massFactor, double stiffnessFactor);
__global__ void addMassKernel(DeviceModel m, double massFactor);
__global__ void forceKernel(DeviceModel m, double* force);
__global__ void pressureKernel(DeviceModel m, const double* x, const DeviceScalars* s, double* external);
__global__ void productKernel(DeviceModel m, const double* in, double* out);
__global__ void rightHandSideKernel(DeviceModel m, const double* force, const double* external, const double* v,
                                    const double* av, double h, double alpha, double beta, double massFactor,
                                    double stiffnessFactor, double* rhs, double* dv);
__global__ void cgInitKernel(DeviceModel m, const double* b, const double* x, double* inverseDiagonal, double* r,
                             double* z, double* p, double* q, DeviceScalars* s);
__global__ void cgDirectionKernel(DeviceModel m, const double* z, double* p, double* q, DeviceScalars* s,
                                  double tolerance, int maxIterations);
__global__ void cgUpdateKernel(DeviceModel m, const double* inverseDiagonal, double* x, double* r, double* z,
                               const double* p, const double* q, DeviceScalars* s, double tolerance, int maxIterations);
/// Threads per matrix row in productKernel, cgInitKernel and cgDirectionKernel (launch nodes * this many).
/// (8 measured best on the H100: 16 lanes took 30.1 ms a step at 1M tets, 8 lanes 21.5 ms.)
constexpr int kRowLanes = 8;
__global__ void finishKernel(int count, const double* dv, double h, double* v, double* x);

} // namespace vsim::cuda::fem
