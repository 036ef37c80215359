#pragma once

// The first-order Finite Particle Method (thesis ch. 5.2, eq. 5.17; Liu & Liu 2006): a field's value and
// gradient at particle i from its neighbours, exact for linear fields whatever the particles' arrangement,
// also where the kernel's support is cut by a wall or a free surface (where the plain SPH sums lose their
// normalisation). The Taylor expansion f_j = f_i + (x_j - x_i) . grad f_i is multiplied by W_ij and by grad_i
// W_ij and summed with the volumes V_j = m_j / rho_j into a 4x4 system for (f_i, grad f_i); the same moment
// matrix serves every field (FpmFields: several at once, as the solver's density rate takes the velocity's three
// components, SphRates.h).

#include "vsim/sim/sph/QuarticKernel.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <optional>

namespace vsim::sim::sph {

struct CorrectedField
{
    double value = 0.0;
    Eigen::Vector3d gradient = Eigen::Vector3d::Zero(); ///< per m
};

/// The FPM system of `Fields` fields at one particle.
template <int Fields>
class FpmFields
{
public:
    using Values = Eigen::Matrix<double, Fields, 1>;
    /// Row 0 the fields' values at i, rows 1-3 their gradients (d f_k / d x_l at (1 + l, k)).
    using Solution = Eigen::Matrix<double, 4, Fields>;

    /// Adds neighbour j (or particle i itself, with rij = 0): rij = x_i - x_j (m), |rij| = r, W_ij = w and grad_i
    /// W_ij = gradW (the caller has them), its volume V_j (m^3), the fields' values at j.
    void add(const Eigen::Vector3d& rij, double w, const Eigen::Vector3d& gradW, double volumeM3, const Values& values)
    {
        Eigen::Vector4d test;
        test << w, gradW;
        Eigen::Vector4d taylor; // the offset x_j - x_i
        taylor << 1.0, -rij;
        m_moments.noalias() += volumeM3 * test * taylor.transpose();
        m_sums.noalias() += volumeM3 * test * values.transpose();
    }
    /// The corrected values and gradients; nothing when the moment matrix is (near) singular: too few
    /// neighbours, or all of them in a plane (the caller keeps the plain SPH estimate there).
    std::optional<Solution> solve() const
    {
        const Eigen::FullPivLU<Eigen::Matrix4d> lu(m_moments);
        // Scale-free singularity test: the smallest pivot against the largest.
        const Eigen::Matrix4d& u = lu.matrixLU();
        double largest = 0.0, smallest = INFINITY;
        for (int k = 0; k < 4; ++k)
            largest = std::max(largest, std::abs(u(k, k))), smallest = std::min(smallest, std::abs(u(k, k)));
        if (!(largest > 0.0) || smallest < 1e-10 * largest)
            return std::nullopt;
        return Solution(lu.solve(m_sums));
    }

private:
    Eigen::Matrix4d m_moments = Eigen::Matrix4d::Zero();
    Eigen::Matrix<double, 4, Fields> m_sums = Eigen::Matrix<double, 4, Fields>::Zero();
};

/// One field's FPM system with the kernel at hand.
class FpmSystem
{
public:
    explicit FpmSystem(const QuarticKernel& kernel) : m_kernel(kernel) {}

    /// Adds neighbour j (or particle i itself, with rij = 0): rij = x_i - x_j (m), its volume V_j (m^3), its
    /// value f_j.
    void add(const Eigen::Vector3d& rij, double volumeM3, double value);
    /// The corrected value and gradient; nothing where FpmFields::solve gives nothing.
    std::optional<CorrectedField> solve() const;

private:
    const QuarticKernel& m_kernel;
    FpmFields<1> m_fields;
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
