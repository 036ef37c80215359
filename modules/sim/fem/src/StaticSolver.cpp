#include "vsim/sim/fem/StaticSolver.h"

#include "vsim/core/Error.h"
#include "vsim/sim/fem/ConjugateGradient.h"


#include <cmath>
#include <cstdio>

namespace vsim::sim::fem {
namespace {

double freeNorm(const Eigen::VectorXd& v, const std::vector<std::uint8_t>& constrained)
{
    double sum = 0.0;
    for (Eigen::Index i = 0; i < v.size(); ++i)
        if (constrained.empty() || !constrained[std::size_t(i)])
            sum += v[i] * v[i];
    return std::sqrt(sum);
}

} // namespace

StaticSolveReport solveStatic(CorotationalFem& model, const Eigen::VectorXd& externalForces,
                              const std::vector<std::uint8_t>& constrained, double tolerance, int maxUpdates,
                              int cgMaxIterations)
{
    StaticSolveReport report;
    BlockSparseMatrix stiffness = model.makeMatrix();
    const Eigen::VectorXd external =
        externalForces.size() == 0 ? Eigen::VectorXd::Zero(model.positions().size()) : externalForces;
    double reference = freeNorm(external, constrained);
    for (; report.updates < maxUpdates; ++report.updates)
    {
        if (const std::size_t inverted = model.updateElements(); inverted > 0)
        {
            const Eigen::Vector3d where = 1e3 * model.firstInvertedCentroid();
            char place[96];
            std::snprintf(place, sizeof place, " (the first near %.1f, %.1f, %.1f mm)", where.x(), where.y(), where.z());
            throw Error(std::to_string(inverted) + " elements inverted during the static solve" + place +
                        ": the load is too large for the mesh, or the constraints do not hold it");
        }
        const Eigen::VectorXd residual = model.elasticForces() + external;
        const double norm = freeNorm(residual, constrained);
        if (reference == 0.0)
            reference = norm; // only prescribed displacements drive it
        report.forceResidual = reference > 0.0 ? norm / reference : 0.0;
        if (report.forceResidual <= tolerance)
        {
            report.converged = true;
            break;
        }
        model.assemble(stiffness, 0.0, 1.0);
        Eigen::VectorXd delta = Eigen::VectorXd::Zero(residual.size());
        const ConjugateGradientResult cg =
            solveConjugateGradient(stiffness, residual, delta, constrained, 0.1 * tolerance, cgMaxIterations);
        report.cgIterations += cg.iterations;
        model.positions() += delta;
    }
    return report;
}

} // namespace vsim::sim::fem
