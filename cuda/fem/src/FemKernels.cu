#include "DeviceMath.cuh"
#include "FemKernels.cuh"

namespace vsim::cuda::fem {
namespace {

constexpr int kLanes = kRowLanes; // rows hold about 15 blocks

/// Where off-diagonal block (a, b) of an element is stored among its 10 (CorotationalFem.h's layout).
__device__ inline int upperIndex(int a, int b)
{
    const int low = a < b ? a : b, high = a < b ? b : a;
    return low == 0 ? 3 + high : low == 1 ? 5 + high : 9; // (0,1..3) -> 4..6, (1,2..3) -> 7..8, (2,3) -> 9
}

/// Sums `value` over the block into thread 0's return value (blockDim.x a power of two, at most 1024).
__device__ double blockSum(double value, double* shared)
{
    shared[threadIdx.x] = value;
    __syncthreads();
    for (unsigned stride = blockDim.x / 2; stride > 0; stride /= 2)
    {
        if (threadIdx.x < stride)
            shared[threadIdx.x] += shared[threadIdx.x + stride];
        __syncthreads();
    }
    const double sum = shared[0];
    __syncthreads();
    return sum;
}

/// True in thread 0 of the last block to get here (the counter wraps back to 0 for the next sweep).
__device__ bool lastBlock(DeviceScalars* s)
{
    __shared__ bool last;
    __threadfence();
    if (threadIdx.x == 0)
        last = atomicInc(&s->blocksDone, gridDim.x - 1) == gridDim.x - 1;
    __syncthreads();
    return last && threadIdx.x == 0;
}

/// Row `node` of the matrix times `v`, computed by kLanes neighbouring threads (each takes every kLanes-th block
/// of the row; the matrix is stored component-major, so neighbouring lanes read neighbouring memory) and summed
/// with shuffles: every lane of the group returns the sum. Lanes of a node past the end contribute zeros.
__device__ void rowProduct(const DeviceModel& m, const double* v, int node, int lane, double out[3])
{
    out[0] = out[1] = out[2] = 0.0;
    if (node < m.nodes)
        for (std::uint32_t s = m.rowStart[node] + std::uint32_t(lane); s < m.rowStart[node + 1]; s += kLanes)
        {
            const double* x = v + 3 * std::size_t(__ldg(m.columns + s));
            const std::size_t stride = std::size_t(m.blocks);
            double b[9];
            for (int j = 0; j < 9; ++j)
                b[j] = double(__ldg(m.matrix + j * stride + s)); // read-only during the sweep
            const double x0 = x[0], x1 = x[1], x2 = x[2];
            out[0] += b[0] * x0 + b[1] * x1 + b[2] * x2;
            out[1] += b[3] * x0 + b[4] * x1 + b[5] * x2;
            out[2] += b[6] * x0 + b[7] * x1 + b[8] * x2;
        }
    for (int offset = kLanes / 2; offset > 0; offset /= 2)
        for (int i = 0; i < 3; ++i)
            out[i] += __shfl_xor_sync(0xffffffffu, out[i], offset, kLanes);
}

} // namespace

__global__ void resetKernel(DeviceScalars* s)
{
    s->bb = s->rr = s->rz = s->pq = s->rzNext = 0.0;
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
    Mat3 edges, restInverse;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
        {
            edges(r, c) = x[3 * node[c + 1] + r] - x[3 * node[0] + r];
            restInverse(r, c) = m.restEdgesInverse[9 * std::size_t(e) + 3 * r + c];
        }
    const Mat3 deformation = multiply(edges, restInverse);
    Quat q{m.quaternions[4 * e], m.quaternions[4 * e + 1], m.quaternions[4 * e + 2], m.quaternions[4 * e + 3]};
    if (determinant(deformation) <= 0.0)
        atomicAdd(&s->inverted, 1);
    else
    {
        extractRotation(deformation, q, 20, 1e-10);
        m.quaternions[4 * e] = q.w, m.quaternions[4 * e + 1] = q.x, m.quaternions[4 * e + 2] = q.y,
        m.quaternions[4 * e + 3] = q.z;
    }
    const Mat3 r = rotationMatrix(q);
    double u[12];
    for (int a = 0; a < 4; ++a)
        for (int i = 0; i < 3; ++i)
            u[3 * a + i] = r(0, i) * x[3 * node[a]] + r(1, i) * x[3 * node[a] + 1] + r(2, i) * x[3 * node[a] + 2] -
                           m.rest[3 * node[a] + i];
    // K is stored entry-major (entry c of every element together) so that a warp's loads coalesce.
    const std::size_t elements = std::size_t(m.elements);
    auto k = [&](int entry) { return m.stiffness[std::size_t(entry) * elements + std::size_t(e)]; };
    auto force = [&](int entry) -> double& { return m.elementForces[std::size_t(entry) * elements + std::size_t(e)]; };
    for (int a = 0; a < 4; ++a)
    {
        double f[3];
        for (int i = 0; i < 3; ++i)
        {
            double sum = 0.0;
            for (int c = 0; c < 12; ++c)
                sum += k(12 * (3 * a + i) + c) * u[c];
            f[i] = sum;
        }
        for (int i = 0; i < 3; ++i)
            force(3 * a + i) = -(r(i, 0) * f[0] + r(i, 1) * f[1] + r(i, 2) * f[2]);
    }
    // Entry-major like K: entry j of element e at j * elements + e (coalesced writes).
    auto blockEntry = [&](int block, int j) -> MatrixReal& {
        return m.elementBlocks[std::size_t(9 * block + j) * elements + std::size_t(e)];
    };
    Mat3 diagonal[4];
    for (int a = 0; a < 4; ++a)
        for (int i = 0; i < 9; ++i)
            diagonal[a].m[i] = 0.0;
    for (int a = 0; a < 4; ++a)
        for (int b = a + 1; b < 4; ++b)
        {
            Mat3 kab;
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j)
                    kab(i, j) = k(12 * (3 * a + i) + 3 * b + j);
            const Mat3 rotated = multiply(r, multiplyTransposed(kab, r)); // R (K_ab R^T)
            const int stored = upperIndex(a, b);
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j)
                {
                    blockEntry(stored, 3 * i + j) = MatrixReal(rotated(i, j));
                    diagonal[a](i, j) -= rotated(i, j);
                    diagonal[b](i, j) -= rotated(j, i);
                }
        }
    for (int a = 0; a < 4; ++a)
        for (int i = 0; i < 9; ++i)
            blockEntry(a, i) = MatrixReal(diagonal[a].m[i]);
}

