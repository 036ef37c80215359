#pragma once

// Hyperelastic laws of the converged wall analysis (total Lagrangian: the second Piola-Kirchhoff stress S and the
// material tangent dS/dE from the right Cauchy-Green tensor C = F^T F), SI units:
//  St. Venant-Kirchhoff   S = lambda tr(E) I + 2 mu E (CalculiX's *ELASTIC under NLGEOM; with F = I it is linear
//                         elasticity, whose tangent is the 6x6 elasticity matrix)
//  isochoric polynomial   W = c10 (I1b - 3) + c20 (I1b - 3)^2 + c01 (I2b - 3) + c02 (I2b - 3)^2 + kappa/2 (J - 1)^2
//                         with I1b = J^-2/3 I1, I2b = J^-4/3 I2 (CalculiX's *HYPERELASTIC, POLYNOMIAL, N=2 with
//                         C11 = 0 and D1 = 2 / kappa). The AAA literature's laws are of this form:
//   - the AAA wall of Raghavan & Vorp 2000 (J Biomech 33:475, "Toward a biomechanical tool to evaluate rupture
//     potential of abdominal aortic aneurysm: identification of a finite strain constitutive model and evaluation
//     of its applicability"): W = alpha (I_B - 3) + beta (I_B - 3)^2, population means alpha = 17.4 N/cm^2,
//     beta = 188.1 N/cm^2, incompressible; the model the Vande Geest 2006 strength was used with;
//   - the intraluminal thrombus of Wang et al. 2001 (J Biomech Eng 123:536, "Mechanical properties and
//     microstructure of intraluminal thrombus from abdominal aortic aneurysm"): W = c1 (II_B - 3) + c2 (II_B - 3)^2
//     in the second invariant, luminal layer c1 = 2.62 N/cm^2, c2 = 2.65 N/cm^2 (the values of Wang et al. 2002,
//     J Vasc Surg 36:598, for the whole thrombus), incompressible.
//  Incompressibility is approached by the bulk modulus kappa from the small-strain shear modulus mu0 = 2 (c10 + c01)
//  and a Poisson's ratio (0.49 by default): kappa = 2 mu0 (1 + nu) / (3 (1 - 2 nu)).

#include <Eigen/Core>

namespace vsim::sim::fem {

using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Vector6d = Eigen::Matrix<double, 6, 1>;

struct HyperelasticMaterial
{
    enum class Law { StVenantKirchhoff, IsochoricPolynomial };
    Law law = Law::StVenantKirchhoff;
    double lambda = 0.0, mu = 0.0;                 ///< St. Venant-Kirchhoff's Lame parameters, Pa
    double c10 = 0.0, c20 = 0.0, c01 = 0.0, c02 = 0.0; ///< the polynomial's coefficients, Pa
    double bulkModulus = 0.0;                      ///< kappa, Pa

    static HyperelasticMaterial stVenantKirchhoff(double youngModulusPa, double poissonRatio);
    /// Raghavan & Vorp 2000 population means (alpha 174 kPa, beta 1881 kPa).
    static HyperelasticMaterial raghavanVorp2000(double poissonRatio = 0.49);
    /// Wang et al. 2001 / 2002 thrombus (c1 26.2 kPa, c2 26.5 kPa in the second invariant).
    static HyperelasticMaterial wang2001Thrombus(double poissonRatio = 0.49);

    /// Shear modulus at zero strain (Pa): mu, or 2 (c10 + c01).
    double initialShearModulus() const;
    /// Second Piola-Kirchhoff stress (Voigt xx, yy, zz, xy, yz, zx; Pa) at right Cauchy-Green tensor `c`, and,
    /// when `tangent` is given, the material tangent dS/dE (Voigt, engineering shear strains; Pa).
    Vector6d stress(const Eigen::Matrix3d& c, Matrix6d* tangent = nullptr) const;
    /// Strain energy density (J/m^3).
    double energyDensity(const Eigen::Matrix3d& c) const;
    /// Throws vsim::Error for a law whose parameters are not positive where they must be.
    void validate() const;
};

/// Voigt (xx, yy, zz, xy, yz, zx) of a symmetric tensor and back.
Vector6d toVoigt(const Eigen::Matrix3d& m);
Eigen::Matrix3d fromVoigt(const Vector6d& v);

} // namespace vsim::sim::fem
