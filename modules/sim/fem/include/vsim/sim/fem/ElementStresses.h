#pragma once

// Stresses per element (Pa): the Cauchy stress tensor in the patient frame, its von Mises value and largest
// principal value; shared by the co-rotational and the quadratic hyperelastic models.

#include <Eigen/Core>

#include <vector>

namespace vsim::sim::fem {

struct ElementStresses
{
    std::vector<double> vonMises;
    std::vector<double> maxPrincipal;
    std::vector<Eigen::Matrix3d> tensors; ///< in the patient frame
};

/// Von Mises stress sqrt(3/2 s:s) of a symmetric stress tensor (s its deviator).
double vonMisesOf(const Eigen::Matrix3d& stress);
/// The von Mises and largest principal values of the tensors (in parallel).
ElementStresses elementStressesFrom(std::vector<Eigen::Matrix3d> tensors);

} // namespace vsim::sim::fem