__global__ void assembleKernel(DeviceModel m, double massFactor, double stiffnessFactor)
{
    const int slot = blockIdx.x * blockDim.x + threadIdx.x;
    if (slot >= m.blocks)
        return;
    double sum[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    for (std::uint32_t i = m.blockEntryStart[slot]; i < m.blockEntryStart[slot + 1]; ++i)
    {
        const std::uint32_t entry = m.blockEntries[i], element = entry / 16, local = entry % 16;
        const int a = int(local / 4), b = int(local % 4);
        const int stored = a == b ? a : upperIndex(a, b);
        const std::size_t elements = std::size_t(m.elements);
        auto block = [&](int j) { return double(__ldg(m.elementBlocks + std::size_t(9 * stored + j) * elements + element)); };
        if (a > b)
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 3; ++c)
                    sum[3 * r + c] += block(3 * c + r);
        else
            for (int j = 0; j < 9; ++j)
                sum[j] += block(j);
    }
    for (int j = 0; j < 9; ++j)
        m.matrix[std::size_t(j) * std::size_t(m.blocks) + std::size_t(slot)] = MatrixReal(stiffnessFactor * sum[j]);
}

__global__ void addMassKernel(DeviceModel m, double massFactor)
{
    const int node = blockIdx.x * blockDim.x + threadIdx.x;
    if (node >= m.nodes)
        return;
    const std::size_t slot = m.diagonalSlot[node], stride = std::size_t(m.blocks);
    const double add = massFactor * m.mass[3 * node];
    for (int j : {0, 4, 8})
        m.matrix[std::size_t(j) * stride + slot] = MatrixReal(double(m.matrix[std::size_t(j) * stride + slot]) + add);
}

