#include "BlockRows.cuh"
#include "DeviceMath.cuh"
#include "ElementShape.cuh"
#include "FemKernels.cuh"
#include "RotationStiffness.cuh"

namespace vsim::cuda::fem {
namespace {

/// Grid-wide sums of `Count` values per thread in a fixed order, so that a step repeats bit for bit: every block
/// stores its sums in partials[Count * block + i]; the last block to finish adds those up (its first warp) and gets
/// true, with the sums in `totals` in that warp's threads. The counter wraps back to 0 for the next sweep.
template <int Count>
__device__ bool gridSum(double (&values)[Count], double* partials, DeviceScalars* s, double (&totals)[Count])
{
    __shared__ double warpSums[Count][32];
    __shared__ bool last;
    const unsigned lane = threadIdx.x % 32, warp = threadIdx.x / 32;
    for (int i = 0; i < Count; ++i)
    {
        for (int offset = 16; offset > 0; offset /= 2)
            values[i] += __shfl_down_sync(0xffffffffu, values[i], offset);
        if (lane == 0)
            warpSums[i][warp] = values[i];
    }
    __syncthreads();
    if (threadIdx.x == 0)
    {
        for (int i = 0; i < Count; ++i)
        {
            double sum = 0.0;
            for (unsigned w = 0; w < blockDim.x / 32; ++w)
                sum += warpSums[i][w];
            partials[Count * blockIdx.x + i] = sum;
        }
        __threadfence(); // the partials are visible before the count says so
        last = atomicInc(&s->blocksDone, gridDim.x - 1) == gridDim.x - 1;
    }
    __syncthreads();
    if (!last || warp != 0)
        return false;
    for (int i = 0; i < Count; ++i)
    {
        double sum = 0.0;
        for (unsigned block = lane; block < gridDim.x; block += 32)
            sum += __ldcg(partials + Count * block + i); // from L2: other multiprocessors wrote them
        for (int offset = 16; offset > 0; offset /= 2)
            sum += __shfl_xor_sync(0xffffffffu, sum, offset);
        totals[i] = sum;
    }
    return true;
}

} // namespace

__global__ void resetKernel(DeviceScalars* s)
{
    s->rz = 0.0;
    s->done = 0;
    s->iterations = 0;
    s->inverted = 0;
    s->blocksDone = 0;
}

__global__ void elementKernel(DeviceModel m, const double* x, DeviceScalars* s)
{
    const int e = blockIdx.x * blockDim.x + threadIdx.x;
    if (e >= m.elements)
        return;
    int node[4];
    for (int a = 0; a < 4; ++a)
        node[a] = m.tets[4 * e + a];
    const ElementShape shape = elementShape(m, std::size_t(e));
    Mat3 edges, restInverse;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
        {
            edges(r, c) = x[3 * node[c + 1] + r] - x[3 * node[0] + r];
            restInverse(r, c) = shape.g[r + 1][c];
        }
    const Mat3 deformation = multiply(edges, restInverse);
    Quat q = shape.rotation;
    if (determinant(deformation) <= 0.0)
        atomicAdd(&s->inverted, 1);
    else
    {
        extractRotation(deformation, q, 20, 1e-10);
        double* record = m.elementRecords + 16 * std::size_t(e);
        record[0] = q.w, record[1] = q.x, record[2] = q.y, record[3] = q.z;
    }
    const Mat3 r = rotationMatrix(q);
    // f = -R K u with u = R^T x - X: K u = V sigma g_a for the linear strain of the displacement gradient
    // H = sum_b u_b g_b^T (sigma = lambda tr(H) I + mu (H + H^T)), the same product as K_e = V B^T D B.
    Mat3 h;
    for (int i = 0; i < 9; ++i)
        h.m[i] = 0.0;
    for (int b = 0; b < 4; ++b)
    {
        double u[3];
        for (int i = 0; i < 3; ++i)
            u[i] = r(0, i) * x[3 * node[b]] + r(1, i) * x[3 * node[b] + 1] + r(2, i) * x[3 * node[b] + 2] -
                   m.rest[3 * node[b] + i];
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                h(i, j) += u[i] * shape.g[b][j];
    }
    const Mat3 stress = volumeStress(shape, h); // V sigma
    for (int a = 0; a < 4; ++a)
    {
        double f[3];
        for (int i = 0; i < 3; ++i)
            f[i] = stress(i, 0) * shape.g[a][0] + stress(i, 1) * shape.g[a][1] + stress(i, 2) * shape.g[a][2];
        double* target = m.elementForces + 3 * std::size_t(m.forceSlots[4 * e + a]);
        for (int i = 0; i < 3; ++i)
            target[i] = -(r(i, 0) * f[0] + r(i, 1) * f[1] + r(i, 2) * f[2]);
    }
}

/// Off-diagonal stored block t = sum over its elements of R K_ab R^T, with K_ab = V (lambda g_a g_b^T + mu g_b g_a^T +
/// mu (g_a . g_b) I) (V B^T D B written out per node pair; K_ba = K_ab^T), + the rotations' derivative at
/// `rotationsAt` where given (RotationStiffness.cuh), times the stiffness factor.
__global__ void assembleKernel(DeviceModel m, double stiffnessFactor, const double* rotationsAt)
{
    const int stored = blockIdx.x * blockDim.x + threadIdx.x;
    if (stored >= m.storedBlocks)
        return;
    const std::uint32_t slot = m.assembledSource[stored];
    if (slot == kDiagonalBlock)
        return; // diagonalKernel's
    Mat3 sum;
    for (int j = 0; j < 9; ++j)
        sum.m[j] = 0.0;
    for (std::uint32_t i = m.blockEntryStart[slot]; i < m.blockEntryStart[slot + 1]; ++i)
    {
        const std::uint32_t entry = m.blockEntries[i], element = entry / 16;
        const int a = int(entry % 16 / 4), b = int(entry % 4);
        const ElementShape shape = elementShape(m, element);
        const Mat3 k = stiffnessBlock(shape, a, b);
        const Mat3 r = rotationMatrix(shape.rotation);
        const Mat3 rotated = multiply(r, multiplyTransposed(k, r));
        for (int j = 0; j < 9; ++j)
            sum.m[j] += rotated.m[j];
        if (rotationsAt)
        {
            const Mat3 derivative = rotationTerm(m, rotationsAt, element, a, b);
            for (int j = 0; j < 9; ++j)
                sum.m[j] += derivative.m[j];
        }
    }
    for (int j = 0; j < 9; ++j)
        sum.m[j] *= stiffnessFactor;
    storeBlock(m.matrix, std::size_t(stored), sum.m);
}

/// Diagonal block i = c_M M_i - sum over j != i of the stiffness blocks A_ij just assembled: every element's
/// K_aa is -sum_b K_ab (rigid translations carry no force), the identity the CPU's element pass uses per element.
/// Summing the assembled row instead spares the assembly the diagonal blocks' many elements (about 24 each, four
/// times an edge's), which kept most threads of a warp idle.
__global__ void diagonalKernel(DeviceModel m, double massFactor)
{
    const int thread = blockIdx.x * blockDim.x + threadIdx.x, node = thread / kLanes, lane = thread % kLanes;
    double sum[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    if (node < m.nodes)
    {
        const std::uint32_t lowerBegin = m.lowerRowStart[node], lowerCount = m.lowerRowStart[node + 1] - lowerBegin;
        const std::uint32_t upperBegin = m.rowStart[node] + 1, upperCount = m.rowStart[node + 1] - upperBegin;
        for (std::uint32_t k = std::uint32_t(lane); k < lowerCount + upperCount; k += kLanes)
        {
            const bool transposed = k < lowerCount; // A_ij = A_ji^T for j < i
            double block[9];
            loadBlock(m.matrix, transposed ? m.lowerSlots[lowerBegin + k] : upperBegin + k - lowerCount, block);
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 3; ++c)
                    sum[3 * r + c] += transposed ? block[3 * c + r] : block[3 * r + c];
        }
    }
    for (int offset = kLanes / 2; offset > 0; offset /= 2)
        for (int j = 0; j < 9; ++j)
            sum[j] += __shfl_xor_sync(0xffffffffu, sum[j], offset, kLanes);
    if (node >= m.nodes || lane != 0)
        return;
    const double mass = massFactor * m.mass[3 * node];
    for (int j = 0; j < 9; ++j)
        sum[j] = -sum[j] + (j % 4 == 0 ? mass : 0.0);
    storeBlock(m.matrix, m.rowStart[node], sum);
}

__global__ void forceKernel(DeviceModel m, double* force)
{
    const int node = blockIdx.x * blockDim.x + threadIdx.x;
    if (node >= m.nodes)
        return;
    double sum[3] = {0, 0, 0};
    for (std::uint32_t i = m.nodeEntryStart[node]; i < m.nodeEntryStart[node + 1]; ++i)
        for (int k = 0; k < 3; ++k)
            sum[k] += __ldg(m.elementForces + 3 * std::size_t(i) + k);
    force[3 * node] = sum[0], force[3 * node + 1] = sum[1], force[3 * node + 2] = sum[2];
}

__global__ void pressureKernel(DeviceModel m, const double* x, const DeviceScalars* s, double* external)
{
    const int face = blockIdx.x * blockDim.x + threadIdx.x;
    if (face >= m.faces)
        return;
    const int n0 = m.faces3[3 * face], n1 = m.faces3[3 * face + 1], n2 = m.faces3[3 * face + 2];
    double e1[3], e2[3];
    for (int i = 0; i < 3; ++i)
        e1[i] = x[3 * n1 + i] - x[3 * n0 + i], e2[i] = x[3 * n2 + i] - x[3 * n0 + i];
    const double areaNormal[3] = {0.5 * (e1[1] * e2[2] - e1[2] * e2[1]), 0.5 * (e1[2] * e2[0] - e1[0] * e2[2]),
                                  0.5 * (e1[0] * e2[1] - e1[1] * e2[0])};
    for (int n : {n0, n1, n2})
        for (int i = 0; i < 3; ++i)
            atomicAdd(&external[3 * n + i], -s->pressure * areaNormal[i] / 3.0);
}

__global__ void productKernel(DeviceModel m, const double* in, double* out)
{
    const int thread = blockIdx.x * blockDim.x + threadIdx.x, node = thread / kLanes, lane = thread % kLanes;
    double y[3];
    rowProduct(m, in, node, lane, y);
    if (node < m.nodes && lane == 0)
        out[3 * node] = y[0], out[3 * node + 1] = y[1], out[3 * node + 2] = y[2];
}

/// rhs = h (f_el + f_ext - alpha M v) - h (beta + h) (A v - c_M M v) / c_K; the warm start dv keeps its value
/// except on constrained components (0).
__global__ void rightHandSideKernel(DeviceModel m, const double* force, const double* external, const double* v,
                                    const double* av, double h, double alpha, double beta, double massFactor,
                                    double stiffnessFactor, double* rhs, double* dv)
{
    const int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= 3 * m.nodes)
        return;
    const double mv = m.mass[i] * v[i];
    const double kv = (av[i] - massFactor * mv) / stiffnessFactor;
    rhs[i] = h * (force[i] - alpha * mv) - h * (beta + h) * kv + h * external[i];
    dv[i] *= m.freeMask[i];
}

