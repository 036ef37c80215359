#include "vsim/sim/fem/BackwardEuler.h"

#include "vsim/core/Error.h"
#include "vsim/sim/fem/ConjugateGradient.h"

namespace vsim::sim::fem {

BackwardEuler::BackwardEuler(const CorotationalFem& model, BackwardEulerSettings settings)
    : m_settings(settings), m_system(model.makeMatrix()),
      m_lastDeltaV(Eigen::VectorXd::Zero(Eigen::Index(3 * model.nodeCount()))),
      m_setUpRule(settings.multigridSetUpAgainFactor)
{
    if (!(settings.timeStep > 0.0) || settings.rayleighAlpha < 0.0 || settings.rayleighBeta < 0.0)
        throw Error("the time step must be positive and the Rayleigh coefficients non-negative");
}

StepReport BackwardEuler::step(CorotationalFem& model, const Eigen::VectorXd& externalForces,
                               const std::vector<std::uint8_t>& constrained, const Contacts& contacts)
{
    StepReport report;
    const double h = m_settings.timeStep, alpha = m_settings.rayleighAlpha, beta = m_settings.rayleighBeta;
    report.invertedElements = model.updateElements();
    const double massFactor = 1.0 + h * alpha, stiffnessFactor = h * beta + h * h;
    model.assemble(m_system, massFactor, stiffnessFactor);
    Eigen::VectorXd contactForces = Eigen::VectorXd::Zero(model.positions().size());
    if (!contacts.springs.empty() || !contacts.probes.empty())
        for (const ContactStiffness& contact :
             addContactForces(contacts, model.positions(), model.velocities(), contactForces))
            m_system.diagonal(std::size_t(contact.node)) += stiffnessFactor * contact.block;

    const Eigen::VectorXd& v = model.velocities();
    const Eigen::VectorXd& mass = model.lumpedMass();
    // K v from the assembled system: K v = (A v - (1 + h alpha) M v) / (h beta + h^2).
    Eigen::VectorXd av;
    m_system.multiply(v, av);
    const Eigen::VectorXd kv = (av - massFactor * mass.cwiseProduct(v)) / stiffnessFactor;
    Eigen::VectorXd rhs = h * (model.elasticForces() + contactForces - alpha * mass.cwiseProduct(v)) - h * (beta + h) * kv;
    if (externalForces.size() == rhs.size())
        rhs += h * externalForces;
    else if (externalForces.size() != 0)
        throw Error("the external forces do not match the mesh");

    Eigen::VectorXd deltaV = m_lastDeltaV;
    if (!constrained.empty())
        for (Eigen::Index i = 0; i < deltaV.size(); ++i)
            if (constrained[std::size_t(i)])
                deltaV[i] = 0.0;
    if (m_settings.preconditioner == CgPreconditioner::Multigrid)
    {
        if (!m_multigrid || constrained != m_multigridConstraints)
        {
            m_multigrid = std::make_unique<AggregationMultigrid>(m_system, model.positions(), constrained);
            m_multigridConstraints = constrained;
            m_setUpRule.setUp();
            ++m_multigridSetUps;
        }
        else
            m_multigrid->refreshFinest(m_system);
    }
    const ConjugateGradientResult cg = solveConjugateGradient(m_system, rhs, deltaV, constrained, m_settings.cgTolerance,
                                                              m_settings.cgMaxIterations, m_multigrid.get());
    if (m_multigrid && m_setUpRule.setUpAgainAfter(cg.iterations))
        m_multigrid.reset(); // set up again from the next step's matrix (MultigridSetUpRule.h)
    report.cgIterations = cg.iterations;
    report.cgResidual = cg.relativeResidual;
    report.cgConverged = cg.converged;
    m_lastDeltaV = deltaV;
    model.velocities() += deltaV;
    model.positions() += h * model.velocities();
    return report;
}

} // namespace vsim::sim::fem
