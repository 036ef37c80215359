#pragma once

// The first-order Finite Particle Method (thesis ch. 5.2, eq. 5.17; Liu & Liu 2006): a field's value and
// gradient at particle i from its neighbours, exact for linear fields whatever the particles' arrangement,
// also where the kernel's support is cut by a wall or a free surface (where the plain SPH sums lose their
// normalisation). The Taylor expansion f_j = f_i + (x_j - x_i) . grad f_i is multiplied by W_ij and by grad_i
// W_ij and summed with the volumes V_j = m_j / rho_j into a 4x4 system for (f_i, grad f_i).

#include "vsim/sim/sph/QuarticKernel.h"

#include <Eigen/Dense>

#include <optional>

namespace vsim::sim::sph {

struct CorrectedField
{
    double value = 0.0;
    Eigen::Vector3d gradient = Eigen::Vector3d::Zero(); ///< per m
};

class FpmSystem
{
public:
    explicit FpmSystem(const QuarticKernel& kernel) : m_kernel(kernel) {}

    /// Adds neighbour j (or particle i itself, with rij = 0): rij = x_i - x_j (m), its volume V_j (m^3), its
    /// value f_j.
    void add(const Eigen::Vector3d& rij, double volumeM3, double value);
    /// The corrected value and gradient; nothing when the moment matrix is (near) singular: too few
    /// neighbours, or all of them in a plane (the caller keeps the plain SPH estimate there).
    std::optional<CorrectedField> solve() const;

private:
    const QuarticKernel& m_kernel;
    Eigen::Matrix4d m_moments = Eigen::Matrix4d::Zero();
    Eigen::Vector4d m_sums = Eigen::Vector4d::Zero();
};

/// The plain SPH gradient at i, sum_j V_j (f_j - f_i) grad_i W_ij, for the comparison: add every neighbour j
/// != i.
class PlainGradient
{
public:
    explicit PlainGradient(const QuarticKernel& kernel, double valueAtI) : m_kernel(kernel), m_fi(valueAtI) {}
    void add(const Eigen::Vector3d& rij, double volumeM3, double value)
    {
        m_sum += volumeM3 * (value - m_fi) * m_kernel.gradient(rij);
    }
    Eigen::Vector3d gradient() const { return m_sum; }

private:
    const QuarticKernel& m_kernel;
    double m_fi;
    Eigen::Vector3d m_sum = Eigen::Vector3d::Zero();
};

} // namespace vsim::sim::sph
