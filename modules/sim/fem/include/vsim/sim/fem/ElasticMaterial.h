#pragma once

// Isotropic linear elastic material in SI units, the constitutive law of the co-rotational wall model
// (thesis ch. 4.3; Lame parameters from E and nu).

#include <Eigen/Core>

namespace vsim::sim::fem {

struct ElasticMaterial
{
    /// The constitutive model: co-rotational linear elasticity (default) or St. Venant-Kirchhoff.
    enum class Model { CorotationalLinear, StVenantKirchhoff };
    Model model = Model::CorotationalLinear;
    double youngModulusPa = 4.23e6;  ///< Pa (thesis patient 1: 4.23 MPa)
    double poissonRatio = 0.23;      ///< dimensionless, -1 < nu < 0.5
    double densityKgPerM3 = 1100.0;  ///< kg/m^3 (arterial wall, about that of soft tissue)

    /// First Lame parameter lambda = E nu / ((1 + nu)(1 - 2 nu)), Pa.
    double lambda() const;
    /// Shear modulus mu = E / (2 (1 + nu)), Pa.
    double mu() const;
    /// The 6x6 elasticity matrix in Voigt order (xx, yy, zz, xy, yz, zx) with engineering shear strains, Pa.
    Eigen::Matrix<double, 6, 6> elasticityMatrix() const;
    /// Throws vsim::Error for E <= 0, nu outside (-1, 0.5) or density <= 0, naming the value.
    void validate() const;
};

} // namespace vsim::sim::fem
