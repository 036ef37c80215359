#include "vsim/sim/fem/StVenantKirchhoff.h"

#include "vsim/sim/fem/TetElement.h"

#include <Eigen/LU>

namespace vsim::sim::fem {
namespace {

Eigen::Matrix3d secondPiolaKirchhoff(const Eigen::Matrix3d& e, double lambda, double mu)
{
    return lambda * e.trace() * Eigen::Matrix3d::Identity() + 2.0 * mu * e;
}

Eigen::Matrix3d greenStrain(const Eigen::Matrix3d& f)
{
    return 0.5 * (f.transpose() * f - Eigen::Matrix3d::Identity());
}

} // namespace

void stVenantKirchhoffElement(const Eigen::Matrix3d& f, const Eigen::Matrix<double, 4, 3>& g, double volume,
                              double lambda, double mu, Eigen::Matrix<double, 12, 1>& forces,
                              std::array<Eigen::Matrix3d, 10>& blocks)
{
    const Eigen::Matrix3d s = secondPiolaKirchhoff(greenStrain(f), lambda, mu);
    const Eigen::Matrix3d p = f * s; // first Piola-Kirchhoff
    for (int a = 0; a < 4; ++a)
        forces.segment<3>(3 * a) = -volume * p * g.row(a).transpose();
    // K_ab column j = V d(P g_a) / d(x_b)_j with dF = e_j g_b^T:
    //   dE = (dF^T F + F^T dF) / 2, dS = lambda tr(dE) I + 2 mu dE, dP = dF S + F dS.
    for (int a = 0; a < 4; ++a)
        blocks[std::size_t(a)].setZero();
    for (int a = 0; a < 4; ++a)
        for (int b = a + 1; b < 4; ++b)
        {
            Eigen::Matrix3d block;
            for (int j = 0; j < 3; ++j)
            {
                const Eigen::Matrix3d dF = Eigen::Vector3d::Unit(j) * g.row(b);
                const Eigen::Matrix3d dE = 0.5 * (dF.transpose() * f + f.transpose() * dF);
                const Eigen::Matrix3d dP = dF * s + f * secondPiolaKirchhoff(dE, lambda, mu);
                block.col(j) = volume * dP * g.row(a).transpose();
            }
            blocks[std::size_t(kUpperBlockIndex[a][b])] = block;
            blocks[std::size_t(a)] -= block; // rows of the tangent sum to zero (translation invariance)
            blocks[std::size_t(b)] -= block.transpose();
        }
}

double stVenantKirchhoffEnergy(const Eigen::Matrix3d& f, double volume, double lambda, double mu)
{
    const Eigen::Matrix3d e = greenStrain(f);
    return volume * (0.5 * lambda * e.trace() * e.trace() + mu * (e * e).trace());
}

Eigen::Matrix3d stVenantKirchhoffCauchy(const Eigen::Matrix3d& f, double lambda, double mu)
{
    return f * secondPiolaKirchhoff(greenStrain(f), lambda, mu) * f.transpose() / f.determinant();
}

} // namespace vsim::sim::fem
