#pragma once

// The derivative of the element rotations in the co-rotational tangent, on the GPU: the same terms as
// sim::fem::CorotationalFem::addRotationStiffness (the Hessian of the co-rotational energy, McAdams et al. 2011),
// added per element to the off-diagonal blocks by assembleKernel when the static wall asks for it (CudaStaticWall);
// diagonalKernel then forms the diagonal blocks from their rows (an element's term has rows that sum to zero:
// sum_b [g_b]x = 0). Without it the modified Newton iteration took 13-50 updates an equilibrium on the thinned tube
// instead of 8-13 (RESULTS.md).

#include "ElementShape.cuh"

#include <cstdint>

namespace vsim::cuda::fem {

__device__ inline Mat3 skew(const double v[3])
{
    Mat3 s;
    s(0, 0) = 0.0, s(0, 1) = -v[2], s(0, 2) = v[1];
    s(1, 0) = v[2], s(1, 1) = 0.0, s(1, 2) = -v[0];
    s(2, 0) = -v[1], s(2, 1) = v[0], s(2, 2) = 0.0;
    return s;
}

/// Element e's term for node pair (a, b): R C_a Lambda^-1 [g_b]x R^T with C_a = -[(K u)_a]x + sum_m K_am [R^T x_m]x,
/// Lambda = tr(S) I - S, S = R^T F; zero for an inverted element or a singular Lambda (as on the CPU).
__device__ inline Mat3 rotationTerm(const DeviceModel& m, const double* x, std::uint32_t e, int a, int b)
{
    Mat3 term;
    for (int j = 0; j < 9; ++j)
        term.m[j] = 0.0;
    const ElementShape shape = elementShape(m, e);
    const Mat3 r = rotationMatrix(shape.rotation);
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
                h(i, j) += (rotated[n][i] - m.rest[3 * node + i]) * shape.g[n][j];
                s(i, j) += rotated[n][i] * shape.g[n][j];
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
    const Mat3 stress = volumeStress(shape, h);
    double ku[3]; // (K u)_a = V sigma g_a
    for (int i = 0; i < 3; ++i)
        ku[i] = stress(i, 0) * shape.g[a][0] + stress(i, 1) * shape.g[a][1] + stress(i, 2) * shape.g[a][2];
    Mat3 c = skew(ku);
    for (int j = 0; j < 9; ++j)
        c.m[j] = -c.m[j];
    for (int n = 0; n < 4; ++n)
    {
        const Mat3 product = multiply(stiffnessBlock(shape, a, n), skew(rotated[n]));
        for (int j = 0; j < 9; ++j)
            c.m[j] += product.m[j];
    }
    const Mat3 spin = multiplyTransposed(multiply(inverted(lambda, det), skew(shape.g[b])), r); // Lambda^-1 [g_b]x R^T
    return multiply(r, multiply(c, spin));
}

} // namespace vsim::cuda::fem
