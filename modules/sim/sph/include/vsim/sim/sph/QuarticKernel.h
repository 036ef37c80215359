#pragma once

// The Liu quartic smoothing kernel in 3D (thesis eq. 5.13 with its printed 8/9 corrected to 9/8,
// SEED-NOTES.md):
//   W(r, h) = 315 / (208 pi h^3) (2/3 - 9/8 q^2 + 19/24 q^3 - 5/32 q^4),  q = r / h in [0, 2], 0 beyond.
// It integrates to 1 over space, vanishes with its first derivative at r = 2h (the support), and is C1 there.
// Lengths in m (SI inside the solver), W in 1/m^3, its gradient in 1/m^4.

#include <Eigen/Core>

#include <algorithm>

namespace vsim::sim::sph {

class QuarticKernel
{
public:
    /// `smoothingLengthM` h > 0 (the support radius is 2h).
    explicit QuarticKernel(double smoothingLengthM);

    double smoothingLength() const { return m_h; }
    double support() const { return 2.0 * m_h; }
    /// W at distance r (m). W = norm (2 - q)^2 (1/6 + q/6 - 5/32 q^2): slightly negative for q in (1.696, 2).
    double value(double r) const;
    /// max(W, 0): the weights of Shepard interpolations (walls' pressures, open boundaries' extrapolation), where the
    /// negative lobe could cancel the sum of weights of a sparse neighbourhood (a deep wall particle's).
    double interpolationWeight(double r) const { return std::max(0.0, value(r)); }
    /// dW/dr at distance r (m); 0 at r = 0 and beyond the support.
    double derivative(double r) const;
    /// grad_i W(x_i - x_j) for rij = x_i - x_j: dW/dr rij / r (the zero vector at r = 0).
    Eigen::Vector3d gradient(const Eigen::Vector3d& rij) const;
    /// sum_k W(|k| spacing) over the simple cubic lattice's sites k (self included), 1/m^3: what a particle sums
    /// on the lattice the particles were seeded on (within 0.1 % of 1 / spacing^3 at h = 2 spacings).
    double latticeSum(double spacingM) const;
    /// The same with r = |rij| already known (the neighbour loops have it), inline for them.
    Eigen::Vector3d gradient(const Eigen::Vector3d& rij, double r) const
    {
        const double q = r / m_h;
        if (r <= 0.0 || q >= 2.0)
            return Eigen::Vector3d::Zero();
        return (m_norm / (m_h * m_h) * 0.625 * (2.0 - q) * (q - 1.8)) * rij; // dW/dr / r, 0 at q = 2 exactly
    }

private:
    double m_h, m_norm; ///< h (m), 315 / (208 pi h^3)
};

} // namespace vsim::sim::sph