__global__ void forceKernel(DeviceModel m, double* force)
{
    const int node = blockIdx.x * blockDim.x + threadIdx.x;
    if (node >= m.nodes)
        return;
    double sum[3] = {0, 0, 0};
    for (std::uint32_t i = m.nodeEntryStart[node]; i < m.nodeEntryStart[node + 1]; ++i)
    {
        const std::uint32_t entry = m.nodeEntries[i];
        const std::size_t elements = std::size_t(m.elements), element = entry / 4, first = 3 * (entry % 4);
        for (int k = 0; k < 3; ++k)
            sum[k] += __ldg(m.elementForces + (first + std::size_t(k)) * elements + element);
    }
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
                             double* z, double* p, double* q, DeviceScalars* s)
{
    __shared__ double shared[256];
    const int thread = blockIdx.x * blockDim.x + threadIdx.x, node = thread / kLanes, lane = thread % kLanes;
    double ax[3];
    rowProduct(m, x, node, lane, ax);
    double bb = 0.0, rr = 0.0, rz = 0.0;
    if (node < m.nodes && lane == 0)
    {
        const std::size_t slot = m.diagonalSlot[node], stride = std::size_t(m.blocks);
        Mat3 block;
        for (int j = 0; j < 9; ++j)
            block.m[j] = double(m.matrix[j * stride + slot]);
        const double det = determinant(block);
        Mat3 inverse;
        if (fabs(det) > 0.0)
        {
            inverse(0, 0) = (block(1, 1) * block(2, 2) - block(1, 2) * block(2, 1)) / det;
            inverse(0, 1) = (block(0, 2) * block(2, 1) - block(0, 1) * block(2, 2)) / det;
            inverse(0, 2) = (block(0, 1) * block(1, 2) - block(0, 2) * block(1, 1)) / det;
            inverse(1, 0) = (block(1, 2) * block(2, 0) - block(1, 0) * block(2, 2)) / det;
            inverse(1, 1) = (block(0, 0) * block(2, 2) - block(0, 2) * block(2, 0)) / det;
            inverse(1, 2) = (block(0, 2) * block(1, 0) - block(0, 0) * block(1, 2)) / det;
            inverse(2, 0) = (block(1, 0) * block(2, 1) - block(1, 1) * block(2, 0)) / det;
            inverse(2, 1) = (block(0, 1) * block(2, 0) - block(0, 0) * block(2, 1)) / det;
            inverse(2, 2) = (block(0, 0) * block(1, 1) - block(0, 1) * block(1, 0)) / det;
        }
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
            bb += bFree * bFree;
            rr += residual[i] * residual[i];
        }
        const double* inv = inverseDiagonal + 9 * std::size_t(node);
        for (int i = 0; i < 3; ++i)
        {
            const double zi = inv[3 * i] * residual[0] + inv[3 * i + 1] * residual[1] + inv[3 * i + 2] * residual[2];
            r[3 * node + i] = residual[i];
            z[3 * node + i] = zi;
            p[3 * node + i] = 0.0;
            q[3 * node + i] = 0.0;
            rz += residual[i] * zi;
        }
    }
    bb = blockSum(bb, shared);
    rr = blockSum(rr, shared);
    rz = blockSum(rz, shared);
    if (threadIdx.x == 0)
    {
        atomicAdd(&s->bb, bb);
        atomicAdd(&s->rr, rr);
        atomicAdd(&s->rz, rz);
    }
    if (lastBlock(s))
    {
        const double sbb = atomicAdd(&s->bb, 0.0), srr = atomicAdd(&s->rr, 0.0);
        s->reference = sbb > 0.0 ? sqrt(sbb) : sqrt(srr);
        s->residual = s->reference > 0.0 ? sqrt(srr) / s->reference : 0.0;
        s->done = s->reference == 0.0 ? 1 : 0;
        s->beta = 0.0;
        s->pq = 0.0;
    }
}

