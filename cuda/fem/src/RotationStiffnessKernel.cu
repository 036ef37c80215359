// The derivative of the element rotations in the co-rotational tangent, on the GPU: the same terms as
// sim::fem::CorotationalFem::addRotationStiffness (McAdams et al. 2011's Hessian of the co-rotational energy),
// added to the stored off-diagonal blocks before diagonalKernel forms the diagonal ones from their rows (an element's
// term has rows that sum to zero: sum_b [g_b]x = 0). The static wall's tangent (CudaStaticWall) needs it: without it
// the modified Newton iteration took 13-50 updates an equilibrium on the thinned tube instead of 8-13.

#include "DeviceMath.cuh"
#include "FemKernels.cuh"

namespace vsim::cuda::fem {
namespace {

__device__ inline Mat3 skew(const double v[3])
{
    Mat3 s;
    s(0, 0) = 0.0, s(0, 1) = -v[2], s(0, 2) = v[1];
    s(1, 0) = v[2], s(1, 1) = 0.0, s(1, 2) = -v[0];
    s(2, 0) = -v[1], s(2, 1) = v[0], s(2, 2) = 0.0;
    return s;
}

__device__ inline Mat3 inverse(const Mat3& a, double det)
{
    Mat3 i;
    i(0, 0) = (a(1, 1) * a(2, 2) - a(1, 2) * a(2, 1)) / det;
    i(0, 1) = (a(0, 2) * a(2, 1) - a(0, 1) * a(2, 2)) / det;
    i(0, 2) = (a(0, 1) * a(1, 2) - a(0, 2) * a(1, 1)) / det;
    i(1, 0) = (a(1, 2) * a(2, 0) - a(1, 0) * a(2, 2)) / det;
    i(1, 1) = (a(0, 0) * a(2, 2) - a(0, 2) * a(2, 0)) / det;
    i(1, 2) = (a(0, 2) * a(1, 0) - a(0, 0) * a(1, 2)) / det;
    i(2, 0) = (a(1, 0) * a(2, 1) - a(1, 1) * a(2, 0)) / det;
    i(2, 1) = (a(0, 1) * a(2, 0) - a(0, 0) * a(2, 1)) / det;
    i(2, 2) = (a(0, 0) * a(1, 1) - a(0, 1) * a(1, 0)) / det;
    return i;
}

/// Element e's term for node pair (a, b): R C_a Lambda^-1 [g_b]x R^T with C_a = -[(K u)_a]x + sum_m K_am [R^T x_m]x,
/// Lambda = tr(S) I - S, S = R^T F; zero for an inverted element or a singular Lambda (as on the CPU).
__device__ Mat3 rotationTerm(const DeviceModel& m, const double* x, std::uint32_t e, int a, int b)
{
    Mat3 term;
    for (int j = 0; j < 9; ++j)
        term.m[j] = 0.0;
    const double* record = m.elementRecords + 16 * std::size_t(e);
    const Mat3 r = rotationMatrix(Quat{record[0], record[1], record[2], record[3]});
    double g[4][3];
    for (int n = 1; n < 4; ++n)
        for (int i = 0; i < 3; ++i)
            g[n][i] = record[4 + 3 * (n - 1) + i];
    for (int i = 0; i < 3; ++i)
        g[0][i] = -(g[1][i] + g[2][i] + g[3][i]);
    const double volumeLambda = record[13], volumeMu = record[14];
    double rotated[4][3]; // R^T x per node
    Mat3 h, s; // the displacement gradient of u = R^T x - X, and S = sum_n (R^T x_n) g_n^T
    for (int j = 0; j < 9; ++j)
        h.m[j] = s.m[j] = 0.0;
    for (int n = 0; n < 4; ++n)
    {
        const int node = m.tets[4 * e + n];
        for (int i = 0; i < 3; ++i)
            rotated[n][i] = r(0, i) * x[3 * node] + r(1, i) * x[3 * node + 1] + r(2, i) * x[3 * node + 2];
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
            {
                h(i, j) += (rotated[n][i] - m.rest[3 * node + i]) * g[n][j];
                s(i, j) += rotated[n][i] * g[n][j];
            }
    }
    if (determinant(s) <= 0.0) // det S = det F: inverted
        return term;
    Mat3 lambda;
    const double trace = s(0, 0) + s(1, 1) + s(2, 2);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            lambda(i, j) = (i == j ? trace : 0.0) - s(i, j);
    const double det = determinant(lambda);
    if (fabs(det) < 1e-12)
        return term;
    // (K u)_a = V sigma g_a (the element kernel's product).
    const double pressure = volumeLambda * (h(0, 0) + h(1, 1) + h(2, 2));
    double ku[3];
    for (int i = 0; i < 3; ++i)
    {
        ku[i] = 0.0;
        for (int j = 0; j < 3; ++j)
            ku[i] += (volumeMu * (h(i, j) + h(j, i)) + (i == j ? pressure : 0.0)) * g[a][j];
    }
    Mat3 c = skew(ku);
    for (int j = 0; j < 9; ++j)
        c.m[j] = -c.m[j];
    for (int n = 0; n < 4; ++n)
    {
        // K_an = V (lambda g_a g_n^T + mu g_n g_a^T + mu (g_a . g_n) I), as assembleKernel.
        const double dot = volumeMu * (g[a][0] * g[n][0] + g[a][1] * g[n][1] + g[a][2] * g[n][2]);
        Mat3 k;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                k(i, j) = volumeLambda * g[a][i] * g[n][j] + volumeMu * g[a][j] * g[n][i] + (i == j ? dot : 0.0);
        const Mat3 product = multiply(k, skew(rotated[n]));
        for (int j = 0; j < 9; ++j)
            c.m[j] += product.m[j];
    }
    const Mat3 spin = multiplyTransposed(multiply(inverse(lambda, det), skew(g[b])), r); // Lambda^-1 [g_b]x R^T
    return multiply(r, multiply(c, spin));
}

} // namespace

__global__ void rotationStiffnessKernel(DeviceModel m, const double* x, double stiffnessFactor)
{
    const int stored = blockIdx.x * blockDim.x + threadIdx.x;
    if (stored >= m.storedBlocks)
        return;
    const std::uint32_t slot = m.assembledSource[stored];
    if (slot == kDiagonalBlock)
        return; // diagonalKernel's
    double* block = m.matrix + std::size_t(kBlockStride) * std::size_t(stored);
    for (std::uint32_t i = m.blockEntryStart[slot]; i < m.blockEntryStart[slot + 1]; ++i)
    {
        const std::uint32_t entry = m.blockEntries[i];
        const Mat3 term = rotationTerm(m, x, entry / 16, int(entry % 16 / 4), int(entry % 4));
        for (int j = 0; j < 9; ++j)
            block[j] += stiffnessFactor * term.m[j];
    }
}

} // namespace vsim::cuda::fem
