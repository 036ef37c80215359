#pragma once

// What the wall kernels compute per element from its record (DeviceModel::elementRecords): the shape-function
// gradients, the element stiffness block K_ab and V sigma of a displacement gradient, shared by the element pass,
// the assembly (FemKernels.cu) and the rotations' derivative (RotationStiffness.cuh).

#include "DeviceMath.cuh"
#include "FemKernels.cuh"

#include <cstddef>

namespace vsim::cuda::fem {

/// What the kernels read of element `e`'s record (DeviceModel::elementRecords): its rotation, the shape-function
/// gradients (1/m: rows of the rest edges' inverse, g_0 = -(g_1 + g_2 + g_3), TetElement.cpp), V lambda, V mu.
struct ElementShape
{
    Quat rotation;
    double g[4][3];
    double volumeLambda, volumeMu;
};

__device__ inline ElementShape elementShape(const DeviceModel& m, std::size_t e)
{
    double s[16]; // read as 16-byte pairs: the record is 128-byte aligned
    const double2* pairs = reinterpret_cast<const double2*>(m.elementRecords + 16 * e);
    for (int k = 0; k < 8; ++k)
    {
        const double2 pair = pairs[k];
        s[2 * k] = pair.x, s[2 * k + 1] = pair.y;
    }
    ElementShape shape;
    shape.rotation = Quat{s[0], s[1], s[2], s[3]};
    for (int b = 1; b < 4; ++b)
        for (int i = 0; i < 3; ++i)
            shape.g[b][i] = s[4 + 3 * (b - 1) + i];
    for (int i = 0; i < 3; ++i)
        shape.g[0][i] = -(shape.g[1][i] + shape.g[2][i] + shape.g[3][i]);
    shape.volumeLambda = s[13];
    shape.volumeMu = s[14];
    return shape;
}


/// K_ab = V (lambda g_a g_b^T + mu g_b g_a^T + mu (g_a . g_b) I): V B^T D B written out per node pair (K_ba = K_ab^T).
__device__ inline Mat3 stiffnessBlock(const ElementShape& shape, int a, int b)
{
    const double* ga = shape.g[a];
    const double* gb = shape.g[b];
    const double dot = shape.volumeMu * (ga[0] * gb[0] + ga[1] * gb[1] + ga[2] * gb[2]);
    Mat3 k;
    for (int row = 0; row < 3; ++row)
        for (int c = 0; c < 3; ++c)
            k(row, c) = shape.volumeLambda * ga[row] * gb[c] + shape.volumeMu * ga[c] * gb[row] + (row == c ? dot : 0.0);
    return k;
}

/// V sigma for the linear strain of displacement gradient h: V (lambda tr(h) I + mu (h + h^T)); (K u)_a = V sigma g_a.
__device__ inline Mat3 volumeStress(const ElementShape& shape, const Mat3& h)
{
    const double pressure = shape.volumeLambda * (h(0, 0) + h(1, 1) + h(2, 2));
    Mat3 stress;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            stress(i, j) = shape.volumeMu * (h(i, j) + h(j, i)) + (i == j ? pressure : 0.0);
    return stress;
}

} // namespace vsim::cuda::fem