/// Sweep 1 of an iteration (solveConjugateGradient's first loop): p = z + beta p, q = S A z + beta q, p.q; the last
/// block computes alpha.
__global__ void cgDirectionKernel(DeviceModel m, const double* z, double* p, double* q, DeviceScalars* s,
                                  double tolerance, int maxIterations)
{
    __shared__ double shared[256];
    if (s->done || s->residual <= tolerance || s->iterations >= maxIterations)
        return; // the whole grid agrees: these only change between kernels
    const int thread = blockIdx.x * blockDim.x + threadIdx.x, node = thread / kLanes, lane = thread % kLanes;
    double w[3];
    rowProduct(m, z, node, lane, w);
    double pq = 0.0;
    if (node < m.nodes && lane == 0)
    {
        const double beta = s->beta;
        for (int i = 0; i < 3; ++i)
        {
            const double pi = z[3 * node + i] + beta * p[3 * node + i];
            const double qi = m.freeMask[3 * node + i] * w[i] + beta * q[3 * node + i];
            p[3 * node + i] = pi;
            q[3 * node + i] = qi;
            pq += pi * qi;
        }
    }
    pq = blockSum(pq, shared);
    if (threadIdx.x == 0)
        atomicAdd(&s->pq, pq);
    if (lastBlock(s))
    {
        const double total = atomicAdd(&s->pq, 0.0);
        if (!(total > 0.0))
            s->done = 1; // not positive definite along p (or NaN)
        else
            s->alpha = s->rz / total;
        s->rzNext = 0.0;
        s->rr = 0.0;
    }
}

/// Sweep 2: x += alpha p, r -= alpha q, z = P r, with r.z and r.r; the last block computes beta and the residual.
__global__ void cgUpdateKernel(DeviceModel m, const double* inverseDiagonal, double* x, double* r, double* z,
                               const double* p, const double* q, DeviceScalars* s, double tolerance, int maxIterations)
{
    __shared__ double shared[256];
    if (s->done || s->residual <= tolerance || s->iterations >= maxIterations)
        return;
    const int node = blockIdx.x * blockDim.x + threadIdx.x;
    double rzNext = 0.0, rr = 0.0;
    if (node < m.nodes)
    {
        const double alpha = s->alpha;
        double rNode[3];
        for (int i = 0; i < 3; ++i)
        {
            x[3 * node + i] += alpha * p[3 * node + i];
            rNode[i] = r[3 * node + i] - alpha * q[3 * node + i];
            r[3 * node + i] = rNode[i];
        }
        const double* inv = inverseDiagonal + 9 * std::size_t(node);
        for (int i = 0; i < 3; ++i)
        {
            const double zi = inv[3 * i] * rNode[0] + inv[3 * i + 1] * rNode[1] + inv[3 * i + 2] * rNode[2];
            z[3 * node + i] = zi;
            rzNext += rNode[i] * zi;
            rr += rNode[i] * rNode[i];
        }
    }
    rzNext = blockSum(rzNext, shared);
    rr = blockSum(rr, shared);
    if (threadIdx.x == 0)
    {
        atomicAdd(&s->rzNext, rzNext);
        atomicAdd(&s->rr, rr);
    }
    if (lastBlock(s))
    {
        const double next = atomicAdd(&s->rzNext, 0.0);
        s->beta = next / s->rz;
        s->rz = next;
        s->residual = sqrt(atomicAdd(&s->rr, 0.0)) / s->reference;
        s->iterations += 1;
        s->pq = 0.0;
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