__global__ void cgInitKernel(DeviceModel m, const double* b, const double* x, double* inverseDiagonal, double* r,
                             double* z, double* p, double* q, double* partials, DeviceScalars* s)
{
    const int groups = int(gridDim.x * blockDim.x) / kLanes, lane = int(threadIdx.x) % kLanes;
    double sums[3] = {0.0, 0.0, 0.0}; // b.b, r.r, r.z over the free components
    for (int pass = 0, passes = rowPasses(m.nodes, groups); pass < passes; ++pass)
    {
        const int node = int(blockIdx.x * blockDim.x + threadIdx.x) / kLanes + pass * groups;
        double ax[3];
        rowProduct(m, x, node, lane, ax);
        if (node >= m.nodes || lane != 0)
            continue;
        double stored[9];
        loadBlock(m.matrix, m.rowStart[node], stored);
        Mat3 block;
        for (int j = 0; j < 9; ++j)
            block.m[j] = stored[j];
        const double det = determinant(block);
        Mat3 inverse;
        if (fabs(det) > 0.0)
            inverse = inverted(block, det);
        else
            for (int j = 0; j < 9; ++j)
                inverse.m[j] = j % 4 == 0 ? 1.0 : 0.0;
        const double* mask = m.freeMask + 3 * node;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                inverseDiagonal[9 * std::size_t(node) + 3 * i + j] = mask[i] * inverse(i, j) * mask[j];
        double residual[3];
        for (int i = 0; i < 3; ++i)
        {
            const double bFree = mask[i] * b[3 * node + i];
            residual[i] = bFree - mask[i] * ax[i];
            sums[0] += bFree * bFree;
            sums[1] += residual[i] * residual[i];
        }
        const double* inv = inverseDiagonal + 9 * std::size_t(node);
        for (int i = 0; i < 3; ++i)
        {
            const double zi = inv[3 * i] * residual[0] + inv[3 * i + 1] * residual[1] + inv[3 * i + 2] * residual[2];
            r[3 * node + i] = residual[i];
            z[3 * node + i] = zi;
            p[3 * node + i] = 0.0;
            q[3 * node + i] = 0.0;
            sums[2] += residual[i] * zi;
        }
    }
    double totals[3];
    if (gridSum(sums, partials, s, totals) && threadIdx.x == 0)
    {
        s->reference = totals[0] > 0.0 ? sqrt(totals[0]) : sqrt(totals[1]);
        s->residual = s->reference > 0.0 ? sqrt(totals[1]) / s->reference : 0.0;
        s->rz = totals[2];
        s->done = s->reference == 0.0 ? 1 : 0;
        s->beta = 0.0;
    }
}

