#include "vsim/sim/fem/Hyperelastic.h"

#include "vsim/core/Error.h"

#include <Eigen/LU>

#include <array>
#include <cmath>

namespace vsim::sim::fem {
namespace {

constexpr double kNewtonPerCm2 = 1e4; // Pa

/// Voigt index pairs (xx, yy, zz, xy, yz, zx).
constexpr std::array<std::array<int, 2>, 6> kVoigt = {{{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {2, 0}}};

/// (A (x) B)_IJ = A_ij B_kl.
Matrix6d outer(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b)
{
    return toVoigt(a) * toVoigt(b).transpose();
}

/// (A (.) A)_ijkl = (A_ik A_jl + A_il A_jk) / 2, the derivative of -A^-1 by A for symmetric A.
Matrix6d symmetricProduct(const Eigen::Matrix3d& a)
{
    Matrix6d out;
    for (int p = 0; p < 6; ++p)
        for (int q = 0; q < 6; ++q)
        {
            const int i = kVoigt[std::size_t(p)][0], j = kVoigt[std::size_t(p)][1];
            const int k = kVoigt[std::size_t(q)][0], l = kVoigt[std::size_t(q)][1];
            out(p, q) = 0.5 * (a(i, k) * a(j, l) + a(i, l) * a(j, k));
        }
    return out;
}

double bulkFromPoisson(double shearModulus, double poissonRatio)
{
    return 2.0 * shearModulus * (1.0 + poissonRatio) / (3.0 * (1.0 - 2.0 * poissonRatio));
}

} // namespace

Vector6d toVoigt(const Eigen::Matrix3d& m)
{
    Vector6d v;
    v << m(0, 0), m(1, 1), m(2, 2), m(0, 1), m(1, 2), m(2, 0);
    return v;
}

Eigen::Matrix3d fromVoigt(const Vector6d& v)
{
    Eigen::Matrix3d m;
    m << v[0], v[3], v[5], v[3], v[1], v[4], v[5], v[4], v[2];
    return m;
}

HyperelasticMaterial HyperelasticMaterial::stVenantKirchhoff(double e, double nu)
{
    HyperelasticMaterial m;
    m.law = Law::StVenantKirchhoff;
    m.lambda = e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
    m.mu = e / (2.0 * (1.0 + nu));
    return m;
}

HyperelasticMaterial HyperelasticMaterial::raghavanVorp2000(double poissonRatio)
{
    HyperelasticMaterial m;
    m.law = Law::IsochoricPolynomial;
    m.c10 = 17.4 * kNewtonPerCm2;
    m.c20 = 188.1 * kNewtonPerCm2;
    m.bulkModulus = bulkFromPoisson(m.initialShearModulus(), poissonRatio);
    return m;
}

HyperelasticMaterial HyperelasticMaterial::wang2001Thrombus(double poissonRatio)
{
    HyperelasticMaterial m;
    m.law = Law::IsochoricPolynomial;
    m.c01 = 2.62 * kNewtonPerCm2;
    m.c02 = 2.65 * kNewtonPerCm2;
    m.bulkModulus = bulkFromPoisson(m.initialShearModulus(), poissonRatio);
    return m;
}

double HyperelasticMaterial::initialShearModulus() const
{
    return law == Law::StVenantKirchhoff ? mu : 2.0 * (c10 + c01);
}

void HyperelasticMaterial::validate() const
{
    if (law == Law::StVenantKirchhoff && (!(mu > 0.0) || !(lambda >= 0.0)))
        throw Error(Pattern{"St. Venant-Kirchhoff material needs mu > 0 and lambda >= 0 (got mu %1 Pa, lambda %2 Pa)",
                            {std::to_string(mu), std::to_string(lambda)}});
    if (law == Law::IsochoricPolynomial && (!(initialShearModulus() > 0.0) || !(bulkModulus > 0.0) || c20 < 0.0 || c02 < 0.0))
        throw Error("hyperelastic polynomial material needs c10 + c01 > 0, c20, c02 >= 0 and a bulk modulus > 0");
}

Vector6d HyperelasticMaterial::stress(const Eigen::Matrix3d& c, Matrix6d* tangent) const
{
    const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
    if (law == Law::StVenantKirchhoff)
    {
        const Eigen::Matrix3d e = 0.5 * (c - identity);
        if (tangent)
            *tangent = lambda * outer(identity, identity) + 2.0 * mu * symmetricProduct(identity);
        return toVoigt(lambda * e.trace() * identity + 2.0 * mu * e);
    }
    // Derivatives by C (Holzapfel 2000, ch. 6.4, written out for W(I1b, I2b) + U(J)):
    //  dI1b/dC = J^-2/3 (I - I1/3 C^-1) = A1,  dI2b/dC = J^-4/3 (B - 2/3 I2 C^-1) = A2 with B = I1 I - C,
    //  dJ/dC = J/2 C^-1;  S = 2 W1 A1 + 2 W2 A2 + J U' C^-1;  C_mat = 2 dS/dC (= dS/dE).
    const double i1 = c.trace(), i2 = 0.5 * (i1 * i1 - (c * c).trace()), j = std::sqrt(c.determinant());
    const Eigen::Matrix3d ci = c.inverse(), b = i1 * identity - c;
    const double j23 = std::pow(j, -2.0 / 3.0), j43 = j23 * j23;
    const double i1b = j23 * i1 - 3.0, i2b = j43 * i2 - 3.0;
    const double w1 = c10 + 2.0 * c20 * i1b, w11 = 2.0 * c20, w2 = c01 + 2.0 * c02 * i2b, w22 = 2.0 * c02;
    const double u1 = bulkModulus * (j - 1.0), u2 = bulkModulus;
    const Eigen::Matrix3d a1 = j23 * (identity - i1 / 3.0 * ci), a2 = j43 * (b - 2.0 / 3.0 * i2 * ci);
    if (tangent)
    {
        const Matrix6d cici = outer(ci, ci), ciDotCi = symmetricProduct(ci);
        // dA1/dC = J^-2/3 [-(I (x) C^-1 + C^-1 (x) I)/3 + I1/9 C^-1 (x) C^-1 + I1/3 C^-1 (.) C^-1]
        const Matrix6d da1 = j23 * (-(outer(identity, ci) + outer(ci, identity)) / 3.0 + i1 / 9.0 * cici + i1 / 3.0 * ciDotCi);
        // dA2/dC = J^-4/3 [I (x) I - II - 2/3 (B (x) C^-1 + C^-1 (x) B) + 4/9 I2 C^-1 (x) C^-1 + 2/3 I2 C^-1 (.) C^-1]
        const Matrix6d da2 = j43 * (outer(identity, identity) - symmetricProduct(identity) -
                                    2.0 / 3.0 * (outer(b, ci) + outer(ci, b)) + 4.0 / 9.0 * i2 * cici + 2.0 / 3.0 * i2 * ciDotCi);
        *tangent = 4.0 * (w11 * outer(a1, a1) + w22 * outer(a2, a2)) + 4.0 * (w1 * da1 + w2 * da2) +
                   j * (u1 + j * u2) * cici - 2.0 * j * u1 * ciDotCi;
    }
    return toVoigt(2.0 * w1 * a1 + 2.0 * w2 * a2 + j * u1 * ci);
}

double HyperelasticMaterial::energyDensity(const Eigen::Matrix3d& c) const
{
    if (law == Law::StVenantKirchhoff)
    {
        const Eigen::Matrix3d e = 0.5 * (c - Eigen::Matrix3d::Identity());
        return 0.5 * lambda * e.trace() * e.trace() + mu * (e * e).trace();
    }
    const double i1 = c.trace(), i2 = 0.5 * (i1 * i1 - (c * c).trace()), j = std::sqrt(c.determinant());
    const double i1b = std::pow(j, -2.0 / 3.0) * i1 - 3.0, i2b = std::pow(j, -4.0 / 3.0) * i2 - 3.0;
    return c10 * i1b + c20 * i1b * i1b + c01 * i2b + c02 * i2b * i2b + 0.5 * bulkModulus * (j - 1.0) * (j - 1.0);
}

} // namespace vsim::sim::fem
