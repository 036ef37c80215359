#pragma once

// 3x3 matrices (row-major, 9 doubles) and unit quaternions (w, x, y, z) for the element kernels; the same
// formulas as Eigen's on the CPU side so that both backends round alike.

namespace vsim::cuda::fem {

struct Mat3
{
    double m[9];
    __device__ double& operator()(int r, int c) { return m[3 * r + c]; }
    __device__ double operator()(int r, int c) const { return m[3 * r + c]; }
};

__device__ inline Mat3 multiply(const Mat3& a, const Mat3& b)
{
    Mat3 c;
    for (int r = 0; r < 3; ++r)
        for (int k = 0; k < 3; ++k)
            c(r, k) = a(r, 0) * b(0, k) + a(r, 1) * b(1, k) + a(r, 2) * b(2, k);
    return c;
}

__device__ inline Mat3 multiplyTransposed(const Mat3& a, const Mat3& b) // a * b^T
{
    Mat3 c;
    for (int r = 0; r < 3; ++r)
        for (int k = 0; k < 3; ++k)
            c(r, k) = a(r, 0) * b(k, 0) + a(r, 1) * b(k, 1) + a(r, 2) * b(k, 2);
    return c;
}

__device__ inline double determinant(const Mat3& a)
{
    return a(0, 0) * (a(1, 1) * a(2, 2) - a(1, 2) * a(2, 1)) - a(0, 1) * (a(1, 0) * a(2, 2) - a(1, 2) * a(2, 0)) +
           a(0, 2) * (a(1, 0) * a(2, 1) - a(1, 1) * a(2, 0));
}

/// The inverse of `a` whose determinant is `det` (non-zero): the adjugate over det.
__device__ inline Mat3 inverted(const Mat3& a, double det)
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

struct Quat
{
    double w, x, y, z;
};

__device__ inline Mat3 rotationMatrix(const Quat& q) // Eigen's Quaternion::toRotationMatrix
{
    const double tx = 2 * q.x, ty = 2 * q.y, tz = 2 * q.z;
    const double twx = tx * q.w, twy = ty * q.w, twz = tz * q.w;
    const double txx = tx * q.x, txy = ty * q.x, txz = tz * q.x;
    const double tyy = ty * q.y, tyz = tz * q.y, tzz = tz * q.z;
    Mat3 r;
    r(0, 0) = 1 - (tyy + tzz), r(0, 1) = txy - twz, r(0, 2) = txz + twy;
    r(1, 0) = txy + twz, r(1, 1) = 1 - (txx + tzz), r(1, 2) = tyz - twx;
    r(2, 0) = txz - twy, r(2, 1) = tyz + twx, r(2, 2) = 1 - (txx + tyy);
    return r;
}

__device__ inline Quat product(const Quat& a, const Quat& b)
{
    return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
            a.w * b.y + a.y * b.w + a.z * b.x - a.x * b.z, a.w * b.z + a.z * b.w + a.x * b.y - a.y * b.x};
}

__device__ inline Quat normalized(const Quat& q)
{
    const double n = sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
    return {q.w / n, q.x / n, q.y / n, q.z / n};
}

/// Rotation of `a` (RotationExtraction.cpp: Mueller et al. 2016 with the Newton step near the solution).
__device__ inline void extractRotation(const Mat3& a, Quat& q, int maxIterations, double tolerance)
{
    for (int iteration = 0; iteration < maxIterations; ++iteration)
    {
        const Mat3 r = rotationMatrix(q);
        double torque[3] = {0, 0, 0};
        for (int i = 0; i < 3; ++i) // sum_i r_i x a_i over columns
        {
            torque[0] += r(1, i) * a(2, i) - r(2, i) * a(1, i);
            torque[1] += r(2, i) * a(0, i) - r(0, i) * a(2, i);
            torque[2] += r(0, i) * a(1, i) - r(1, i) * a(0, i);
        }
        const Mat3 m = multiplyTransposed(a, r);
        const double trace = m(0, 0) + m(1, 1) + m(2, 2);
        const double h00 = trace - m(0, 0), h11 = trace - m(1, 1), h22 = trace - m(2, 2);
        const double h01 = -0.5 * (m(0, 1) + m(1, 0)), h02 = -0.5 * (m(0, 2) + m(2, 0)), h12 = -0.5 * (m(1, 2) + m(2, 1));
        const double c00 = h11 * h22 - h12 * h12, c01 = h02 * h12 - h01 * h22, c02 = h01 * h12 - h02 * h11;
        const double det = h00 * c00 + h01 * c01 + h02 * c02;
        const double floor = 0.1 * fabs(trace);
        double omega[3];
        if (trace > 0.0 && fmin(h00, fmin(h11, h22)) > floor && h00 * h11 - h01 * h01 > 0.0 && det > 0.0)
        {
            const double c11 = h00 * h22 - h02 * h02, c12 = h01 * h02 - h00 * h12, c22 = h00 * h11 - h01 * h01;
            omega[0] = (c00 * torque[0] + c01 * torque[1] + c02 * torque[2]) / det;
            omega[1] = (c01 * torque[0] + c11 * torque[1] + c12 * torque[2]) / det;
            omega[2] = (c02 * torque[0] + c12 * torque[1] + c22 * torque[2]) / det;
        }
        else
            for (int i = 0; i < 3; ++i)
                omega[i] = torque[i] / (fabs(trace) + 1e-12);
        const double angle = sqrt(omega[0] * omega[0] + omega[1] * omega[1] + omega[2] * omega[2]);
        if (angle < tolerance)
            break;
        Quat turn;
        if (angle < 1e-3)
            turn = {1.0, 0.5 * omega[0], 0.5 * omega[1], 0.5 * omega[2]};
        else
        {
            const double s = sin(0.5 * angle) / angle;
            turn = {cos(0.5 * angle), s * omega[0], s * omega[1], s * omega[2]};
        }
        q = normalized(product(turn, q));
    }
}

} // namespace vsim::cuda::fem