/// Sweep 1 of an iteration (solveConjugateGradient's first loop): p = z + beta p, q = S A z + beta q, p.q; the last
/// block computes alpha.
__global__ void cgDirectionKernel(DeviceModel m, const double* z, double* p, double* q, double* partials,
                                  DeviceScalars* s, double tolerance, int maxIterations)
{
    if (!cgActive(s, tolerance, maxIterations))
        return;
    const int groups = int(gridDim.x * blockDim.x) / kLanes, lane = int(threadIdx.x) % kLanes;
    const double beta = s->beta;
    double pq[1] = {0.0};
    for (int pass = 0, passes = rowPasses(m.nodes, groups); pass < passes; ++pass)
    {
        const int node = int(blockIdx.x * blockDim.x + threadIdx.x) / kLanes + pass * groups;
        const bool owner = node < m.nodes && lane < 3; // lane i updates component i
        const std::size_t i = 3 * std::size_t(node) + std::size_t(lane);
        double zi = 0.0, pi = 0.0, qi = 0.0, free = 0.0;
        if (owner) // loaded before the row product so that both wait on memory together
            zi = z[i], pi = p[i], qi = q[i], free = m.freeMask[i];
        double w[3];
        rowProduct(m, z, node, lane, w);
        if (!owner)
            continue;
        pi = zi + beta * pi;
        qi = free * (lane == 0 ? w[0] : lane == 1 ? w[1] : w[2]) + beta * qi;
        p[i] = pi;
        q[i] = qi;
        pq[0] += pi * qi;
    }
    double total[1];
    if (gridSum(pq, partials, s, total) && threadIdx.x == 0)
    {
        if (!(total[0] > 0.0))
            s->done = 1; // not positive definite along p (or NaN)
        else
            s->alpha = s->rz / total[0];
    }
}

