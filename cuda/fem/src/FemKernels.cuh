#pragma once

// The kernels of one implicit step (CudaBackwardEuler.cu records them into a CUDA graph). Each mirrors a loop of
// the CPU path: elementKernel = CorotationalFem::updateElements (rotation and force), assembleKernel and
// diagonalKernel = CorotationalFem::assemble, forceKernel = CorotationalFem::elasticForces, the PCG kernels =
// solveConjugateGradient's two fused sweeps, with the scalar work done by the last block to finish (no extra
// launches) and a device flag that ends the iterations. The arithmetic is the CPU's up to rounding: the element
// stiffness is formed from the shape-function gradients where it is used instead of being read (K_e = V B^T D B
// written out), and a diagonal block is minus the sum of its row's off-diagonal ones (as per element on the CPU).

#include <cstdint>

namespace vsim::cuda::fem {

/// Doubles per stored 3x3 block (row-major). Measured on the H100: padding blocks to 10 doubles for 16-byte loads
/// took 11.86 ms a step at 1M tets (9: 11.66 ms) and 1.971 ms at 100k (9: 1.987 ms). A single-precision matrix
/// halves the PCG's traffic but left the CPU path's positions by 1e-4..7e-4 after 100 steps, over the 1e-5 parity
/// bound, so the matrix stays double.
constexpr int kBlockStride = 9;

/// DeviceModel::assembledSource of a diagonal block: diagonalKernel forms it from its row.
constexpr std::uint32_t kDiagonalBlock = 0xffffffffu;

/// Device pointers and sizes of one model (all double precision, 3 entries per node where per dof).
///
/// The matrix is symmetric and stored once: row by row, the diagonal block and the blocks (i, j) with i < j (the
/// upper triangle). Row i's product reads its upper blocks in place and its lower blocks (j, i)^T
/// through `lowerSlots`; those were just read by row j < i, so they come from the L2 cache, and the PCG's
/// mat-vec streams about half the bytes of a full block-sparse matrix.
struct DeviceModel
{
    int nodes = 0, elements = 0, storedBlocks = 0, faces = 0;
    const int* tets = nullptr;         // 4 per element
    const double* rest = nullptr;      // X, 3 per node
    double* elementRecords = nullptr;  // 16 per element, element after element (128 bytes, read whole by the element
                                       // and assembly kernels): the rotation as a quaternion (w, x, y, z; the element
                                       // kernel's warm start and result), the rest edges' inverse (row-major; its rows
                                       // are the gradients of N1..N3, 1/m), V lambda, V mu (N m), 0
    const double* mass = nullptr;      // 3 per node (lumped, per component)
    const double* freeMask = nullptr;  // 3 per node: 1 free, 0 constrained
    const int* faces3 = nullptr;       // 3 per pressure face
    // Forces: the element kernel writes node a's force of element e to node entry forceSlots[4 e + a], so that
    // node n's sum reads entries [nodeEntryStart[n], nodeEntryStart[n + 1]) in one run.
    double* elementForces = nullptr;   // 3 per node entry
    const std::uint32_t* forceSlots = nullptr;
    const std::uint32_t* nodeEntryStart = nullptr;
    // Assembly: off-diagonal stored block t sums the elements listed for full-pattern slot assembledSource[t],
    // blockEntries[blockEntryStart[slot] ..) = 16 e + 4 a + b.
    const std::uint32_t* assembledSource = nullptr;
    const std::uint32_t* blockEntryStart = nullptr;
    const std::uint32_t* blockEntries = nullptr;
    // The matrix: row i stores blocks [rowStart[i], rowStart[i + 1]), its diagonal block first, then (i, j > i),
    // kBlockStride doubles each; columns[t] is block t's j. Row i's lower blocks (i, j < i) are the stored (j, i)
    // transposed: lowerSlots / lowerColumns [lowerRowStart[i] ..).
    double* matrix = nullptr;
    const std::uint32_t* rowStart = nullptr;
    const std::uint32_t* columns = nullptr;
    const std::uint32_t* lowerRowStart = nullptr;
    const std::uint32_t* lowerSlots = nullptr;
    const std::uint32_t* lowerColumns = nullptr;
};

/// Scalars of the step and of the PCG, kept on the device.
struct DeviceScalars
{
    double pressure;
    double rz, reference, alpha, beta, residual;
    int done, iterations, inverted;
    unsigned int blocksDone; // the last-block-done counter of the current sweep
};

__global__ void resetKernel(DeviceScalars* s);
__global__ void elementKernel(DeviceModel m, const double* x, DeviceScalars* s);
/// `rotationsAt`: the positions at which the rotations' derivative (CorotationalFem::addRotationStiffness) joins the
/// off-diagonal blocks (the static wall's tangent); null: R K R^T alone (the implicit step's).
__global__ void assembleKernel(DeviceModel m, double stiffnessFactor, const double* rotationsAt);
__global__ void diagonalKernel(DeviceModel m, double massFactor);
__global__ void forceKernel(DeviceModel m, double* force);
__global__ void pressureKernel(DeviceModel m, const double* x, const DeviceScalars* s, double* external);
__global__ void productKernel(DeviceModel m, const double* in, double* out);
__global__ void rightHandSideKernel(DeviceModel m, const double* force, const double* external, const double* v,
                                    const double* av, double h, double alpha, double beta, double massFactor,
                                    double stiffnessFactor, double* rhs, double* dv);
__global__ void cgInitKernel(DeviceModel m, const double* b, const double* x, double* inverseDiagonal, double* r,
                             double* z, double* p, double* q, double* partials, DeviceScalars* s);
__global__ void cgDirectionKernel(DeviceModel m, const double* z, double* p, double* q, double* partials,
                                  DeviceScalars* s, double tolerance, int maxIterations);
__global__ void cgUpdateKernel(DeviceModel m, const double* inverseDiagonal, double* x, double* r, double* z,
                               const double* p, const double* q, double* partials, DeviceScalars* s, double tolerance,
                               int maxIterations);
/// r.z of the multigrid-preconditioned PCG (after the V-cycle): rz, and beta from the previous rz once iterating.
__global__ void cgDotKernel(int count, const double* r, const double* z, double* partials, DeviceScalars* s,
                            double tolerance, int maxIterations);
/// Threads per matrix row in productKernel, cgInitKernel and cgDirectionKernel (launch nodes * this many; at
/// least 3: lanes 0-2 own a component each). Measured on the H100 at 1M tets: 4 lanes 15.2 ms a step, 8 lanes
/// 17.4 ms, 16 lanes 25.1 ms.
constexpr int kRowLanes = 4;
/// Nodes per warp in cgUpdateKernel (one thread per component: launch ceil(nodes / this) * 32 threads).
constexpr int kNodesPerWarp = 10;
__global__ void finishKernel(int count, const double* dv, double h, double* v, double* x);

} // namespace vsim::cuda::fem