/// Sweep 2: x += alpha p, r -= alpha q, z = P r, with r.z and r.r; the last block computes beta and the residual.
/// One thread per component, ten nodes per warp (lanes 30 and 31 idle), so that every load is coalesced; a node's
/// three residual components reach each other by shuffles. With `inverseDiagonal` null (the multigrid
/// preconditioner) z is left to the V-cycle and beta to cgDotKernel.
__global__ void cgUpdateKernel(DeviceModel m, const double* inverseDiagonal, double* x, double* r, double* z,
                               const double* p, const double* q, double* partials, DeviceScalars* s, double tolerance,
                               int maxIterations)
{
    if (!cgActive(s, tolerance, maxIterations))
        return;
    const double alpha = s->alpha;
    const int lane = int(threadIdx.x % 32), component = lane % 3, first = lane - component;
    const int warps = int(gridDim.x * blockDim.x / 32), chunks = (m.nodes + kNodesPerWarp - 1) / kNodesPerWarp;
    double sums[2] = {0.0, 0.0}; // r.z, r.r
    for (int chunk = int((blockIdx.x * blockDim.x + threadIdx.x) / 32); chunk < chunks; chunk += warps)
    {
        const int node = kNodesPerWarp * chunk + lane / 3;
        const bool active = lane < 3 * kNodesPerWarp && node < m.nodes;
        const std::size_t i = 3 * std::size_t(node) + std::size_t(component);
        double ri = 0.0;
        if (active)
        {
            x[i] += alpha * p[i];
            ri = r[i] - alpha * q[i];
            r[i] = ri;
        }
        const double r0 = __shfl_sync(0xffffffffu, ri, first), r1 = __shfl_sync(0xffffffffu, ri, first + 1),
                     r2 = __shfl_sync(0xffffffffu, ri, first + 2);
        if (!active)
            continue;
        if (!inverseDiagonal)
        {
            sums[1] += ri * ri;
            continue;
        }
        const double* inv = inverseDiagonal + 9 * std::size_t(node) + 3 * std::size_t(component);
        const double zi = inv[0] * r0 + inv[1] * r1 + inv[2] * r2;
        z[i] = zi;
        sums[0] += ri * zi;
        sums[1] += ri * ri;
    }
    double totals[2];
    if (gridSum(sums, partials, s, totals) && threadIdx.x == 0)
    {
        if (inverseDiagonal)
        {
            s->beta = totals[0] / s->rz;
            s->rz = totals[0];
        }
        s->residual = sqrt(totals[1]) / s->reference;
        s->iterations += 1;
    }
}

__global__ void cgDotKernel(int count, const double* r, const double* z, double* partials, DeviceScalars* s,
                            double tolerance, int maxIterations)
{
    if (!cgActive(s, tolerance, maxIterations))
        return;
    double sums[1] = {0.0};
    for (int i = int(blockIdx.x * blockDim.x + threadIdx.x); i < count; i += int(gridDim.x * blockDim.x))
        sums[0] += r[i] * z[i];
    double totals[1];
    if (gridSum(sums, partials, s, totals) && threadIdx.x == 0)
    {
        if (s->iterations > 0) // after cgInitKernel beta stays 0
            s->beta = totals[0] / s->rz;
        s->rz = totals[0];
    }
}

__global__ void finishKernel(int count, const double* dv, double h, double* v, double* x)
{
    const int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= count)
        return;
    v[i] += dv[i];
    x[i] += h * v[i];
}

} // namespace vsim::cuda::fem
